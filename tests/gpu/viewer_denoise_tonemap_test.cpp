// The a-trous denoiser (on illumination, albedo divided out and multiplied back) and the display
// pass against the CPU tone mapper.
#include <cmath>
#include <random>

#include "image/tonemap.h"
#include "render/passes/denoise_pass.h"
#include "render/passes/temporal_pass.h"
#include "render/passes/tonemap_pass.h"
#include "render/view_settings.h"
#include "viewer_pass_fixture.h"

namespace penumbra::test {
namespace {

class DenoiseTest : public ViewerPassTest {
protected:
    // One first frame through temporal (which demodulates) and then `iterations` a-trous passes;
    // returns the denoised radiance per pixel. With a display buffer the last pass also fills it.
    std::vector<Vec3> denoise(const std::vector<Vec3>& radiance, const std::vector<Vec3>& albedo, std::uint32_t iterations,
                              const gpu::Buffer* display = nullptr) {
        gpu::Buffer accum = pixels<Vec4>(), gbuffer = pixels<shader::GBufferTexel>(), gbufferPrev = pixels<shader::GBufferTexel>();
        gpu::Buffer history = pixels<shader::HistoryTexel>(), historyOut = pixels<shader::HistoryTexel>();
        gpu::Buffer a = pixels<Vec4>(), b = pixels<Vec4>(), guide = pixelBytes(PN_DENOISE_GUIDE_BYTES);
        gpu::Buffer estimates = pixels<Vec4>();
        for (std::uint32_t i = 0; i < width * height; ++i) {
            float y = luminance(radiance[i]);
            view<Vec4>(accum)[i] = Vec4{radiance[i].x, radiance[i].y, radiance[i].z, y * y};
            view<shader::GBufferTexel>(gbuffer)[i] = surfaceTexel(3.0f, {0, 0, -1}, albedo[i]);
        }
        TemporalPass temporal(*ctx, TemporalBuffers{&frame, &viewer, &accum, &gbuffer, &gbufferPrev, &history, &historyOut, &a, &guide,
                                                    &estimates});
        DenoisePass pass(*ctx, frame, viewer, gbuffer, guide, historyOut, a, b, display);
        const gpu::Buffer* result = nullptr;
        submit([&](VkCommandBuffer cmd) {
            temporal.record(cmd, width, height);
            gpu::computeBarrier(cmd);
            result = &pass.record(cmd, width, height, iterations, display != nullptr);
        });
        std::vector<Vec3> out(width * height);
        for (std::uint32_t i = 0; i < width * height; ++i) {
            Vec4 v = view<Vec4>(*result)[i];
            out[i] = Vec3{v.x, v.y, v.z};
        }
        return out;
    }
};

TEST_F(DenoiseTest, AFlatLitCheckerTextureComesOutUnchanged) {
    // Constant illumination times a 2-pixel checker albedo: blurring radiance would smear the
    // checker; with the albedo divided out, the filter sees a constant and changes nothing.
    setUpImage(48, 40);
    const Vec3 light{1.0f, 0.8f, 0.6f};
    std::vector<Vec3> radiance(width * height), albedo(width * height);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            Vec3 a = ((x / 2 + y / 2) % 2) ? Vec3{0.9f, 0.85f, 0.8f} : Vec3{0.1f, 0.2f, 0.05f};
            albedo[y * width + x] = a;
            radiance[y * width + x] = Vec3{a.x * light.x, a.y * light.y, a.z * light.z};
        }
    std::vector<Vec3> out = denoise(radiance, albedo, 5);
    for (std::uint32_t i = 0; i < width * height; ++i)
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(out[i][c], radiance[i][c], 1e-4) << "pixel " << i << " channel " << c;
}

TEST_F(DenoiseTest, NoiseOnAFlatSurfaceIsReducedAndItsMeanKept) {
    setUpImage(48, 40);
    const float sigma = 0.3f;
    std::mt19937 rng(11);
    std::normal_distribution<float> noise(0.0f, sigma);
    std::vector<Vec3> radiance(width * height), albedo(width * height, Vec3{0.5f});
    for (Vec3& r : radiance) r = Vec3{0.5f * std::max(0.0f, 1.0f + noise(rng))};
    std::vector<Vec3> out = denoise(radiance, albedo, 5);
    auto stats = [&](const std::vector<Vec3>& img, double& mean, double& variance) {
        double s = 0, s2 = 0;
        for (const Vec3& v : img) s += v.x, s2 += double(v.x) * v.x;
        mean = s / img.size();
        variance = s2 / img.size() - mean * mean;
    };
    double inMean, inVar, outMean, outVar;
    stats(radiance, inMean, inVar);
    stats(out, outMean, outVar);
    EXPECT_LT(outVar, inVar / 10) << "in " << inVar << " out " << outVar;
    // The input mean's standard error is 0.5 sigma / sqrt(pixels) ~ 0.0034; allow 5 of them.
    EXPECT_NEAR(outMean, inMean, 5 * 0.5 * sigma / std::sqrt(double(width * height)));
}

TEST_F(DenoiseTest, ItsLastPassDisplaysWhatTheTonemapPassWould) {
    // The viewer skips the tonemap pass when the denoiser's last pass writes the display: the
    // pixels must be the tonemap pass's own, byte for byte, for both curves and any exposure.
    setUpImage(40, 32);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<Vec3> radiance(width * height), albedo(width * height);
    for (std::uint32_t i = 0; i < width * height; ++i) {
        albedo[i] = Vec3{0.2f + 0.7f * unit(rng), 0.5f, 0.3f + 0.6f * unit(rng)};
        radiance[i] = albedo[i] * (4.0f * unit(rng) * unit(rng));
    }
    gpu::Buffer display = pixels<std::uint32_t>(), tonemapped = pixels<std::uint32_t>(), filtered = pixels<Vec4>();
    gpu::Buffer history = pixels<shader::HistoryTexel>(), gbuffer = pixels<shader::GBufferTexel>();
    TonemapPass tonemap(*ctx, frame, viewer, history, filtered, gbuffer, tonemapped);
    viewerUniforms.denoise = 1;
    for (ToneMapper curve : {ToneMapper::Reinhard, ToneMapper::Aces})
        for (float exposure : {0.0f, 2.5f}) {
            viewerUniforms.toneMapper = std::uint32_t(curve);
            viewerUniforms.exposure = exposure;
            writeViewer();
            const std::vector<Vec3> out = denoise(radiance, albedo, 3, &display);
            for (std::uint32_t i = 0; i < width * height; ++i) view<Vec4>(filtered)[i] = Vec4{out[i].x, out[i].y, out[i].z, 0.0f};
            submit([&](VkCommandBuffer cmd) { tonemap.record(cmd, width, height); });
            for (std::uint32_t i = 0; i < width * height; ++i)
                ASSERT_EQ(view<std::uint32_t>(display)[i], view<std::uint32_t>(tonemapped)[i])
                    << "pixel " << i << (curve == ToneMapper::Aces ? " ACES" : " Reinhard") << " exposure " << exposure;
        }
}

TEST_F(ViewerPassTest, TonemapPassMatchesTheCpuToneMapper) {
    const std::vector<float> values = {0.0f, 1e-4f, 0.003f, 0.01f, 0.18f, 0.5f, 1.0f, 2.0f, 10.0f, 1000.0f, -1.0f, INFINITY};
    setUpImage(std::uint32_t(values.size()), 3);
    gpu::Buffer history = pixels<shader::HistoryTexel>(), filtered = pixels<Vec4>(), gbuffer = pixels<shader::GBufferTexel>();
    gpu::Buffer display = pixels<std::uint32_t>();
    // Row y: channel r = value, g = value / 3, b = value * 3.
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x)
            view<shader::HistoryTexel>(history)[y * width + x].color = Vec3{values[x], values[x] / 3, values[x] * 3};
    TonemapPass pass(*ctx, frame, viewer, history, filtered, gbuffer, display);
    for (ToneMapper curve : {ToneMapper::Reinhard, ToneMapper::Aces})
        for (float exposure : {0.0f, 1.5f, -2.0f}) {
            viewerUniforms.toneMapper = std::uint32_t(curve);
            viewerUniforms.exposure = exposure;
            writeViewer();
            submit([&](VkCommandBuffer cmd) { pass.record(cmd, width, height); });
            for (std::uint32_t i = 0; i < width * height; ++i) {
                Vec3 c = view<shader::HistoryTexel>(history)[i].color;
                std::uint32_t got = view<std::uint32_t>(display)[i];
                EXPECT_EQ(got >> 24, 255u);
                for (int ch = 0; ch < 3; ++ch) {
                    float x = c[ch] * std::exp2(exposure);
                    int want = toSrgb8(curve == ToneMapper::Aces ? acesFilmic(x) : reinhard(x));
                    int have = int((got >> (8 * ch)) & 255u);
                    // One step of 8-bit rounding for the GPU's pow and division.
                    EXPECT_LE(std::abs(have - want), 1) << "value " << c[ch] << " exposure " << exposure
                                                        << (curve == ToneMapper::Aces ? " ACES" : " Reinhard");
                }
            }
        }
}

}  // namespace
}  // namespace penumbra::test
