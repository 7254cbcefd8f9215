#include "serve/frame_pacer.h"

namespace penumbra::serve {

bool FramePacer::moving(Clock::time_point now) const {
    return std::chrono::duration<double>(now - lastMotion_).count() < options_.restAfterSeconds;
}

bool FramePacer::takeFrame(Clock::time_point now, double frameSeconds) {
    const double fps = moving(now) ? options_.maxFps : options_.restFps;
    const double interval = fps > 0 ? 1.0 / fps : 0.0;
    // Due one interval after the last frame taken; a frame finishing within half a frame of that
    // is taken (rendering the next would overshoot further than this one undershoots).
    const double since = std::chrono::duration<double>(now - lastTaken_).count() + frameSeconds * 0.5;
    if (since < interval) return false;
    // Keep the rhythm: the next frame is due one interval after this one was, not after now,
    // unless the schedule fell behind by more than an interval.
    const auto step = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(interval));
    lastTaken_ = since < 2 * interval ? lastTaken_ + step : now;
    return true;
}

}  // namespace penumbra::serve
