// Glass in the path tracer, against analytic answers: a slab of glass under a uniform unit sky
// is lossless (every path leaves with weight 1, whatever it reflects or refracts), and an
// index-matched absorbing slab (ior 1: no reflection, no bending) transmits exactly
// exp(-sigma d), the absorption colour at its distance.
#include <cmath>

#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/mesh_builder.h"
#include "shared/constants.h"

namespace penumbra::test {
namespace {

// A closed box of glass, faces wound outward, 1 m thick along z and wide enough to fill a
// narrow view.
Scene glassSlab(float ior, Vec3 absorptionColor, float absorptionDistance) {
    Scene scene;
    scene.name = "slab";
    Material glass;
    glass.name = "glass";
    glass.albedo = Vec3{1.0f};
    glass.transmission = 1.0f;
    glass.roughness = 0.0f;
    glass.ior = ior;
    glass.absorptionColor = absorptionColor;
    glass.absorptionDistance = absorptionDistance;
    scene.materials.push_back(glass);
    Mesh box;
    box.name = "slab";
    const float w = 20.0f, h = 0.5f;
    const Vec3 p[8] = {{-w, -w, -h}, {w, -w, -h}, {w, w, -h}, {-w, w, -h},
                       {-w, -w, h},  {w, -w, h},  {w, w, h},  {-w, w, h}};
    addQuad(box, p[3], p[2], p[1], p[0]);  // z = -h, faces -z
    addQuad(box, p[6], p[7], p[4], p[5]);  // z = +h, faces +z
    addQuad(box, p[7], p[3], p[0], p[4]);  // x = -w, faces -x
    addQuad(box, p[2], p[6], p[5], p[1]);  // x = +w, faces +x
    addQuad(box, p[0], p[1], p[5], p[4]);  // y = -w, faces -y
    addQuad(box, p[7], p[6], p[2], p[3]);  // y = +w, faces +y
    scene.meshes.push_back(box);
    scene.camera.position = {0, 0, 3};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.fovYDegrees = 8.0f;
    scene.background = Vec3{1.0f};
    return scene;
}

RenderSettings slabSettings() {
    RenderSettings s;
    s.width = 12;
    s.height = 12;
    s.samplesPerPixel = 64;
    s.samplesPerPass = 64;
    s.maxBounces = kMaxBounces;  // paths end by leaving (or by roulette), not by the cap
    return s;
}

TEST_F(GpuTest, ClearGlassUnderAUniformSkyIsLossless) {
    Renderer r(*ctx, glassSlab(1.5f, Vec3{1.0f}, 0.0f), slabSettings());
    r.render();
    EXPECT_EQ(r.stats().invalidSamples, 0u);
    // Weights are exactly 1 until Russian roulette, which keeps the mean: allow its noise.
    std::vector<Vec4> sums = r.accumulation();
    const double z = sidakZ(1e-3, sums.size());
    for (std::size_t i = 0; i < sums.size(); ++i) {
        PixelStats p = pixelStats(sums[i], r.settings().samplesPerPixel);
        EXPECT_NEAR(p.mean, 1.0, z * p.stderr + 1e-4) << "pixel " << i;
    }
}

TEST_F(GpuTest, IndexMatchedAbsorberTransmitsTheAbsorptionColour) {
    const Vec3 colour{0.5f, 0.25f, 0.8f};
    Renderer r(*ctx, glassSlab(1.0f, colour, 1.0f), slabSettings());
    r.render();
    EXPECT_EQ(r.stats().invalidSamples, 0u);
    ImageRgb img = r.image();
    // Off-axis rays cross the slab at angle theta and travel 1 / cos(theta) metres inside.
    const double tanHalf = std::tan(degreesToRadians(4.0));
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 12; ++x) {
            const double px = (2 * (x + 0.5) / 12 - 1) * tanHalf, py = (2 * (y + 0.5) / 12 - 1) * tanHalf;
            const double pathLength = std::sqrt(1 + px * px + py * py);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(img.at(x, y)[c], std::pow(colour[c], pathLength), 2e-3) << x << "," << y << " channel " << c;
        }
}

}  // namespace
}  // namespace penumbra::test
