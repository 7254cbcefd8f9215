// A final render in rounds, under a budget: a sample count, a wall-clock limit, a stop request
// (SIGINT/SIGTERM), whichever comes first; with adaptive sampling and checkpoints.
//
// A round is a fixed number of passes (roundPasses): the GPU adds them into its fp32 buffer,
// then the round's sums are read back into PixelAccumulator's doubles and the next round's
// adaptive plan is made. Submissions inside a round are sized by time (about 0.1 s each, and
// never past the time limit), but round boundaries depend only on the pass count, so the
// image does not depend on how fast the device was: an interrupted and resumed render equals
// an uninterrupted one bit for bit.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <vector>

#include "image/image.h"
#include "render/accumulator.h"
#include "render/adaptive.h"
#include "render/renderer.h"

namespace penumbra {

// Passes per round: short rounds when adaptive sampling needs fresh decisions, longer ones
// otherwise (each round costs a read-back).
std::uint32_t roundPasses(const AdaptiveSettings& adaptive);

struct RenderBudget {
    std::uint32_t samplesPerPixel = 64;  // nominal samples per pixel at most
    double seconds = 0;                  // wall-clock limit; 0: none
    const std::atomic<int>* stop = nullptr;  // nonzero: finish the pass and stop (a signal's number)
    double checkpointSeconds = 0;        // 0: no checkpoints
    std::function<void()> onCheckpoint;  // called every checkpointSeconds (write image and state)
    // After each submission: nominal samples per pixel so far, and the seconds left (< 0: unknown).
    std::function<void(std::uint32_t, double)> onProgress;
};

enum class StopReason { Samples, TimeLimit, Signal };

// Per pixel: the variance of the mean's luminance (variance AOV), and the samples taken
// (samples AOV).
std::vector<float> varianceOf(const PixelAccumulator& sums);
std::vector<float> samplesTakenOf(const PixelAccumulator& sums);
// Samples traced over nominal samples, in [0, 1]: what adaptive sampling saved.
double sampledFraction(const PixelAccumulator& sums);

// What a checkpoint keeps: enough to continue exactly where the render stopped.
struct RenderSnapshot {
    std::uint32_t passesDone = 0;
    AccumulatorData sums;
    std::vector<Vec4> pending;  // the GPU's sums of the round in progress (empty at a round boundary)
};

class ProgressiveRender {
public:
    ProgressiveRender(Renderer& renderer, const AdaptiveSettings& adaptive);

    StopReason run(const RenderBudget& budget);

    // The sums so far, the round in progress included (read back from the GPU).
    PixelAccumulator current();
    // The image so far.
    ImageRgb image() { return current().image(); }

    std::uint32_t samplesPerPixel() const;  // nominal, so far
    RenderSnapshot snapshot();
    void restore(const RenderSnapshot& snapshot);  // a fresh render's state only (PN_CHECK)

private:
    void startRound();
    void finishRound();
    std::uint32_t passInRound() const;

    Renderer& renderer_;
    AdaptiveSettings adaptive_;
    std::uint32_t roundPasses_;
    PixelAccumulator sums_;
    RoundPlan plan_;
    bool planned_ = false;
};

}  // namespace penumbra
