#include "render/final_passes.h"

#include <cstring>

#include "render/frame_uniforms.h"
#include "render/kernel_features.h"
#include "render/passes/denoise_pass.h"
#include "render/passes/gbuffer_pass.h"
#include "render/passes/temporal_pass.h"
#include "shared/types.h"

namespace penumbra {
namespace {

constexpr VkBufferUsageFlags kPixelUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

// The viewer's uniforms for a still camera whose history is valid: "previous" camera = this one.
shader::ViewerUniforms stillCameraUniforms(const shader::FrameUniforms& f, const FinalDenoiseSettings& s) {
    shader::ViewerUniforms v{};
    setPreviousCamera(v, f);
    v.historyValid = 1;
    v.cameraMoved = 0;
    v.samplesPerFrame = 1;  // the "current frame" is the mean itself, one sample's worth
    v.depthTolerance = 0.1f;
    v.normalTolerance = 0.9f;
    v.maxHistory = 1e30f;
    v.sigmaLuminance = s.sigmaLuminance;
    v.sigmaNormal = s.sigmaNormal;
    v.sigmaDepth = s.sigmaDepth;
    v.denoise = 1;
    return v;
}

}  // namespace

FinalFramePasses::FinalFramePasses(const gpu::Context& ctx, const Renderer& renderer)
    : ctx_(ctx), renderer_(renderer), width_(renderer.settings().width), height_(renderer.settings().height),
      commands_(ctx) {
    viewerUniforms_ = gpu::Buffer(ctx, sizeof(shader::ViewerUniforms), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                  gpu::MemoryKind::HostVisible);
    gbuffer_ = pixelBuffer(sizeof(shader::GBufferTexel));
    restart();
}

FinalFramePasses::~FinalFramePasses() = default;

void FinalFramePasses::restart() {
    const auto* frame = static_cast<const shader::FrameUniforms*>(renderer_.frameUniforms().mapped());
    const shader::ViewerUniforms v = stillCameraUniforms(*frame, FinalDenoiseSettings{});
    std::memcpy(viewerUniforms_.mapped(), &v, sizeof v);
    gbufferDone_ = false;
}

gpu::Buffer FinalFramePasses::pixelBuffer(VkDeviceSize bytesPerPixel) const {
    return gpu::Buffer(ctx_, VkDeviceSize(width_) * height_ * bytesPerPixel, kPixelUsage, gpu::MemoryKind::DeviceLocal);
}

void FinalFramePasses::makeDenoiser() {
    if (atrous_) return;
    historyIn_ = pixelBuffer(sizeof(shader::HistoryTexel));
    current_ = pixelBuffer(sizeof(Vec4));
    historyOut_ = pixelBuffer(sizeof(shader::HistoryTexel));
    filterA_ = pixelBuffer(sizeof(Vec4));
    filterB_ = pixelBuffer(sizeof(Vec4));
    guide_ = pixelBuffer(PN_DENOISE_GUIDE_BYTES);
    estimates_ = pixelBuffer(sizeof(Vec4));  // written, never read: there is no next pass
    temporal_ = std::make_unique<TemporalPass>(
        ctx_, TemporalBuffers{&renderer_.frameUniforms(), &viewerUniforms_, &current_, &gbuffer_, &gbuffer_, &historyIn_,
                              &historyOut_, &filterA_, &guide_, &estimates_});
    atrous_ = std::make_unique<DenoisePass>(ctx_, renderer_.frameUniforms(), viewerUniforms_, gbuffer_, guide_,
                                            historyOut_, filterA_, filterB_);
}

void FinalFramePasses::runGBuffer() {
    if (gbufferDone_) return;
    const std::size_t n = std::size_t(width_) * height_;
    // Kept across frames, but made again when the renderer's kernels were (Renderer::setMaterial
    // may bring code the old ones left out).
    const KernelSpec spec = renderer_.kernelSpec().withOption(PN_OPTION_FRAME_STATS, false);
    if (!gbufferPass_ || gbufferSpec_ != spec) {
        gbufferPass_ = std::make_unique<GBufferPass>(ctx_, renderer_.gpuScene(), renderer_.frameUniforms(),
                                                     viewerUniforms_, gbuffer_, spec);
        gbufferSpec_ = spec;
    }
    auto trace = [&](int subpixel) {
        commands_.run([&](VkCommandBuffer cmd) {
            gpu::computeBarrier(cmd);  // the last frame's denoiser has done reading the G-buffer
            gbufferPass_->record(cmd, width_, height_, subpixel);
        });
        return gpu::downloadBuffer<shader::GBufferTexel>(ctx_, commands_, gbuffer_, n);
    };
    // The centre ray's surface, normal and depth guide the filter; the albedo is averaged over
    // a 4x4 grid of the pixel, as the radiance is over its jittered samples. (Demodulating an
    // antialiased edge or a texture finer than a pixel by the centre's albedo alone would divide
    // one texel's radiance by its neighbour's colour.) A ray that misses counts as albedo 0 in
    // the AOV and as 1 (nothing divided out) for the denoiser, as demodulationAlbedo says.
    std::vector<shader::GBufferTexel> texels = trace(-1);
    std::vector<Vec3> demodulation(n, Vec3{0.0f});
    albedo_.assign(n, Vec3{0.0f});
    constexpr int kCells = 16;
    for (int cell = 0; cell < kCells; ++cell) {
        const std::vector<shader::GBufferTexel> sub = trace(cell);
        for (std::size_t i = 0; i < n; ++i) {
            const bool hit = sub[i].surfaceId != 0;
            albedo_[i] = albedo_[i] + (hit ? sub[i].albedo : Vec3{0.0f}) / float(kCells);
            demodulation[i] = demodulation[i] + (hit ? max(sub[i].albedo, Vec3{1e-3f}) : Vec3{1.0f}) / float(kCells);
        }
    }
    centre_.resize(n);
    // A final render filters its emitters and sprites too (docs/RENDERING.md: leaving emitters
    // out lost 1.5 dB on the Cornell box at 8 spp); the viewer leaves them alone.
    for (std::size_t i = 0; i < n; ++i) {
        centre_[i] = texels[i];
        texels[i].albedo = demodulation[i];
        texels[i].flags &= ~PN_GBUFFER_UNFILTERED;
    }
    gpu::uploadToBuffer(ctx_, commands_, gbuffer_, std::span<const shader::GBufferTexel>(texels));
    gbufferDone_ = true;
}

FrameGuides FinalFramePasses::guides() {
    runGBuffer();
    const std::size_t n = std::size_t(width_) * height_;
    FrameGuides g;
    g.albedo = albedo_;
    g.normal.resize(n);
    g.depth.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        g.normal[i] = centre_[i].normal;
        g.depth[i] = centre_[i].depth;
    }
    return g;
}

ImageRgb FinalFramePasses::denoise(const PixelAccumulator& sums, const FinalDenoiseSettings& settings) {
    PN_CHECK(sums.width() == width_ && sums.height() == height_ && settings.iterations >= 1);
    const auto* frame = static_cast<const shader::FrameUniforms*>(renderer_.frameUniforms().mapped());
    const shader::ViewerUniforms v = stillCameraUniforms(*frame, settings);
    std::memcpy(viewerUniforms_.mapped(), &v, sizeof v);
    runGBuffer();

    // The render's statistics as a still camera's history, and a "current frame" equal to the mean.
    const std::size_t n = std::size_t(width_) * height_;
    const ImageRgb mean = sums.image();
    std::vector<shader::HistoryTexel> history(n);
    std::vector<Vec4> current(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double taken = std::max<std::uint32_t>(sums.samplesTaken(i), 1);
        const double m1 = luminance(sums.rawMean(i));
        const double m2 = sums.data().squares[i] / taken;  // mean squared luminance of the samples
        history[i] = shader::HistoryTexel{mean.pixels[i], float(taken), float(m1), float(m2), 0.0f, 0.0f};
        current[i] = Vec4{mean.pixels[i].x, mean.pixels[i].y, mean.pixels[i].z, float(m2)};
    }
    makeDenoiser();
    gpu::uploadToBuffer(ctx_, commands_, historyIn_, std::span<const shader::HistoryTexel>(history));
    gpu::uploadToBuffer(ctx_, commands_, current_, std::span<const Vec4>(current));
    const gpu::Buffer* result = nullptr;
    commands_.run([&](VkCommandBuffer cmd) {
        gpu::computeBarrier(cmd);
        temporal_->record(cmd, width_, height_);
        gpu::computeBarrier(cmd);
        result = &atrous_->record(cmd, width_, height_, settings.iterations);
    });
    const auto filtered = gpu::downloadBuffer<Vec4>(ctx_, commands_, *result, n);
    ImageRgb out{int(width_), int(height_)};
    for (std::size_t i = 0; i < n; ++i) out.pixels[i] = Vec3{filtered[i].x, filtered[i].y, filtered[i].z};
    return out;
}

}  // namespace penumbra
