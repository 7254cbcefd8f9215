// Imported scenes through the real shaders: a textured glTF quad must show its texture where its
// UVs say, and Freedoom's E1M1 from the player start must render finite and plausibly lit.
#include <cstdlib>
#include <filesystem>

#include "../unit/io/io_test_util.h"
#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/io/load.h"

namespace penumbra::test {
namespace {

// tests/data/gltf/textured_quad.gltf: a 2x2 m quad at z=0 seen by its own camera at z=2 with a
// 90-degree field of view, so the quad fills the middle half of the image. Its 4x4 base-colour
// texture holds four 2x2 blocks (red, green / blue, grey); bilinear filtering returns a block's
// colour exactly over the middle half of the block, where the test looks. A diffuse surface under
// a uniform unit sky reflects exactly its albedo, so the pixels equal the texels' linear colours
// (the material turns off glTF's specular layer with KHR_materials_specular, so it is pure Lambert).
TEST_F(GpuTest, TexturedGltfQuadShowsItsTexture) {
    Scene scene = loadSceneFile(dataDir() / "gltf/textured_quad.gltf");
    scene.background = Vec3{1.0f};
    Renderer r(*ctx, scene, testSettings(32, 32, 16, 2));
    r.render();
    EXPECT_EQ(r.stats().invalidSamples, 0u);
    ImageRgb img = r.image();
    // The quad covers pixels 8..23; each block's exact region is 2 pixels wide around its centre.
    const float grey = srgbToLinear8(128);
    const struct { int x, y; Vec3 colour; } probes[] = {
        {11, 11, {1, 0, 0}}, {12, 12, {1, 0, 0}},            // top left: red
        {19, 11, {0, 1, 0}}, {20, 12, {0, 1, 0}},            // top right: green
        {11, 19, {0, 0, 1}}, {12, 20, {0, 0, 1}},            // bottom left: blue
        {19, 19, {grey, grey, grey}}, {20, 20, {grey, grey, grey}},  // bottom right: grey
        {2, 2, {1, 1, 1}}, {29, 29, {1, 1, 1}},              // around the quad: the sky
    };
    for (const auto& p : probes) {
        Vec3 got = img.at(p.x, p.y);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[c], p.colour[c], 2e-3f) << "pixel " << p.x << "," << p.y << " channel " << c;
    }
}

// E1M1 of Debian's freedoom1.wad from the player start with the camera torch: every sample is
// finite, almost every pixel receives light (walls, floor and ceiling are all in view of the
// torch), and the mean lies in a plausible band for a dim level lit by lamps and a torch (a
// black image, or one blown out by a light placed wrongly, falls outside it).
TEST_F(GpuTest, FreedoomE1M1FromThePlayerStartRendersFiniteAndLit) {
    const std::filesystem::path wad = "/usr/share/games/doom/freedoom1.wad";
    PENUMBRA_REQUIRE_ASSET(wad);
    LoadOptions options;
    options.map = "E1M1";
    Scene scene = loadSceneFile(wad, options);
    ASSERT_TRUE(scene.torch.enabled) << "WAD levels carry the torch by default";
    attachTorch(scene);
    Renderer r(*ctx, scene, testSettings(64, 40, 8, 3));
    r.render();
    EXPECT_EQ(r.stats().invalidSamples, 0u);
    ImageRgb img = r.image();
    double sum = 0;
    int lit = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            Vec3 c = img.at(x, y);
            for (int k = 0; k < 3; ++k) ASSERT_TRUE(std::isfinite(c[k])) << x << "," << y;
            double l = luminance(c);
            sum += l;
            lit += l > 0;
        }
    const int pixels = img.width * img.height;
    double mean = sum / pixels;
    EXPECT_GT(lit, pixels * 9 / 10) << "most of the view should be lit";
    EXPECT_GT(mean, 0.005) << "E1M1 renders almost black";
    EXPECT_LT(mean, 1.0) << "E1M1 renders blown out";
}

}  // namespace
}  // namespace penumbra::test
