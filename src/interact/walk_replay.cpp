#include "interact/walk_replay.h"

#include "core/error.h"

namespace penumbra::viewer {

std::uint64_t walkFrameCount(const std::vector<ScriptEvent>& events, double frameSeconds) {
    PN_CHECK(frameSeconds > 0);
    const double last = events.empty() ? 0.0 : events.back().time;
    // The clock as ScriptPlayer sums it, so rounding agrees with the replay frame for frame.
    double clock = 0;
    std::uint64_t frame = 0;
    while (clock < last) {
        clock += frameSeconds;
        if (++frame >= kMaxWalkFrames)
            throw UsageError("the walk is longer than a million frames at this --fps");
    }
    return frame + 1;
}

WalkReplay::WalkReplay(const Scene& scene, std::vector<ScriptEvent> events, double frameSeconds, bool phantom)
    : frameSeconds_(frameSeconds),
      frames_(walkFrameCount(events, frameSeconds)),
      nav_(scene, false),
      player_(std::move(events)),
      phantom_(phantom) {}

WorldChange WalkReplay::nextFrame(Scene& scene) {
    player_.playFrame(input_, frameSeconds_);
    (void)nav_.handlePresses(input_, scene);
    WorldChange change = playStep(scene, nav_, input_, clock_, float(frameSeconds_));
    // The phantom's switch as the viewer has it (viewer_app.cpp): after the step, at its clock.
    if (input_.phantomToggled && nav_.hasPhantom()) phantom_ = !phantom_;
    if (nav_.showPhantom(scene, phantom_, clock_)) change.instancesMoved = true;
    endInputFrame(input_);
    return change;
}

}  // namespace penumbra::viewer
