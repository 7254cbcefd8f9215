#include "app/render_frame.h"

#include <chrono>
#include <cstdio>
#include <system_error>

#include "app/render_outputs.h"
#include "core/interrupt.h"
#include "core/progress.h"
#include "gpu/check.h"
#include "render/checkpoint.h"
#include "render/final_passes.h"

namespace penumbra::app {
namespace {

using Clock = std::chrono::steady_clock;

// Writes the image so far and the state beside it (checkpoints and interrupts).
void writeCheckpointFiles(const std::filesystem::path& output, const FrameJob& job, ProgressiveRender& render,
                          FinalFramePasses& passes, const RenderKey& key) {
    writeFrameOutputs(output, job, render, passes, false);
    writeCheckpoint(statePathFor(output), render.snapshot(), key);
}

[[noreturn]] void throwInterrupted(int signal, const std::filesystem::path& output, std::uint32_t spp,
                                   const FrameJob& job) {
    const std::string state = statePathFor(output).string();
    const std::string resume = job.resumeArgument.empty() ? state : job.resumeArgument;
    throw Interrupted(std::string("interrupted by ") + StopOnSignals::signalName(signal) + " at " + std::to_string(spp) +
                          " of " + std::to_string(job.settings.samplesPerPixel) + " spp; the image so far is in " +
                          output.string() + " and the state in " + state + "; run the same command with --resume '" +
                          resume + "' to finish",
                      128 + signal);
}

// A lost device or exhausted memory ends the render like any Error; when a checkpoint exists
// (written atomically, so a failure mid-write leaves the one before), the line says how to go on.
[[noreturn]] void throwVulkanFailure(const gpu::VulkanError& e, const std::filesystem::path& output,
                                     const FrameJob& job) {
    std::error_code ec;
    const std::filesystem::path state = statePathFor(output);
    if (!std::filesystem::exists(state, ec)) throw;
    const std::string resume = job.resumeArgument.empty() ? state.string() : job.resumeArgument;
    throw Error(std::string(e.what()) + "; the last checkpoint is intact: run the same command with --resume '" +
                resume + "' to continue from it");
}

void removeState(const std::filesystem::path& output) {
    std::error_code ec;
    std::filesystem::remove(statePathFor(output), ec);  // a finished frame needs no state
}

}  // namespace

FrameOutcome renderFrame(const gpu::Context& ctx, const Scene& scene, const FrameJob& job,
                         const std::filesystem::path& output, const std::optional<std::filesystem::path>& resumeFrom) {
    Renderer renderer(ctx, scene, job.settings);
    ProgressiveRender render(renderer, job.adaptive);
    FinalFramePasses passes(ctx, renderer);
    const RenderKey key = renderKey(renderer, job.adaptive);
    if (resumeFrom) {
        render.restore(readCheckpoint(*resumeFrom, key, job.settings.width, job.settings.height));
        if (!job.quiet)
            std::fprintf(stderr, "penumbra: resuming %s at %u spp\n", resumeFrom->string().c_str(), render.samplesPerPixel());
    }

    std::optional<StopOnSignals> signals;
    if (job.stopOnSignals) signals.emplace();
    ProgressBar progress(job.progressLabel, job.settings.samplesPerPixel, job.quiet ? ProgressMode::Off : job.progress,
                         "spp");
    RenderBudget budget;
    budget.samplesPerPixel = job.settings.samplesPerPixel;
    budget.seconds = job.timeLimit;
    budget.stop = &StopOnSignals::signal();
    budget.checkpointSeconds = job.checkpointSeconds;
    budget.onCheckpoint = [&] { writeCheckpointFiles(output, job, render, passes, key); };
    budget.onProgress = [&](std::uint32_t spp, double secondsLeft) { progress.update(spp, secondsLeft); };
    const auto start = Clock::now();
    FrameOutcome outcome;
    try {
        outcome.reason = render.run(budget);
    } catch (const gpu::VulkanError& e) {
        throwVulkanFailure(e, output, job);
    }
    outcome.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    outcome.samplesPerPixel = render.samplesPerPixel();
    progress.update(outcome.samplesPerPixel, 0);
    progress.finish();

    if (outcome.reason == StopReason::Signal) {
        writeCheckpointFiles(output, job, render, passes, key);
        throwInterrupted(StopOnSignals::signal().load(), output, outcome.samplesPerPixel, job);
    }
    writeFrameOutputs(output, job, render, passes, true);
    removeState(output);
    outcome.sampledFraction = sampledFraction(render.current());
    outcome.stats = renderer.stats();
    return outcome;
}

}  // namespace penumbra::app
