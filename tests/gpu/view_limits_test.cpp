// The WebGPU renderer's render distance and texture saturation on the real shaders (both trace
// kernels), on the textured quad under a uniform unit sky: a diffuse surface there reflects
// exactly its albedo, so each pixel's expected value is known (shared/view_limits.h's formulas).
#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scoped_tuning.h"
#include "shared/view_limits.h"

namespace penumbra::test {
namespace {

class ViewLimitsTest : public GpuTest, public ::testing::WithParamInterface<const char*> {};

// 8x8 texels: the left half red, the right half grey 128.
Scene redAndGreyQuad() {
    Texture tex;
    tex.name = "red and grey";
    tex.width = tex.height = 8;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const std::uint8_t texel[4] = {std::uint8_t(x < 4 ? 255 : 128), std::uint8_t(x < 4 ? 0 : 128),
                                           std::uint8_t(x < 4 ? 0 : 128), 255};
            tex.rgba.insert(tex.rgba.end(), texel, texel + 4);
        }
    return texturedQuadScene("red and grey", std::move(tex));
}

ImageRgb render(const gpu::Context& ctx, float saturation, float renderDistance) {
    RenderSettings settings = testSettings(32, 32, 16, 2);
    settings.textureSaturation = saturation;
    settings.renderDistance = renderDistance;
    Renderer r(ctx, redAndGreyQuad(), settings);
    r.render();
    return r.image();
}

void expectColor(const ImageRgb& img, int x, int y, Vec3 expected) {
    const Vec3 got = img.at(x, y);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 2e-3f) << "pixel " << x << "," << y << " channel " << c;
}

TEST_P(ViewLimitsTest, TextureSaturationMovesTexelsFromTheirGreyAndKeepsGreys) {
    ScopedTuning tuning;
    tuning.kernel(GetParam());
    const float grey = srgbToLinear8(128);
    const float redLuminance = 0.2126f;  // Rec. 709: the red texel's luminance
    for (float s : {0.0f, 0.5f, 1.0f, 1.6f}) {
        SCOPED_TRACE("saturation " + std::to_string(s));
        const ImageRgb img = render(*ctx, s, 0);
        const float r = shader::saturateChannel(1.0f, redLuminance, s), gb = shader::saturateChannel(0.0f, redLuminance, s);
        expectColor(img, 12, 12, {r, gb, gb});
        expectColor(img, 20, 12, {grey, grey, grey});  // grey has nothing to saturate
    }
    // The analytic values themselves: grey at 0, half way at 0.5, clamped above 1.
    EXPECT_NEAR(shader::saturateChannel(1.0f, redLuminance, 0.0f), redLuminance, 1e-6f);
    EXPECT_NEAR(shader::saturateChannel(1.0f, redLuminance, 0.5f), 0.6063f, 1e-4f);
    EXPECT_EQ(shader::saturateChannel(0.0f, redLuminance, 1.6f), 0.0f);
}

TEST_P(ViewLimitsTest, NothingBeyondTheRenderDistanceIsDrawn) {
    ScopedTuning tuning;
    tuning.kernel(GetParam());
    // The quad stands 2 m in front of the camera and reaches 1 m to each side (2.24 m away).
    const ImageRgb all = render(*ctx, 1, 0);
    expectColor(all, 9, 12, {1, 0, 0});
    // Beyond every point of the quad: the same image, bit for bit.
    const ImageRgb far = render(*ctx, 1, 3);
    ASSERT_EQ(far.pixels.size(), all.pixels.size());
    for (std::size_t i = 0; i < all.pixels.size(); ++i) ASSERT_EQ(far.pixels[i], all.pixels[i]) << "pixel " << i;
    // Nearer than the quad: only the sky.
    const ImageRgb near = render(*ctx, 1, 1.5f);
    for (int y = 0; y < 32; y += 5)
        for (int x = 0; x < 32; x += 5) expectColor(near, x, y, {1, 1, 1});
    // Through it: the middle (2.05 m across the floor) is drawn, the sides (2.13 m and more) not.
    const ImageRgb cut = render(*ctx, 1, 2.1f);
    expectColor(cut, 12, 12, {1, 0, 0});
    expectColor(cut, 9, 12, {1, 1, 1});
}

INSTANTIATE_TEST_SUITE_P(Kernels, ViewLimitsTest, ::testing::Values("mega", "wavefront"));

}  // namespace
}  // namespace penumbra::test
