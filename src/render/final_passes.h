// The viewer's G-buffer and denoiser applied to a final render (penumbra render --denoise, --aov):
// the same passes (gbuffer.comp, temporal.comp's demodulation, atrous.comp), not a copy.
//
// The denoiser needs per-pixel illumination (radiance over albedo) and its variance. A final
// render has exactly what temporal.comp keeps for a still camera after N samples: a history
// texel with the mean, N and the luminance moments. So the render's statistics are handed to
// temporal.comp as that history (still camera, valid history, the same G-buffer as "previous"),
// with a "current frame" equal to the mean; temporal.comp then demodulates and writes the
// variance of the mean from the moments, and the a-trous passes filter as in the viewer.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/commands.h"
#include "image/image.h"
#include "render/accumulator.h"
#include "render/renderer.h"
#include "shared/types.h"

namespace penumbra {

// What the primary rays saw (gbuffer.comp): noise-free guides. The albedo is averaged over the
// pixel (16 rays on a 4x4 grid, like the image's jittered samples); normal and depth are the
// pixel centre's (an average of normals or depths across an edge is no surface at all).
struct FrameGuides {
    std::vector<Vec3> albedo;  // textured base colour; 0 where the rays missed
    std::vector<Vec3> normal;  // unit shading normal facing the camera; 0 where the ray missed
    std::vector<float> depth;  // distance along the view axis; 0 where the ray missed
};

struct FinalDenoiseSettings {
    std::uint32_t iterations = 5;  // a-trous passes, steps 1, 2, 4, 8, 16 pixels
    // Wider than the viewer's 4: a final frame's variance is the exact variance of the mean, not
    // a few frames' estimate. Measured on the Cornell box at 64x64, 8 spp (docs/RENDERING.md):
    // 4 gains 4.2 dB, 10 gains 4.7 dB, 20 gains 3.4 dB.
    float sigmaLuminance = 10.0f;
    float sigmaNormal = 128.0f;  // the viewer's defaults (render/view_settings.h)
    float sigmaDepth = 1.0f;
};

class GBufferPass;
class TemporalPass;
class DenoisePass;

class FinalFramePasses {
public:
    // Uses the renderer's scene, camera and image size; holds its own buffers and passes, made on
    // first use and kept for every frame the renderer renders (a video's frames: compiling the
    // passes' pipelines anew each frame would cost more than the denoising).
    FinalFramePasses(const gpu::Context& ctx, const Renderer& renderer);
    ~FinalFramePasses();

    // The renderer now shows another view or moved instances (Renderer::restart,
    // setInstanceTransforms): the next guides() or denoise() traces the G-buffer again.
    void restart();
    FrameGuides guides();
    // The denoised image of `sums` (their mean, filtered).
    ImageRgb denoise(const PixelAccumulator& sums, const FinalDenoiseSettings& settings = {});

private:
    void runGBuffer();
    void makeDenoiser();  // the buffers and passes denoise() needs, once
    gpu::Buffer pixelBuffer(VkDeviceSize bytesPerPixel) const;

    const gpu::Context& ctx_;
    const Renderer& renderer_;
    std::uint32_t width_, height_;
    gpu::Commands commands_;
    gpu::Buffer viewerUniforms_, gbuffer_;  // after runGBuffer: centre texels, albedo for demodulation
    // The render as temporal.comp's history and current frame, what it writes (the history, the
    // filter's input, the guide, the roulette estimates nobody reads) and the a-trous scratch.
    gpu::Buffer historyIn_, current_, historyOut_, filterA_, filterB_, guide_, estimates_;
    std::unique_ptr<GBufferPass> gbufferPass_;
    KernelSpec gbufferSpec_;  // what gbufferPass_ was specialised for
    std::unique_ptr<TemporalPass> temporal_;
    std::unique_ptr<DenoisePass> atrous_;
    std::vector<shader::GBufferTexel> centre_;
    std::vector<Vec3> albedo_;  // averaged over the pixel, 0 for misses (the AOV)
    bool gbufferDone_ = false;
};

}  // namespace penumbra
