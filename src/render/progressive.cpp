#include "render/progressive.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"

namespace penumbra {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

std::uint32_t roundPasses(const AdaptiveSettings& adaptive) { return adaptive.enabled() ? 16 : 64; }

ProgressiveRender::ProgressiveRender(Renderer& renderer, const AdaptiveSettings& adaptive)
    : renderer_(renderer),
      adaptive_(adaptive),
      roundPasses_(roundPasses(adaptive)),
      sums_(renderer.settings().width, renderer.settings().height, adaptive.enabled()) {}

std::uint32_t ProgressiveRender::passInRound() const { return renderer_.passesDone() % roundPasses_; }

std::uint32_t ProgressiveRender::samplesPerPixel() const {
    return renderer_.passesDone() * renderer_.settings().samplesPerPass;
}

void ProgressiveRender::startRound() {
    const std::uint64_t round = renderer_.passesDone() / roundPasses_;
    plan_ = planRound(sums_, adaptive_, renderer_.settings().seed, round);
    if (plan_.adaptive) renderer_.setActiveMask(plan_.active);
    planned_ = true;
}

void ProgressiveRender::finishRound() {
    const std::vector<Vec4> sums = renderer_.takeAccumulation();
    sums_.addRound(sums, roundPasses_ * renderer_.settings().samplesPerPass, plan_);
    planned_ = false;
}

StopReason ProgressiveRender::run(const RenderBudget& budget) {
    const std::uint32_t spp = renderer_.settings().samplesPerPass;
    const std::uint32_t targetPasses = (budget.samplesPerPixel + spp - 1) / spp;
    const auto start = Clock::now();
    auto lastCheckpoint = start;
    double perPass = 0;           // seconds, from the last submission
    std::uint32_t batch = 1;      // passes per submission, grown toward ~0.1 s
    std::uint32_t passesThisRun = 0;
    while (true) {
        if (renderer_.passesDone() >= targetPasses) return StopReason::Samples;
        if (budget.stop && budget.stop->load() != 0) return StopReason::Signal;
        std::uint32_t n = std::min({batch, roundPasses_ - passInRound(), targetPasses - renderer_.passesDone()});
        if (budget.seconds > 0) {
            // Never start a pass the budget has no room for (the first pass always runs, so
            // even a tiny budget gives an image).
            const double left = budget.seconds - secondsSince(start);
            if (passesThisRun > 0) {
                const double fits = perPass > 0 ? std::floor(left / perPass) : double(n);
                if (fits < 1) return StopReason::TimeLimit;
                n = std::min<std::uint32_t>(n, std::uint32_t(std::min(fits, double(n))));
            }
        }
        if (!planned_) startRound();
        const auto submitted = Clock::now();
        renderer_.renderPasses(n, true, plan_.adaptive);
        passesThisRun += n;
        if (passInRound() == 0) finishRound();
        perPass = secondsSince(submitted) / n;
        batch = perPass > 0 ? std::clamp<std::uint32_t>(std::uint32_t(0.1 / perPass), 1, 32) : 32;
        if (budget.onProgress) {
            const double bySamples = perPass * double(targetPasses - renderer_.passesDone());
            const double byTime = budget.seconds > 0 ? std::max(0.0, budget.seconds - secondsSince(start)) : bySamples;
            budget.onProgress(samplesPerPixel(), std::min(bySamples, byTime));
        }
        if (budget.checkpointSeconds > 0 && budget.onCheckpoint && secondsSince(lastCheckpoint) >= budget.checkpointSeconds &&
            renderer_.passesDone() < targetPasses) {
            budget.onCheckpoint();
            lastCheckpoint = Clock::now();
        }
    }
}

PixelAccumulator ProgressiveRender::current() {
    if (passInRound() == 0) return sums_;
    PixelAccumulator sums = sums_;
    sums.addRound(renderer_.accumulation(), passInRound() * renderer_.settings().samplesPerPass, plan_);
    return sums;
}

std::vector<float> varianceOf(const PixelAccumulator& sums) {
    std::vector<float> out(sums.pixelCount());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = float(sums.meanLuminanceVariance(i));
    return out;
}

std::vector<float> samplesTakenOf(const PixelAccumulator& sums) {
    std::vector<float> out(sums.pixelCount());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = float(sums.samplesTaken(i));
    return out;
}

double sampledFraction(const PixelAccumulator& sums) {
    if (sums.nominalSamples() == 0) return 1.0;
    double taken = 0;
    for (std::size_t i = 0; i < sums.pixelCount(); ++i) taken += sums.samplesTaken(i);
    return taken / (double(sums.nominalSamples()) * double(sums.pixelCount()));
}

RenderSnapshot ProgressiveRender::snapshot() {
    RenderSnapshot s;
    s.passesDone = renderer_.passesDone();
    s.sums = sums_.data();
    if (passInRound() != 0) s.pending = renderer_.accumulation();
    return s;
}

void ProgressiveRender::restore(const RenderSnapshot& s) {
    PN_CHECK(renderer_.passesDone() == 0 && sums_.nominalSamples() == 0);
    // The checkpoint's key matched, so these only fail for a file edited by hand.
    const std::uint32_t spp = renderer_.settings().samplesPerPass;
    const std::uint32_t inRound = s.passesDone % roundPasses_;
    if (s.sums.adaptive != adaptive_.enabled() || s.sums.width != sums_.width() || s.sums.height != sums_.height() ||
        s.sums.nominalSamples != std::uint64_t(s.passesDone - inRound) * spp || (inRound != 0) != !s.pending.empty())
        throw Error("checkpoint is inconsistent (its pass count disagrees with its sums); render afresh without --resume");
    sums_ = PixelAccumulator(s.sums);
    renderer_.setPassesDone(s.passesDone);
    planned_ = false;
    if (passInRound() != 0) {
        renderer_.loadAccumulation(s.pending);
        // The plan of the round in progress, made again from the same sums: the same decisions.
        startRound();
    }
}

}  // namespace penumbra
