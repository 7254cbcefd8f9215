// Which rendered frames go to the browsers (render thread only). The renderer runs as fast as
// the GPU allows, which keeps the temporal history converging; frames are copied for encoding
// on a schedule: maxFps while the camera or the scene moves, restFps once everything has stood
// still for a quarter second (at rest the picture only refines, and at the rest quality each
// frame is about twice the bytes). A schedule, not a sleep: a frame that moves is due at once
// when the last frame sent was a resting one long enough ago, so input is never held back.
#pragma once

#include <chrono>

namespace penumbra::serve {

struct PaceOptions {
    double maxFps = 60;    // while moving; 0: every frame
    double restFps = 15;   // at rest; 0: every frame
    double restAfterSeconds = 0.25;
};

class FramePacer {
public:
    using Clock = std::chrono::steady_clock;
    explicit FramePacer(const PaceOptions& options) : options_(options) {}

    // Something moved in the frame about to be rendered.
    void noteMotion(Clock::time_point now) { lastMotion_ = now; }
    // Whether frames should be encoded at the motion quality now.
    bool moving(Clock::time_point now) const;
    // Whether the frame about to be rendered, finishing about `frameSeconds` from `now`, is due;
    // when it is, the schedule moves on.
    bool takeFrame(Clock::time_point now, double frameSeconds);

private:
    PaceOptions options_;
    Clock::time_point lastMotion_{}, lastTaken_{};
};

}  // namespace penumbra::serve
