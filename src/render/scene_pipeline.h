// The bindings every scene-tracing kernel shares, and a helper that makes such a pipeline
// with its scene buffers already bound.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "gpu/pipeline.h"
#include "render/gpu_scene.h"

namespace penumbra {

// extraStorageBindings: pass-specific storage buffers (accumulation, scratch, ...). features:
// what the kernel is specialised for (PN_FEATURE_*, render/kernel_features.h); all by default.
std::unique_ptr<gpu::ComputePipeline> makeScenePipeline(const gpu::Context& ctx, const std::string& shader,
                                                        const GpuScene& scene, const gpu::Buffer& frameUniforms,
                                                        const std::vector<std::uint32_t>& extraStorageBindings,
                                                        std::uint32_t features = PN_FEATURE_ALL);

}  // namespace penumbra
