// Textures on the GPU: a quad with a 2x2 texture under a uniform white sky. A diffuse surface lit
// by a uniform unit background reflects exactly its albedo, so each quadrant of the image must
// show its texel's linear colour; alpha-tested texels must show the sky through them.
#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/mesh_builder.h"

namespace penumbra::test {
namespace {

Scene texturedQuad(float alphaCutoff) {
    // 8x8 texels in four 4x4 blocks, so bilinear filtering inside a block returns the block's
    // colour exactly: top-left red, top-right green, bottom-left blue (transparent), bottom-right grey.
    Texture tex;
    tex.name = "quadrants";
    tex.width = 8;
    tex.height = 8;
    const std::uint8_t blocks[4][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 0}, {128, 128, 128, 255}};
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            tex.rgba.insert(tex.rgba.end(), blocks[(y / 4) * 2 + x / 4], blocks[(y / 4) * 2 + x / 4] + 4);
    Scene scene = texturedQuadScene("textured quad", std::move(tex));
    scene.materials[0].alphaCutoff = alphaCutoff;
    return scene;
}

ImageRgb renderQuad(const gpu::Context& ctx, float alphaCutoff, Accel accel = Accel::Bvh) {
    RenderSettings settings = testSettings(32, 32, 16, 2);
    settings.accel = accel;
    Renderer r(ctx, texturedQuad(alphaCutoff), settings);
    r.render();
    return r.image();
}

void expectColor(const ImageRgb& img, int x, int y, Vec3 expected) {
    Vec3 got = img.at(x, y);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 2e-3f) << "pixel " << x << "," << y << " channel " << c;
}

TEST_F(GpuTest, TexturedQuadShowsEachTexelUnderAUniformSky) {
    ImageRgb img = renderQuad(*ctx, 0.0f);
    const float grey = srgbToLinear8(128);
    expectColor(img, 12, 12, {1, 0, 0});
    expectColor(img, 20, 12, {0, 1, 0});
    expectColor(img, 12, 20, {0, 0, 1});
    expectColor(img, 20, 20, {grey, grey, grey});
    expectColor(img, 0, 0, {1, 1, 1});  // the corner sees the sky past the quad
}

TEST_F(GpuTest, AlphaTestedTexelsAreHoles) {
    for (Accel accel : {Accel::Bvh, Accel::Wide}) {
        SCOPED_TRACE(accelName(accel));
        ImageRgb img = renderQuad(*ctx, 0.5f, accel);
        expectColor(img, 12, 20, {1, 1, 1});  // the transparent blue block shows the sky
        expectColor(img, 12, 12, {1, 0, 0});
    }
}

}  // namespace
}  // namespace penumbra::test
