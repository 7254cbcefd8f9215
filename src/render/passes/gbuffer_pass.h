// The G-buffer (shaders/gbuffer.comp) and the BVH heat map (shaders/heatmap.comp): both trace the
// pixel-centre primary ray through the scene, so both are scene pipelines.
#pragma once

#include <memory>

#include "gpu/pipeline.h"
#include "render/gpu_scene.h"
#include "render/kernel_features.h"

namespace penumbra {

class GBufferPass {
public:
    // previousInstances: the scene's Instance entries as the previous frame placed them, for the
    // motion of moving objects; null: the current ones (nothing moves).
    GBufferPass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
                const gpu::Buffer& viewerUniforms, const gpu::Buffer& gbuffer, KernelSpec spec,
                const gpu::Buffer* previousInstances = nullptr);
    // subpixel < 0: the pixel centre; 0..15: that cell of a 4x4 grid in the pixel (row-major).
    void record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height, int subpixel = -1) const;

private:
    std::unique_ptr<gpu::ComputePipeline> pipeline_;
};

class HeatmapPass {
public:
    // heat: vec4 per pixel (nodes visited, triangles tested); counters: HeatCounters (maxima),
    // which the caller zeroes before each frame.
    HeatmapPass(const gpu::Context& ctx, const GpuScene& scene, const gpu::Buffer& frameUniforms,
                const gpu::Buffer& viewerUniforms, const gpu::Buffer& heat, const gpu::Buffer& counters);
    void record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height) const;

private:
    std::unique_ptr<gpu::ComputePipeline> pipeline_;
};

}  // namespace penumbra
