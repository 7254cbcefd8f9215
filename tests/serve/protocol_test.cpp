// The browser's messages (serve/protocol.h): every well-formed kind is read as written, and
// malformed ones of every sort are refused with a reason, never thrown or crashed on.
#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <random>

#include "serve/protocol.h"

namespace penumbra::serve {
namespace {

ClientMessage parsed(std::string_view text) {
    std::string error;
    std::optional<ClientMessage> m = parseClientMessage(text, error);
    EXPECT_TRUE(m.has_value()) << text << ": " << error;
    return m.value_or(ClientMessage{});
}

std::string refused(std::string_view text) {
    std::string error;
    EXPECT_FALSE(parseClientMessage(text, error).has_value()) << text;
    EXPECT_FALSE(error.empty()) << text;
    return error;
}

TEST(ServeProtocol, ReadsEveryKindOfMessage) {
    const ClientMessage key = parsed(R"({"t":"key","code":"KeyW","down":true,"seq":7})");
    EXPECT_EQ(key.seq, 7u);
    EXPECT_EQ(std::get<KeyMessage>(key.body).key, GLFW_KEY_W);
    EXPECT_TRUE(std::get<KeyMessage>(key.body).down);
    const ClientMessage look = parsed(R"({"t":"look","dx":-3.5,"dy":2})");
    EXPECT_FLOAT_EQ(std::get<LookMessage>(look.body).dx, -3.5f);
    EXPECT_FLOAT_EQ(std::get<LookMessage>(look.body).dy, 2.0f);
    EXPECT_EQ(look.seq, 0u);
    EXPECT_FLOAT_EQ(std::get<WheelMessage>(parsed(R"({"t":"wheel","dy":-1})").body).notches, -1.0f);
    const ClickMessage click = std::get<ClickMessage>(parsed(R"({"t":"click","x":0.25,"y":0.75})").body);
    EXPECT_FLOAT_EQ(click.x, 0.25f);
    EXPECT_FLOAT_EQ(click.y, 0.75f);
    EXPECT_TRUE(std::get<GrabMessage>(parsed(R"({"t":"grab","x":0.5,"y":0.5,"turn":true})").body).turn);
    EXPECT_FALSE(std::get<GrabMessage>(parsed(R"({"t":"grab","x":0.5,"y":0.5})").body).turn);
    EXPECT_FLOAT_EQ(std::get<DragMessage>(parsed(R"({"t":"drag","x":0.1,"y":0.9})").body).y, 0.9f);
    EXPECT_TRUE(std::holds_alternative<ReleaseMessage>(parsed(R"({"t":"release"})").body));
    const SetMessage set = std::get<SetMessage>(parsed(R"({"t":"set","name":"spp","value":4})").body);
    EXPECT_EQ(set.name, "spp");
    EXPECT_EQ(set.value, 4);
    EXPECT_EQ(std::get<AckMessage>(parsed(R"({"t":"ack","frame":4294967295})").body).frame, 4294967295u);
}

TEST(ServeProtocol, RefusesMalformedMessages) {
    for (const char* bad : {"", "not json", "[1,2]", "42", "{}", R"({"t":5})", R"({"t":"fly"})",
                            R"({"t":"key","code":"KeyW"})", R"({"t":"key","code":87,"down":true})",
                            R"({"t":"key","code":"KeyW","down":"yes"})", R"({"t":"look","dx":"1","dy":0})",
                            R"({"t":"look","dx":1})", R"({"t":"look","dx":1e300,"dy":0})",
                            R"({"t":"click","x":0.5})", R"({"t":"grab","x":0.5,"y":0.5,"turn":1})",
                            R"({"t":"set","value":1})", R"({"t":"set","name":3,"value":1})",
                            R"({"t":"ack","frame":-1})", R"({"t":"ack","frame":4294967296})",
                            R"({"t":"ack","frame":1.5})", R"({"t":"release","seq":-2})",
                            R"({"t":"release","seq":"1"})", R"({"t":"key","code":"KeyW","down":true)"})
        refused(bad);
    EXPECT_NE(refused(std::string(kMaxClientMessageBytes + 1, ' ')).find("longer"), std::string::npos);
    // An unknown type is named in the reason, cut short so a long one cannot flood the log.
    const std::string reason = refused(R"({"t":")" + std::string(1000, 'x') + R"("})");
    EXPECT_LT(reason.size(), 80u);
}

TEST(ServeProtocol, RandomBytesNeverCrash) {
    std::mt19937 rng(7);
    const std::string alphabet = R"({}[]":,.-+0123456789eEtrufalsn keyloowhcdgbsqx\)";
    int accepted = 0;
    for (int i = 0; i < 20000; ++i) {
        std::string text(rng() % 64, ' ');
        for (char& c : text) c = alphabet[rng() % alphabet.size()];
        if (i % 3 == 0) text = R"({"t":"look","dx":)" + text;
        std::string error;
        if (parseClientMessage(text, error)) ++accepted;
        else EXPECT_FALSE(error.empty());
    }
    EXPECT_LT(accepted, 20000);
}

TEST(ServeProtocol, MapsBrowserKeyCodesToTheViewersKeys) {
    EXPECT_EQ(keyFromBrowserCode("KeyA"), GLFW_KEY_A);
    EXPECT_EQ(keyFromBrowserCode("KeyZ"), GLFW_KEY_Z);
    EXPECT_EQ(keyFromBrowserCode("Digit0"), GLFW_KEY_0);
    EXPECT_EQ(keyFromBrowserCode("Space"), GLFW_KEY_SPACE);
    EXPECT_EQ(keyFromBrowserCode("ShiftLeft"), GLFW_KEY_LEFT_SHIFT);
    EXPECT_EQ(keyFromBrowserCode("ArrowUp"), GLFW_KEY_UP);
    EXPECT_EQ(keyFromBrowserCode("Comma"), GLFW_KEY_COMMA);
    EXPECT_EQ(keyFromBrowserCode("Period"), GLFW_KEY_PERIOD);
    for (const char* unknown : {"", "Key", "Keya", "KeyAA", "Digit", "F13", "MediaPlay", "keyw"})
        EXPECT_EQ(keyFromBrowserCode(unknown), -1) << unknown;
}

}  // namespace
}  // namespace penumbra::serve
