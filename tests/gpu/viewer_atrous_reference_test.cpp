// The a-trous passes, whose texels carry half floats and whose first passes read through a
// shared-memory tile, against a double-precision reference of the same filter written here from
// its definition (SVGF's edge-stopping functions on a 5x5 B3-spline kernel), on an image with
// depth and normal edges, misses, a slope, a gradient and noise, whose size is no multiple of the
// 8x8 workgroup (so tiles are cut by the image's border).
#include <cmath>
#include <random>

#include "render/passes/denoise_pass.h"
#include "render/passes/temporal_pass.h"
#include "viewer_pass_fixture.h"

namespace penumbra::test {
namespace {

float halfToFloat(std::uint32_t h) {
    const int exponent = int((h >> 10) & 31u), mantissa = int(h & 1023u);
    const float magnitude = exponent == 0 ? std::ldexp(float(mantissa), -24)
                                          : exponent == 31 ? INFINITY : std::ldexp(float(1024 + mantissa), exponent - 25);
    return (h & 0x8000u) ? -magnitude : magnitude;
}

// One pixel of the filter's state: guide (as the test made it) and signal.
struct RefTexel {
    Vec3 normal;
    double depth;  // 0: a miss
    double rgb[3];
    double variance;
};

class AtrousReferenceTest : public ViewerPassTest {
protected:
    void SetUp() override {
        ViewerPassTest::SetUp();
        if (!ctx) return;
        setUpImage(43, 29);
        const std::uint32_t n = width * height;
        accum = pixels<Vec4>(), gbuffer = pixels<shader::GBufferTexel>(), gbufferPrev = pixels<shader::GBufferTexel>();
        history = pixels<shader::HistoryTexel>(), historyOut = pixels<shader::HistoryTexel>();
        a = pixels<Vec4>(), b = pixels<Vec4>();
        std::mt19937 rng(5);
        std::normal_distribution<float> noise(0.0f, 0.2f);
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t x = i % width, y = i / width;
            shader::GBufferTexel& g = view<shader::GBufferTexel>(gbuffer)[i];
            const Vec3 albedo{0.3f + 0.6f * float((x / 3 + y / 2) % 2), 0.5f, 0.2f + 0.02f * float(x)};
            if (y < 3) {
                g = shader::GBufferTexel{};  // sky: a miss
            } else if (x < 27) {
                g = surfaceTexel(3.0f + 0.05f * float(x), {0, 0, -1}, albedo, 1);  // a slope facing the camera
            } else {
                g = surfaceTexel(y < 15 ? 6.0f : 2.0f, {-1, 0, 0}, albedo, 2);  // a wall, and a depth step
            }
            const Vec3 light{0.4f + 1.5f * float(x) / float(width), 1.0f + float(y) / float(height), 0.8f};
            const Vec3 a = g.surfaceId ? g.albedo : Vec3{1.0f};
            const float grain = std::max(0.0f, 1.0f + noise(rng));
            const Vec3 radiance = Vec3{light.x * a.x, light.y * a.y, light.z * a.z} * grain;
            const float lum = luminance(radiance);
            view<Vec4>(accum)[i] = Vec4{radiance.x, radiance.y, radiance.z, lum * lum};
        }
    }

    // Runs temporal.comp (a first frame) and returns its texels, decoded.
    std::vector<RefTexel> temporalTexels(const TemporalPass& temporal) {
        submit([&](VkCommandBuffer cmd) { temporal.record(cmd, width, height); });
        std::vector<RefTexel> out(width * height);
        for (std::uint32_t i = 0; i < width * height; ++i) {
            const auto* t = view<std::uint32_t>(a) + 4 * i;
            const shader::GBufferTexel& g = view<shader::GBufferTexel>(gbuffer)[i];
            float depth;
            std::memcpy(&depth, &t[1], sizeof depth);
            EXPECT_EQ(depth, g.surfaceId ? g.depth : 0.0f) << "pixel " << i;
            const double deviation = halfToFloat(t[3] >> 16);
            out[i] = RefTexel{g.normal, depth, {halfToFloat(t[2] & 0xffffu), halfToFloat(t[2] >> 16), halfToFloat(t[3] & 0xffffu)},
                              deviation * deviation};
        }
        return out;
    }

    // One a-trous pass of the given step, in double precision.
    std::vector<RefTexel> referencePass(const std::vector<RefTexel>& in, int step) const {
        const int w = int(width), h = int(height);
        const double kB3[3] = {3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0};
        const double sigmaL = viewerUniforms.sigmaLuminance, sigmaN = viewerUniforms.sigmaNormal, sigmaZ = viewerUniforms.sigmaDepth;
        auto inside = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h; };
        auto lum = [](const double* c) { return double(luminance(Vec3{float(c[0]), float(c[1]), float(c[2])})); };
        std::vector<RefTexel> out = in;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const RefTexel& c = in[y * w + x];
                if (!(c.depth > 0)) continue;
                double variance = 0, kernelSum = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        if (!inside(x + dx, y + dy)) continue;
                        const double k = (dx == 0 ? 0.5 : 0.25) * (dy == 0 ? 0.5 : 0.25);
                        variance += k * in[(y + dy) * w + x + dx].variance;
                        kernelSum += k;
                    }
                const double lumScale = sigmaL * std::sqrt(variance / kernelSum) + 1e-6;
                auto depthAt = [&](int qx, int qy) { return inside(qx, qy) ? in[qy * w + qx].depth : c.depth; };
                const double gx = 0.5 * (depthAt(x + 1, y) - depthAt(x - 1, y));
                const double gy = 0.5 * (depthAt(x, y + 1) - depthAt(x, y - 1));
                double sum[3] = {0, 0, 0}, varianceSum = 0, weightSum = 0;
                for (int dy = -2; dy <= 2; ++dy)
                    for (int dx = -2; dx <= 2; ++dx) {
                        const int qx = x + dx * step, qy = y + dy * step;
                        if (!inside(qx, qy)) continue;
                        const RefTexel& t = in[qy * w + qx];
                        if (!(t.depth > 0)) continue;
                        const double cosine = std::max(0.0, double(dot(c.normal, t.normal)));
                        const double depthScale = sigmaZ * std::abs(gx * dx * step + gy * dy * step) + 1e-3 * c.depth;
                        const double weight = kB3[std::abs(dx)] * kB3[std::abs(dy)] * std::pow(cosine, sigmaN) *
                                              std::exp(-std::abs(c.depth - t.depth) / depthScale) *
                                              std::exp(-std::abs(lum(c.rgb) - lum(t.rgb)) / lumScale);
                        for (int ch = 0; ch < 3; ++ch) sum[ch] += weight * t.rgb[ch];
                        varianceSum += weight * weight * t.variance;
                        weightSum += weight;
                    }
                RefTexel& o = out[y * w + x];
                for (int ch = 0; ch < 3; ++ch) o.rgb[ch] = sum[ch] / weightSum;
                o.variance = varianceSum / (weightSum * weightSum);
            }
        return out;
    }

    // The largest difference between `passes` GPU passes and the reference, over every pixel and
    // channel, as a fraction of the largest illumination times that pixel's albedo.
    double worstError(std::uint32_t passes) {
        TemporalPass temporal(*ctx, TemporalBuffers{&frame, &viewer, &accum, &gbuffer, &gbufferPrev, &history, &historyOut, &a});
        std::vector<RefTexel> ref = temporalTexels(temporal);
        double largest = 0;
        for (const RefTexel& t : ref) largest = std::max({largest, t.rgb[0], t.rgb[1], t.rgb[2]});
        for (std::uint32_t k = 0; k < passes; ++k) ref = referencePass(ref, 1 << k);
        DenoisePass pass(*ctx, frame, viewer, gbuffer, a, b);
        const gpu::Buffer* result = nullptr;
        submit([&](VkCommandBuffer cmd) { result = &pass.record(cmd, width, height, passes); });
        double worst = 0;
        for (std::uint32_t i = 0; i < width * height; ++i) {
            const shader::GBufferTexel& g = view<shader::GBufferTexel>(gbuffer)[i];
            const Vec3 albedo = g.surfaceId ? max(g.albedo, Vec3{1e-3f}) : Vec3{1.0f};
            const Vec4 v = view<Vec4>(*result)[i];
            const float got[3] = {v.x, v.y, v.z};
            for (int ch = 0; ch < 3; ++ch) {
                EXPECT_TRUE(std::isfinite(got[ch])) << "pixel " << i;
                worst = std::max(worst, std::abs(got[ch] - ref[i].rgb[ch] * albedo[ch]) / (albedo[ch] * largest));
            }
        }
        return worst;
    }

    gpu::Buffer accum, gbuffer, gbufferPrev, history, historyOut, a, b;
};

// The bound, as a fraction of the largest illumination M. Each store between passes rounds the
// illumination and the deviation to half floats, relative error u = 2^-11. In the next pass's
// weighted mean that moves the result by at most u M through the tap values, and through each
// luminance weight w = exp(-x), x = |L_c - L_t| / lumScale, by w dx |c_t - c|, where dx <=
// u (L_c + L_t) / lumScale + u x and, on a smooth image, |c_t - c| is about x lumScale: at most
// 2u M x exp(-x) + u lumScale x^2 exp(-x) <= (0.74 + 0.54) u M per unit weight. So about 2.3u M
// per store; later passes average earlier errors without growing them. Allow 4u per store, plus
// u for float arithmetic and the GPU's exp2 and log2 (the first pass reads the same rounded
// input as the reference, so it has only the latter).
double bound(std::uint32_t passes) { return (4.0 * (passes - 1) + 1.0) * std::ldexp(1.0, -11); }

TEST_F(AtrousReferenceTest, OneTiledPassMatchesTheDoubleReference) {
    const double e = worstError(1);
    EXPECT_LT(e, bound(1));
    std::printf("one pass: worst error %.3g of the largest illumination (bound %.3g)\n", e, bound(1));
}

TEST_F(AtrousReferenceTest, TiledAndUntiledPassesMatchTheDoubleReference) {
    // Steps 1 and 2 read through the shared tile, 4 and 8 directly.
    const double e = worstError(4);
    EXPECT_LT(e, bound(4));
    std::printf("four passes: worst error %.3g of the largest illumination (bound %.3g)\n", e, bound(4));
}

TEST_F(AtrousReferenceTest, IlluminationBeyondHalfRangeStaysFinite) {
    // An emitter of radiance 1e6 behind a black albedo (1e9 after the 1e-3 floor): clamped to
    // the largest half, no infinity or NaN spreads to its neighbours.
    const std::uint32_t hot = 10 * width + 10;
    view<shader::GBufferTexel>(gbuffer)[hot].albedo = Vec3{0.0f};
    view<Vec4>(accum)[hot] = Vec4{1e6f, 1e6f, 1e6f, 1e12f};
    TemporalPass temporal(*ctx, TemporalBuffers{&frame, &viewer, &accum, &gbuffer, &gbufferPrev, &history, &historyOut, &a});
    DenoisePass pass(*ctx, frame, viewer, gbuffer, a, b);
    const gpu::Buffer* result = nullptr;
    submit([&](VkCommandBuffer cmd) {
        temporal.record(cmd, width, height);
        gpu::computeBarrier(cmd);
        result = &pass.record(cmd, width, height, 5);
    });
    for (std::uint32_t i = 0; i < width * height; ++i) {
        const Vec4 v = view<Vec4>(*result)[i];
        ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w)) << "pixel " << i;
    }
    EXPECT_LE(view<Vec4>(*result)[hot].x, PN_DENOISE_HALF_MAX * 1e-3 * 1.001);
}

}  // namespace
}  // namespace penumbra::test
