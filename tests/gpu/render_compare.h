// Two renders of the same view, compared block by block with a tolerance derived from their
// sample counts: each block's mean luminance carries a standard error from its pixels' sample
// variances, and the renders agree when no block differs by more than z standard errors of the
// difference, z Sidak-corrected over the blocks. The renders must use different seeds (the
// errors are then independent). On a failure the two images are written as EXR and PNG files.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "image/write.h"
#include "render/renderer.h"
#include "render_helpers.h"

namespace penumbra::test {

struct SampledImage {
    std::uint32_t width = 0, height = 0;
    double spp = 0;
    std::vector<Vec4> sums;  // Renderer::accumulation(): rgb sums, a = sum of squared luminance

    ImageRgb mean() const {
        ImageRgb img(static_cast<int>(width), static_cast<int>(height));
        for (std::size_t i = 0; i < sums.size(); ++i)
            img.pixels[i] = Vec3{sums[i].x, sums[i].y, sums[i].z} / float(spp);
        return img;
    }
};

inline SampledImage renderSamples(const gpu::Context& ctx, const Scene& scene,
                                  const RenderSettings& settings) {
    Renderer r(ctx, scene, settings);
    r.render();
    EXPECT_EQ(r.stats().invalidSamples, 0u);
    return {settings.width, settings.height, double(settings.samplesPerPixel), r.accumulation()};
}

// Left and right swapped: what a right-handed camera sees of a mirrored world.
inline SampledImage mirroredLeftRight(const SampledImage& in) {
    SampledImage out = in;
    for (std::uint32_t y = 0; y < in.height; ++y)
        for (std::uint32_t x = 0; x < in.width; ++x)
            out.sums[y * in.width + x] = in.sums[y * in.width + (in.width - 1 - x)];
    return out;
}

struct BlockAgreement {
    double worstZ = 0;     // the largest |difference| / standard error over the blocks
    double threshold = 0;  // the Sidak-corrected z the blocks must stay under
    std::uint32_t worstX = 0, worstY = 0;  // that block's top-left pixel
    double expected = 0, actual = 0;       // that block's mean luminance in each render
    double meanRelativeError = 0;  // mean over blocks of stderr / |block mean| (the test's power)

    bool agrees() const { return worstZ <= threshold; }
};

inline BlockAgreement compareBlocks(const SampledImage& expected, const SampledImage& actual,
                                    std::uint32_t block, double alpha) {
    BlockAgreement out;
    const std::uint32_t bw = expected.width / block, bh = expected.height / block;
    out.threshold = sidakZ(alpha, std::size_t(bw) * bh);
    double relativeErrors = 0;
    for (std::uint32_t by = 0; by < bh; ++by)
        for (std::uint32_t bx = 0; bx < bw; ++bx) {
            double meanE = 0, meanA = 0, varE = 0, varA = 0;
            for (std::uint32_t y = by * block; y < (by + 1) * block; ++y)
                for (std::uint32_t x = bx * block; x < (bx + 1) * block; ++x) {
                    const PixelStats e =
                        pixelStats(expected.sums[y * expected.width + x], expected.spp);
                    const PixelStats a = pixelStats(actual.sums[y * actual.width + x], actual.spp);
                    meanE += e.mean, meanA += a.mean;
                    varE += e.stderr * e.stderr, varA += a.stderr * a.stderr;
                }
            const double n = double(block) * block;
            meanE /= n, meanA /= n;
            const double error = std::sqrt(varE + varA) / n;
            const double z = std::abs(meanE - meanA) / std::max(error, 1e-12);
            relativeErrors += error / std::max(std::abs(meanE), 1e-6);
            if (z > out.worstZ) {
                out.worstZ = z;
                out.worstX = bx * block, out.worstY = by * block;
                out.expected = meanE, out.actual = meanA;
            }
        }
    out.meanRelativeError = relativeErrors / (double(bw) * bh);
    return out;
}

// Expects the renders to agree, and writes NAME-{expected,actual}.{exr,png} when they do not.
inline void expectSameImage(const SampledImage& expected, const SampledImage& actual,
                            const std::string& name, std::uint32_t block = 4, double alpha = 1e-4) {
    ASSERT_EQ(expected.sums.size(), actual.sums.size());
    const BlockAgreement a = compareBlocks(expected, actual, block, alpha);
    EXPECT_LT(a.meanRelativeError, 0.05)
        << name << ": too few samples for the comparison to mean much";
    if (a.agrees()) return;
    const std::filesystem::path stem = std::filesystem::absolute(name);
    for (const char* ext : {".exr", ".png"}) {
        writeImage(stem.string() + "-expected" + ext, expected.mean(), {});
        writeImage(stem.string() + "-actual" + ext, actual.mean(), {});
    }
    ADD_FAILURE() << name << ": the " << block << "x" << block << " block at (" << a.worstX << ", "
                  << a.worstY << ") has mean luminance " << a.actual << " where " << a.expected
                  << " is expected: " << a.worstZ << " standard errors (at most " << a.threshold
                  << "); images: " << stem.string() << "-{expected,actual}.{exr,png}";
}

}  // namespace penumbra::test
