// A walk replayed without a window (`penumbra render --walk FILE`): the viewer's --script events,
// played frame by frame at a fixed frame time into the same controls and Navigation the viewer
// uses, so a walk renders the camera path `penumbra view --script FILE --fixed-dt DT` shows.
#pragma once

#include <cstdint>
#include <vector>

#include "interact/input_script.h"
#include "interact/navigation.h"
#include "interact/play_step.h"
#include "scene/scene.h"

namespace penumbra::viewer {

constexpr std::uint64_t kMaxWalkFrames = 1'000'000;

// Frames a walk takes at frameSeconds each: up to and including the first frame by which every
// event has been played (as the viewer plays them: events due by a frame's clock, then the clock
// advances). At least one. UsageError beyond kMaxWalkFrames.
std::uint64_t walkFrameCount(const std::vector<ScriptEvent>& events, double frameSeconds);

class WalkReplay {
public:
    // The scene's own movement mode (Doom levels walk, tile maps step on the grid, others fly).
    // phantom: the dungeon's phantom starts on (H in the events toggles it, as in the viewer).
    WalkReplay(const Scene& scene, std::vector<ScriptEvent> events, double frameSeconds, bool phantom = true);

    std::uint64_t frameCount() const { return frames_; }
    // Plays the next frame: the events due, the presses (F, G, R, ...), the move, the world.
    WorldChange nextFrame(Scene& scene);
    Camera camera() const { return nav_.camera(); }
    double clock() const { return clock_; }  // seconds played
    const Navigation& navigation() const { return nav_; }

private:
    double frameSeconds_;
    std::uint64_t frames_;
    Navigation nav_;
    ScriptPlayer player_;
    InputState input_;
    double clock_ = 0;
    bool phantom_ = true;
};

}  // namespace penumbra::viewer
