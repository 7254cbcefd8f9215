// The debug view over the image in the display pass: blended by its opacity, and scaled down
// into the small window (picture-in-picture) with the image around it.
#include <cmath>

#include "image/tonemap.h"
#include "render/passes/tonemap_pass.h"
#include "viewer_pass_fixture.h"

namespace penumbra::test {
namespace {

class DebugOverlayTest : public ViewerPassTest {
protected:
    // A grey-ramp image and an albedo that differs at every pixel, shown in the albedo view.
    void SetUp() override {
        ViewerPassTest::SetUp();
        if (!ctx) return;
        setUpImage(64, 48);
        history = pixels<shader::HistoryTexel>();
        filtered = pixels<Vec4>();
        gbuffer = pixels<shader::GBufferTexel>();
        display = pixels<std::uint32_t>();
        for (std::uint32_t y = 0; y < height; ++y)
            for (std::uint32_t x = 0; x < width; ++x) {
                const std::uint32_t i = y * width + x;
                view<shader::HistoryTexel>(history)[i].color = Vec3(0.05f + 0.03f * float(x % 7));
                view<shader::GBufferTexel>(gbuffer)[i] =
                    surfaceTexel(2.0f, {0, 0, -1}, {float(x) / width, float(y) / height, 0.9f});
            }
        viewerUniforms.debugMode = PN_DEBUG_ALBEDO;
    }

    Vec3 image(std::uint32_t i) {
        const Vec3 c = view<shader::HistoryTexel>(history)[i].color;
        return {reinhard(c.x), reinhard(c.y), reinhard(c.z)};
    }
    Vec3 albedo(std::uint32_t x, std::uint32_t y) {
        return view<shader::GBufferTexel>(gbuffer)[y * width + x].albedo;
    }

    void render(float opacity, bool inset) {
        viewerUniforms.debugOpacity = opacity;
        viewerUniforms.debugInset = inset ? 1u : 0u;
        writeViewer();
        TonemapPass pass(*ctx, frame, viewer, history, filtered, gbuffer, display);
        submit([&](VkCommandBuffer cmd) { pass.record(cmd, width, height); });
    }

    // Display pixel i against a display-linear colour, within one 8-bit step.
    void expectShows(std::uint32_t i, Vec3 want, const char* what) {
        const std::uint32_t got = view<std::uint32_t>(display)[i];
        for (int ch = 0; ch < 3; ++ch)
            ASSERT_LE(std::abs(int((got >> (8 * ch)) & 255u) - int(toSrgb8(want[ch]))), 1)
                << what << " at pixel (" << i % width << ", " << i / width << ") channel " << ch;
    }

    gpu::Buffer history, filtered, gbuffer, display;
};

TEST_F(DebugOverlayTest, OpacityBlendsTheDebugViewOverTheImage) {
    for (float opacity : {0.0f, 0.3f, 1.0f}) {
        render(opacity, false);
        for (std::uint32_t y = 0; y < height; ++y)
            for (std::uint32_t x = 0; x < width; ++x) {
                const std::uint32_t i = y * width + x;
                expectShows(i, image(i) * (1 - opacity) + albedo(x, y) * opacity, "blend");
            }
    }
}

TEST_F(DebugOverlayTest, TheSmallWindowShowsTheWholeViewScaledDownAndTheImageAroundIt) {
    render(1.0f, true);
    // 64 x 48 makes a 16 x 12 window whose top left is 8 pixels plus its size from the corner;
    // window pixel q shows view pixel 4q + 2 (the centre of the 4 x 4 block it stands for).
    const std::uint32_t iw = width / PN_DEBUG_INSET_DIVISOR, ih = height / PN_DEBUG_INSET_DIVISOR;
    const int x0 = int(width - PN_DEBUG_INSET_MARGIN - iw),
              y0 = int(height - PN_DEBUG_INSET_MARGIN - ih);
    int inWindow = 0, onFrame = 0;
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::uint32_t i = y * width + x;
            const int qx = int(x) - x0, qy = int(y) - y0;
            if (qx >= 0 && qy >= 0 && qx < int(iw) && qy < int(ih)) {
                expectShows(i, albedo(std::uint32_t(4 * qx + 2), std::uint32_t(4 * qy + 2)),
                            "window");
                ++inWindow;
            } else if (qx >= -1 && qy >= -1 && qx <= int(iw) && qy <= int(ih)) {
                expectShows(i, Vec3(1.0f), "frame");
                ++onFrame;
            } else {
                expectShows(i, image(i), "image");
            }
        }
    EXPECT_EQ(inWindow, 16 * 12);
    EXPECT_EQ(onFrame, 2 * (18 + 12));
    // At half opacity the window is half image, half view.
    render(0.5f, true);
    const std::uint32_t i = std::uint32_t(y0 + 3) * width + std::uint32_t(x0 + 5);
    expectShows(i, image(i) * 0.5f + albedo(4 * 5 + 2, 4 * 3 + 2) * 0.5f, "half-opaque window");
}

}  // namespace
}  // namespace penumbra::test
