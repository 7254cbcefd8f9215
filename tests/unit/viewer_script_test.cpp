// The viewer's input script: the parser (good lines, every kind of bad line, each an error naming
// the line) and the player, which feeds events into the same controls as real keys.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include "interact/input_script.h"
#include "core/error.h"

namespace penumbra::viewer {
namespace {

std::string errorOf(const std::string& text) {
    try {
        parseInputScript(text, "walk.txt");
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(ViewerScript, ParsesKeysMouseCommentsAndBlankLines) {
    const auto events = parseInputScript(
        "# walk and look\n"
        "\n"
        "0 key W down\n"
        "0.5   mouse  -12.5 3   # look left and a little down\n"
        "\t1 key left_shift down\r\n"
        "1.25 KEY Space UP\n"
        "2 key F1 down",  // no newline at the end
        "walk.txt");
    ASSERT_EQ(events.size(), 5u);
    EXPECT_EQ(events[0].kind, ScriptEvent::Kind::KeyDown);
    EXPECT_EQ(events[0].key, GLFW_KEY_W);
    EXPECT_EQ(events[0].time, 0.0);
    EXPECT_EQ(events[1].kind, ScriptEvent::Kind::Mouse);
    EXPECT_EQ(events[1].dx, -12.5f);
    EXPECT_EQ(events[1].dy, 3.0f);
    EXPECT_EQ(events[1].time, 0.5);
    EXPECT_EQ(events[2].key, GLFW_KEY_LEFT_SHIFT);
    EXPECT_EQ(events[3].kind, ScriptEvent::Kind::KeyUp);
    EXPECT_EQ(events[3].key, GLFW_KEY_SPACE);
    EXPECT_EQ(events[3].time, 1.25);
    EXPECT_EQ(events[4].key, GLFW_KEY_F1);
    EXPECT_TRUE(parseInputScript("", "empty.txt").empty());
    EXPECT_TRUE(parseInputScript("# nothing\n\n   \n", "empty.txt").empty());
}

TEST(ViewerScript, EveryMalformedLineIsOneErrorNamingItsLine) {
    const std::pair<const char*, const char*> cases[] = {
        {"0 key W down\nbanana key W down\n", "walk.txt:2: the time 'banana'"},
        {"-1 key W down\n", "walk.txt:1: the time '-1'"},
        {"nan key W down\n", "walk.txt:1: the time 'nan'"},
        {"1e9 key W down\n", "walk.txt:1: the time '1e9'"},
        {"1 key W down\n0.5 key W up\n", "walk.txt:2: the time '0.5' is earlier"},
        {"0 key FOO down\n", "walk.txt:1: unknown key 'FOO'"},
        {"0 key W sideways\n", "walk.txt:1: a key goes 'down' or 'up'"},
        {"0 key W\n", "walk.txt:1: a key line has exactly 4 words"},
        {"0 key W down now\n", "walk.txt:1: a key line has exactly 4 words"},
        {"\n\n0 mouse 1\n", "walk.txt:3: a mouse line has exactly 4 words"},
        {"0 mouse 1 x\n", "walk.txt:1: the mouse motion '1' 'x'"},
        {"0 mouse 1 inf\n", "walk.txt:1: the mouse motion"},
        {"0 jump\n", "walk.txt:1: unknown event 'jump'"},
        {"3\n", "walk.txt:1: a time with no event"},
        {"0 key W\x01 down\n", "walk.txt:1: unknown key 'W?'"},
    };
    for (const auto& [text, start] : cases) {
        const std::string error = errorOf(text);
        EXPECT_EQ(error.rfind(start, 0), 0u) << "input: " << text << "\nerror: " << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
        EXPECT_NE(error.find("expected 'SECONDS key NAME down|up'"), std::string::npos) << error;
    }
}

TEST(ViewerScript, AMissingFileIsAnInputError) {
    EXPECT_THROW(loadInputScript("/nonexistent/walk.txt"), Error);
}

TEST(ViewerScript, ThePlayerAppliesEventsWhenTheirTimeComesThroughTheControls) {
    ScriptPlayer player(
        parseInputScript("0 key W down\n0 mouse 10 0\n0.5 key W up\n0.5 key P down\n", "s"));
    InputState input;
    player.playFrame(input, 0.25);  // clock 0: W and the mouse
    EXPECT_EQ(cameraInputFrom(input).forward, 1.0f);
    EXPECT_EQ(cameraInputFrom(input).lookX, 10.0f);
    endInputFrame(input);
    player.playFrame(input, 0.25);  // clock 0.25: nothing new; W still held, the look was used
    EXPECT_EQ(cameraInputFrom(input).forward, 1.0f);
    EXPECT_EQ(cameraInputFrom(input).lookX, 0.0f);
    EXPECT_FALSE(player.finished());
    player.playFrame(input, 0.25);  // clock 0.5: W up, P pressed (play/pause, as the real key)
    EXPECT_EQ(cameraInputFrom(input).forward, 0.0f);
    EXPECT_TRUE(input.pauseToggled);
    EXPECT_TRUE(player.finished());
    EXPECT_DOUBLE_EQ(player.clock(), 0.75);
}

TEST(ViewerControls, KeysMapToMovesAndRequests) {
    InputState in;
    applyKey(in, GLFW_KEY_D, true);
    applyKey(in, GLFW_KEY_UP, true);  // arrows move as in Doom
    applyKey(in, GLFW_KEY_Q, true);
    applyKey(in, GLFW_KEY_RIGHT_SHIFT, true);
    CameraInput move = cameraInputFrom(in);
    EXPECT_EQ(move.forward, 1.0f);
    EXPECT_EQ(move.right, 1.0f);
    EXPECT_EQ(move.turn, 1.0f);
    EXPECT_TRUE(move.fast);
    applyKey(in, GLFW_KEY_W, true);  // W and Up together are still one forward
    EXPECT_EQ(cameraInputFrom(in).forward, 1.0f);
    applyKey(in, GLFW_KEY_F, true);
    applyKey(in, GLFW_KEY_TAB, true);
    applyKey(in, GLFW_KEY_ESCAPE, true);
    EXPECT_TRUE(in.walkToggled && in.panelToggled && in.escape);
    endInputFrame(in);
    EXPECT_FALSE(in.walkToggled || in.panelToggled || in.escape);
    EXPECT_EQ(cameraInputFrom(in).right, 1.0f) << "held keys stay held across frames";
    applyKey(in, -1, true);  // GLFW_KEY_UNKNOWN
    applyKey(in, 100000, true);
}

}  // namespace
}  // namespace penumbra::viewer
