// The bindings every scene-tracing kernel shares, and a helper that makes such a pipeline
// with its scene buffers already bound.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "gpu/pipeline.h"
#include "render/gpu_scene.h"
#include "render/kernel_features.h"

namespace penumbra {

// extraStorageBindings: pass-specific storage buffers (accumulation, scratch, ...). spec: what the
// kernel is specialised for (render/kernel_features.h), every capability and no promise by default;
// camera: its camera variant (PN_CAMERA_*). The walk is the scene's (GpuScene::walk).
std::unique_ptr<gpu::ComputePipeline> makeScenePipeline(const gpu::Context& ctx, const std::string& shader,
                                                        const GpuScene& scene, const gpu::Buffer& frameUniforms,
                                                        const std::vector<std::uint32_t>& extraStorageBindings,
                                                        KernelSpec spec = {},
                                                        std::uint32_t camera = PN_CAMERA_FROM_QUEUE);

}  // namespace penumbra
