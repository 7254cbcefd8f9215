// render --walk's replay: the frame count a walk takes, and the camera path, which must be the
// one the viewer's own loop makes of the same script at the same fixed step.
#include "interact/walk_replay.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <cstring>

#include "core/error.h"
#include "scene/phantom.h"
#include "scene/presets/presets.h"

namespace penumbra::viewer {
namespace {

TEST(WalkReplay, FrameCountEndsOnTheFrameThatPlaysTheLastEvent) {
    EXPECT_EQ(walkFrameCount({}, 0.1), 1u);
    EXPECT_EQ(walkFrameCount(parseInputScript("0 key W down", "w"), 0.1), 1u);
    // Frame k plays the events due by k * 0.25 s: the event at 1 s is played by frame 4 (the 5th).
    EXPECT_EQ(walkFrameCount(parseInputScript("0 key W down\n1 key W up", "w"), 0.25), 5u);
    // Just after a frame's moment: one frame more.
    EXPECT_EQ(walkFrameCount(parseInputScript("0 key W down\n1.01 key W up", "w"), 0.25), 6u);
    EXPECT_THROW(walkFrameCount(parseInputScript("100000 key W up", "w"), 0.01), UsageError);
}

TEST(WalkReplay, FollowsTheViewersLoopFrameForFrame) {
    Scene scene = makePreset("cornell");
    const std::string text = "0 key W down\n0.3 mouse 40 -10\n0.5 key D down\n0.75 key W up\n1 key D up";
    const double dt = 1.0 / 24;
    WalkReplay replay(scene, parseInputScript(text, "w"), dt);
    ASSERT_EQ(replay.frameCount(), walkFrameCount(parseInputScript(text, "w"), dt));

    // The viewer's order each frame (app/viewer/viewer_app.cpp): script, presses, move, clock.
    Navigation nav(scene, false);
    ScriptPlayer player(parseInputScript(text, "w"));
    InputState input;
    double clock = 0;
    const Vec3 start = replay.camera().position;
    for (std::uint64_t frame = 0; frame < replay.frameCount(); ++frame) {
        replay.nextFrame(scene);
        player.playFrame(input, dt);
        nav.handlePresses(input, scene);
        nav.update(cameraInputFrom(input), float(dt));
        clock += float(dt);  // the viewer steps by a float
        endInputFrame(input);
        EXPECT_EQ(replay.camera().position, nav.camera().position) << "frame " << frame;
        EXPECT_EQ(replay.camera().lookAt, nav.camera().lookAt) << "frame " << frame;
        EXPECT_DOUBLE_EQ(replay.clock(), clock);
    }
    EXPECT_TRUE(player.finished());
    // Held W for 0.75 s and D for 0.5 s at the flight speed: it went somewhere.
    EXPECT_GT(length(replay.camera().position - start), 0.5f * cameraSpeedFor(scene));
}

// render --walk --no-phantom: the dungeon's phantom starts parked, as `view --no-phantom` has
// it, and H in the walk's events puts it back on its patrol, as in the viewer.
TEST(WalkReplay, PhantomStartsAsAskedAndHTogglesIt) {
    Scene scene = makePreset("dungeon");
    const PhantomSwitch probe(scene);
    ASSERT_TRUE(probe.present());
    std::uint32_t phantom = 0;
    while (scene.prototypes[scene.instances[phantom].prototype].name != kPhantomPrototype) ++phantom;
    const float floorY = scene.bounds().lo.y;
    auto standing = [&] { return scene.instances[phantom].transform.m[1][3] > floorY - 1.0f; };

    const std::string text = "0.5 key H down\n0.55 key H up\n1.5 key W up";
    WalkReplay replay(scene, parseInputScript(text, "w"), 0.1, false);
    EXPECT_TRUE(replay.nextFrame(scene).instancesMoved);  // parked on the first frame
    EXPECT_FALSE(standing()) << "--no-phantom: it starts parked under the level";
    const Affine parked = scene.instances[phantom].transform;
    for (int k = 1; k < 5; ++k) replay.nextFrame(scene);
    EXPECT_EQ(scene.instances[phantom].transform.m[0][3], parked.m[0][3]) << "parked, it does not patrol";
    for (int k = 5; k < 8; ++k) replay.nextFrame(scene);  // H at 0.5 s
    EXPECT_TRUE(standing()) << "H put it back";
    const Affine back = scene.instances[phantom].transform;
    for (int k = 8; k < 14; ++k) replay.nextFrame(scene);
    EXPECT_NE(std::memcmp(&back, &scene.instances[phantom].transform, sizeof back), 0) << "on its patrol again";

    Scene shown = makePreset("dungeon");
    WalkReplay defaults(shown, parseInputScript("1 key W up", "w"), 0.1);
    defaults.nextFrame(shown);
    EXPECT_GT(shown.instances[phantom].transform.m[1][3], floorY - 1.0f) << "on by default, as in view";
}

}  // namespace
}  // namespace penumbra::viewer
