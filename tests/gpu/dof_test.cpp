// Thin-lens depth of field against its exact geometry. The camera looks down -z at an emissive
// step edge (x < 0 bright, radiance 1; x > 0 black) on the plane at depth z. A camera ray
// through image coordinate u (tangent units, u = x/depth for a pinhole) starts at lens offset
// l and aims at u f on the focal plane at depth f, so it meets depth z at u z + l (1 - z/f): it
// sees the bright side when u < l (1/f - 1/z). With l uniform on a disk of radius A, the point
// is spread over a circle of confusion of radius A |1/f - 1/z| in tangent units, which is
// A |1/f - 1/z| * height / (2 tan(fov/2)) pixels. Each pixel's expected value is then the
// fraction of that disk (convolved with the pixel's box) on the bright side.
#include <cmath>

#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/mesh_builder.h"
#include "shared/constants.h"

namespace penumbra::test {
namespace {

constexpr std::uint32_t kWidth = 48, kHeight = 8, kSpp = 1024;
constexpr float kFovY = 2.0f;    // degrees
constexpr float kDepth = 2.0f;   // of the edge's plane

Scene edgeScene(float aperture, float focus) {
    Scene s;
    s.name = "edge";
    std::uint32_t bright = addMaterial(s, "bright", Vec3{0}, Vec3{1});
    std::uint32_t dark = addMaterial(s, "dark", Vec3{0});
    Mesh left, right;
    left.name = "bright half";
    left.material = bright;
    addQuad(left, {-10, -10, -kDepth}, {0, -10, -kDepth}, {0, 10, -kDepth}, {-10, 10, -kDepth});  // faces +z
    right.name = "dark half";
    right.material = dark;
    addQuad(right, {0, -10, -kDepth}, {10, -10, -kDepth}, {10, 10, -kDepth}, {0, 10, -kDepth});
    s.meshes = {left, right};
    s.camera.position = {0, 0, 0};
    s.camera.lookAt = {0, 0, -1};
    s.camera.up = {0, 1, 0};
    s.camera.fovYDegrees = kFovY;
    s.camera.apertureRadius = aperture;
    s.camera.focusDistance = focus;
    return s;
}

// Mean of each column over all rows and samples: the fraction of samples that saw the bright side.
std::vector<double> columnProfile(const gpu::Context& ctx, const Scene& scene) {
    RenderSettings settings;
    settings.width = kWidth;
    settings.height = kHeight;
    settings.samplesPerPixel = kSpp;
    settings.samplesPerPass = 128;
    settings.maxBounces = 0;
    Renderer r(ctx, scene, settings);
    r.render();
    EXPECT_EQ(r.stats().invalidSamples, 0u);
    std::vector<double> columns(kWidth, 0.0);
    std::vector<Vec4> sums = r.accumulation();
    for (std::uint32_t y = 0; y < kHeight; ++y)
        for (std::uint32_t x = 0; x < kWidth; ++x) columns[x] += sums[y * kWidth + x].x;
    for (double& c : columns) c /= double(kHeight) * kSpp;
    return columns;
}

double pixelsPerTangent() { return kHeight / (2.0 * std::tan(kFovY * 0.5 * kPi / 180.0)); }

// Circle-of-confusion radius in pixels for the thin lens above.
double cocRadiusPixels(double aperture, double focus) { return aperture * std::abs(1.0 / focus - 1.0 / kDepth) * pixelsPerTangent(); }

// Expected column values: P(bright) at image position x (pixels from the left) is the share of
// the CoC disk (radius rho pixels, centred on x) left of the edge at x = width / 2, averaged
// over each column's width.
std::vector<double> expectedProfile(double rho) {
    auto brightShare = [&](double x) {
        double s = x - kWidth / 2.0;  // pixels right of the edge
        if (rho <= 0) return s < 0 ? 1.0 : 0.0;
        double q = std::clamp(s / rho, -1.0, 1.0);
        // Fraction of a unit disk with horizontal coordinate > q.
        return 0.5 - (q * std::sqrt(1 - q * q) + std::asin(q)) / kPi;
    };
    std::vector<double> out(kWidth);
    const int steps = 2000;
    for (std::uint32_t i = 0; i < kWidth; ++i) {
        double sum = 0;
        for (int k = 0; k < steps; ++k) sum += brightShare(i + (k + 0.5) / steps);
        out[i] = sum / steps;
    }
    return out;
}

// Spread of the edge: standard deviation (pixels) of the line-spread function, the profile's
// negative difference, which sits between columns.
double edgeSpread(const std::vector<double>& p) {
    double mass = 0, first = 0, second = 0;
    for (std::size_t i = 0; i + 1 < p.size(); ++i) {
        double d = p[i] - p[i + 1];
        double x = double(i) + 1.0;
        mass += d;
        first += d * x;
        second += d * x * x;
    }
    double mean = first / mass;
    return std::sqrt(std::max(0.0, second / mass - mean * mean));
}

void expectProfile(const std::vector<double>& got, const std::vector<double>& want) {
    // Each column is a mean of n Bernoulli samples; Sidak over the columns.
    const double n = double(kHeight) * kSpp;
    const double z = sidakZ(1e-4, kWidth);
    for (std::uint32_t i = 0; i < kWidth; ++i) {
        double sigma = std::sqrt(std::max(want[i] * (1 - want[i]), 0.25 / n) / n);
        EXPECT_NEAR(got[i], want[i], z * sigma + 1e-4) << "column " << i;
    }
}

TEST_F(GpuTest, PinholeAndInFocusEdgesAreSharp) {
    for (float aperture : {0.0f, 0.05f}) {
        std::vector<double> p = columnProfile(*ctx, edgeScene(aperture, kDepth));
        expectProfile(p, expectedProfile(0.0));
        // The edge lies on a column boundary: every column is all bright or all dark, and the
        // line-spread function is (nearly) a single step, well under a pixel wide.
        EXPECT_LT(edgeSpread(p), 0.5) << "aperture " << aperture;
    }
}

TEST_F(GpuTest, OutOfFocusEdgeIsBlurredByTheCircleOfConfusion) {
    const float aperture = 0.05f;
    for (float focus : {1.0f, 4.0f}) {  // focused in front of the edge, then behind it
        const double rho = cocRadiusPixels(aperture, focus);  // 5.7 and 2.9 pixels
        std::vector<double> p = columnProfile(*ctx, edgeScene(aperture, focus));
        expectProfile(p, expectedProfile(rho));
        // The semicircle law of a disk's projection has variance rho^2 / 4. Differences of
        // box-averaged columns see it through a triangle kernel (box * box), which adds 1/6.
        const double spread = edgeSpread(p);
        const double diameter = 2.0 * std::sqrt(std::max(0.0, 4.0 * (spread * spread - 1.0 / 6.0)));
        EXPECT_NEAR(diameter, 2.0 * rho, 0.1 * 2.0 * rho) << "focus " << focus;
    }
}

}  // namespace
}  // namespace penumbra::test
