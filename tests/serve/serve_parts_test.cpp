// The small parts of the server: browsers' input merged, the frame pacer's rates, the token
// check, the JPEG round trip and the embedded page.
#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <cmath>

#include "serve/browser_input.h"
#include "serve/client_hub.h"
#include "serve/frame_pacer.h"
#include "serve/http_server.h"
#include "serve/jpeg_encoder.h"
#include "serve/web_assets.h"

namespace penumbra::serve {
namespace {

TEST(ServeInput, KeysAreHeldWhileAnyBrowserHoldsThemAndGoWithTheBrowser) {
    BrowserInput input;
    viewer::applyKey(input.of(1), GLFW_KEY_W, true);
    viewer::applyKey(input.of(2), GLFW_KEY_W, true);
    viewer::applyLook(input.of(1), 3, 0);
    viewer::applyLook(input.of(2), 4, -1);
    viewer::InputState m = input.merged();
    EXPECT_TRUE(m.held[GLFW_KEY_W]);
    EXPECT_FLOAT_EQ(m.lookX, 7);
    EXPECT_FLOAT_EQ(m.lookY, -1);
    input.endFrame();
    EXPECT_FLOAT_EQ(input.merged().lookX, 0);  // motion is used once
    viewer::applyKey(input.of(1), GLFW_KEY_W, false);
    EXPECT_TRUE(input.merged().held[GLFW_KEY_W]);  // browser 2 still holds it
    input.remove(2);                               // browser 2 went away mid-press
    EXPECT_FALSE(input.merged().held[GLFW_KEY_W]);
}

TEST(ServeInput, PressesOfOneBrowserToggleOnce) {
    BrowserInput input;
    viewer::applyKey(input.of(1), GLFW_KEY_P, true);
    EXPECT_TRUE(input.merged().pauseToggled);
    viewer::applyKey(input.of(2), GLFW_KEY_P, true);
    EXPECT_FALSE(input.merged().pauseToggled);  // two presses in one frame: toggled twice
}

// Frames taken over `seconds` of a renderer producing one every `frameSeconds`.
int framesTaken(FramePacer& pacer, double seconds, double frameSeconds, bool moving) {
    using Clock = FramePacer::Clock;
    const Clock::time_point start = Clock::now();
    int taken = 0;
    const long frames = std::lround(seconds / frameSeconds);
    for (long i = 0; i < frames; ++i) {
        const auto now =
            start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(double(i) * frameSeconds));
        if (moving) pacer.noteMotion(now);
        if (pacer.takeFrame(now, frameSeconds)) ++taken;
    }
    return taken;
}

// A connection that only counts what it is sent.
struct CountingConnection : ClientConnection {
    int frames = 0, texts = 0;
    void sendFrame(std::shared_ptr<const EncodedFrame>) override { ++frames; }
    void sendStats(std::shared_ptr<const nlohmann::json>) override { ++texts; }
    void sendText(std::shared_ptr<const std::string>) override { ++texts; }
};

TEST(ServeHub, BoundsBrowsersAndWaitingMessages) {
    ClientHub hub;
    hub.setHello({{"t", "hello"}});
    std::vector<std::shared_ptr<CountingConnection>> connections;
    std::vector<std::uint64_t> ids;
    for (std::size_t i = 0; i < ClientHub::kMaxClients; ++i) {
        connections.push_back(std::make_shared<CountingConnection>());
        ids.push_back(hub.join(connections.back()));
        EXPECT_NE(ids.back(), 0u);
        EXPECT_EQ(connections.back()->texts, 1);  // the hello, at once
    }
    auto extra = std::make_shared<CountingConnection>();
    EXPECT_EQ(hub.join(extra), 0u);  // full
    EXPECT_EQ(hub.clients(), ClientHub::kMaxClients);
    hub.leave(ids[0]);
    EXPECT_NE(hub.join(extra), 0u);  // a place came free
    hub.broadcastFrame(std::make_shared<EncodedFrame>());
    EXPECT_EQ(extra->frames, 1);
    EXPECT_EQ(connections[0]->frames, 0);  // it left
    hub.drain();
    for (std::size_t i = 0; i < ClientHub::kMaxInbox + 100; ++i) hub.post(ids[1], ClientMessage{});
    hub.leave(ids[2]);  // a departure is never dropped, however full the inbox
    const std::vector<InboxItem> items = hub.drain();
    ASSERT_EQ(items.size(), ClientHub::kMaxInbox + 1);
    EXPECT_EQ(items.back().kind, InboxItem::Kind::Left);
}

TEST(ServePacer, SendsMaxFpsWhileMovingAndRestFpsAtRest) {
    FramePacer pacer(PaceOptions{60, 15, 0.25});
    // A renderer at 290 frames a second: the schedule keeps the rate, not the rate minus drift.
    EXPECT_NEAR(framesTaken(pacer, 10, 1 / 290.0, true), 600, 6);
    FramePacer resting(PaceOptions{60, 15, 0.25});
    EXPECT_NEAR(framesTaken(resting, 10, 1 / 290.0, false), 150, 3);
    // A renderer slower than the rate: every frame goes.
    FramePacer slow(PaceOptions{60, 15, 0.25});
    EXPECT_EQ(framesTaken(slow, 10, 0.1, true), 100);
    FramePacer unlimited(PaceOptions{0, 0, 0.25});
    EXPECT_EQ(framesTaken(unlimited, 1, 0.01, true), 100);
}

TEST(ServePacer, MotionAfterRestIsDueAtOnce) {
    using Clock = FramePacer::Clock;
    FramePacer pacer(PaceOptions{60, 15, 0.25});
    const Clock::time_point t0 = Clock::now();
    EXPECT_TRUE(pacer.takeFrame(t0, 0.004));
    EXPECT_FALSE(pacer.moving(t0));
    const Clock::time_point t1 = t0 + std::chrono::milliseconds(20);  // a rest frame is not due yet
    EXPECT_FALSE(pacer.takeFrame(t1, 0.004));
    pacer.noteMotion(t1);  // a key press: at the motion rate, the frame is due
    EXPECT_TRUE(pacer.moving(t1));
    EXPECT_TRUE(pacer.takeFrame(t1, 0.004));
    EXPECT_FALSE(pacer.moving(t1 + std::chrono::milliseconds(300)));
}

TEST(ServeToken, TheUrlMustCarryExactlyTheToken) {
    EXPECT_TRUE(targetHasToken("/ws", ""));
    EXPECT_TRUE(targetHasToken("/ws?token=s3cret", "s3cret"));
    EXPECT_TRUE(targetHasToken("/?a=1&token=s3cret&b=2", "s3cret"));
    for (const char* target : {"/ws", "/ws?token=", "/ws?token=s3cre", "/ws?token=s3cretX", "/ws?tok=s3cret",
                               "/ws?xtoken=s3cret", "/ws#token=s3cret"})
        EXPECT_FALSE(targetHasToken(target, "s3cret")) << target;
    EXPECT_EQ(targetPath("/ws?token=a"), "/ws");
    EXPECT_EQ(targetPath("/"), "/");
}

TEST(ServeJpeg, RoundTripKeepsThePicture) {
    const int w = 64, h = 48;
    std::vector<std::uint8_t> rgbx(std::size_t(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = &rgbx[(std::size_t(y) * w + x) * 4];
            p[0] = std::uint8_t(x * 4), p[1] = std::uint8_t(y * 5), p[2] = 128, p[3] = 0;
        }
    JpegEncoder encoder;
    std::string jpeg, rgb;
    encoder.encode(rgbx.data(), w, h, 90, jpeg);
    int dw = 0, dh = 0;
    ASSERT_TRUE(decodeJpeg(jpeg, dw, dh, rgb));
    ASSERT_EQ(dw, w);
    ASSERT_EQ(dh, h);
    double error = 0;
    for (std::size_t i = 0; i < std::size_t(w) * h; ++i)
        for (int c = 0; c < 3; ++c) error += std::abs(double(rgb[i * 3 + c] & 0xff) - rgbx[i * 4 + c]);
    EXPECT_LT(error / (w * h * 3), 3.0);  // a smooth ramp at quality 90: a few levels at most
    EXPECT_FALSE(decodeJpeg("not a jpeg", dw, dh, rgb));
    EXPECT_FALSE(decodeJpeg(jpeg.substr(0, 20), dw, dh, rgb));
}

TEST(ServeWeb, ThePageAndTheElementAreEmbedded) {
    const std::optional<WebAsset> page = findWebAsset("/");
    ASSERT_TRUE(page);
    EXPECT_EQ(page->contentType.substr(0, 9), "text/html");
    EXPECT_NE(page->body.find("penumbra-view"), std::string_view::npos);
    const std::optional<WebAsset> element = findWebAsset("/penumbra-view.js");
    ASSERT_TRUE(element);
    EXPECT_EQ(element->contentType.substr(0, 15), "text/javascript");
    EXPECT_NE(element->body.find("customElements.define"), std::string_view::npos);
    EXPECT_FALSE(findWebAsset("/../etc/passwd"));
    EXPECT_FALSE(findWebAsset("/nope.js"));
}

}  // namespace
}  // namespace penumbra::serve
