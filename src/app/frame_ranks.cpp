// One image across ranks. Every round of passes (render/progressive.h) is shared out among the
// ranks (distributed/work_split.h); rank 0 decides between rounds whether to go on (the sample
// count, the time limit). Without adaptive sampling each rank keeps its own double-precision
// sums and they are reduced to rank 0 once at the end; with it, every round's sums are summed on
// every rank, so that all ranks make the same plan for the next round.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "app/render_outputs.h"
#include "app/render_ranks.h"
#include "core/progress.h"
#include "distributed/agree.h"
#include "distributed/work_split.h"
#include "render/checkpoint.h"
#include "render/final_passes.h"
#include "render/progressive.h"
#include "scene/animation.h"

namespace penumbra::app {
namespace {

using Clock = std::chrono::steady_clock;
using distributed::Comm;
using distributed::PassRange;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Renders this rank's passes of a round in submissions of about a tenth of a second;
// onProgress(passes done so far).
void renderShare(Renderer& renderer, PassRange share, bool masked, const std::function<void(std::uint32_t)>& onProgress) {
    renderer.setPassesDone(share.first);  // the pass index picks the random numbers
    std::uint32_t done = 0, batch = 1;
    while (done < share.count) {
        const std::uint32_t n = std::min(batch, share.count - done);
        const auto start = Clock::now();
        renderer.renderPasses(n, true, masked);
        done += n;
        const double perPass = secondsSince(start) / n;
        batch = perPass > 0 ? std::clamp<std::uint32_t>(std::uint32_t(0.1 / perPass), 1, 32) : 32;
        onProgress(done);
    }
}

std::vector<double> toDoubles(const std::vector<Vec4>& sums) {
    std::vector<double> out;
    out.reserve(sums.size() * 4);
    for (const Vec4& v : sums) out.insert(out.end(), {v.x, v.y, v.z, v.w});
    return out;
}

std::vector<Vec4> toVec4(const std::vector<double>& values) {
    std::vector<Vec4> out(values.size() / 4);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = Vec4{float(values[4 * i]), float(values[4 * i + 1]), float(values[4 * i + 2]), float(values[4 * i + 3])};
    return out;
}

struct RanksOutcome {
    StopReason reason = StopReason::Samples;
    std::uint32_t passes = 0;  // over all ranks
    double seconds = 0;
};

// The rounds; on return `sums` holds this rank's share (all ranks' sums when adaptive).
RanksOutcome renderRounds(Comm& comm, Renderer& renderer, const FrameJob& job, PixelAccumulator& sums) {
    const RenderSettings& s = renderer.settings();
    const std::uint32_t totalPasses = (job.settings.samplesPerPixel + s.samplesPerPass - 1) / s.samplesPerPass;
    const bool adaptive = job.adaptive.enabled();
    // Rounds are where rank 0 checks the clock. Adaptive rounds are fixed (the plans depend on
    // them); otherwise the rounds only decide the order of float additions, so under a time
    // limit they shrink to a few passes per rank and the render stops close to the limit.
    const std::uint32_t perRound = !adaptive && job.timeLimit > 0 ? std::uint32_t(4 * comm.size())
                                                                   : roundPasses(job.adaptive);
    ProgressBar progress(job.progressLabel, job.settings.samplesPerPixel,
                         comm.primary() && !job.quiet ? job.progress : ProgressMode::Off, "spp");
    RanksOutcome outcome;
    const auto start = Clock::now();
    double lastRound = 0;
    for (std::uint32_t round = 0;; ++round) {
        const PassRange all = distributed::roundRange(round, perRound, totalPasses);
        // Rank 0's clock decides: a round that would end past the time limit is not started.
        bool go = all.count > 0;
        if (go && round > 0 && job.timeLimit > 0) go = secondsSince(start) + lastRound <= job.timeLimit;
        if (!comm.primaryDecides(go)) {
            outcome.reason = all.count > 0 ? StopReason::TimeLimit : StopReason::Samples;
            break;
        }
        const auto roundStart = Clock::now();
        const RoundPlan plan = adaptive ? planRound(sums, job.adaptive, s.seed, round) : RoundPlan{};
        if (plan.adaptive) renderer.setActiveMask(plan.active);
        const PassRange mine = distributed::shareOf(all, comm.rank(), comm.size());
        renderShare(renderer, mine, plan.adaptive, [&](std::uint32_t done) {
            // Rank 0 sees only its own passes; the others run at about the same pace.
            const double fraction = mine.count ? double(done) / mine.count : 1.0;
            progress.update(std::uint64_t((all.first + fraction * all.count) * s.samplesPerPass));
        });
        std::vector<Vec4> roundSums = renderer.takeAccumulation();
        if (adaptive) {
            std::vector<double> values = toDoubles(roundSums);
            comm.sumEverywhere(values);
            sums.addRound(toVec4(values), all.count * s.samplesPerPass, plan);
        } else {
            sums.addRound(roundSums, mine.count * s.samplesPerPass, plan);
        }
        outcome.passes = all.end();
        lastRound = secondsSince(roundStart);
    }
    progress.update(std::uint64_t(outcome.passes) * s.samplesPerPass, 0);
    progress.finish();
    outcome.seconds = secondsSince(start);
    return outcome;
}

// Rank 0 gets every rank's sums (without adaptive sampling, where each rank kept its own).
PixelAccumulator reduceSums(Comm& comm, const PixelAccumulator& mine, bool adaptive) {
    if (adaptive) return mine;
    AccumulatorData d = mine.data();
    comm.sumOnPrimary(d.estimate);
    comm.sumOnPrimary(d.squares);
    double nominal = double(d.nominalSamples);
    comm.sumOnPrimary(std::span<double>(&nominal, 1));
    d.nominalSamples = std::uint64_t(std::llround(nominal));
    return PixelAccumulator(std::move(d));
}

RenderStats reduceStats(Comm& comm, const RenderStats& mine) {
    std::vector<double> v = {double(mine.closestRays), double(mine.shadowRays), double(mine.invalidSamples),
                             mine.gpuMilliseconds};
    comm.sumOnPrimary(v);
    RenderStats total;
    total.closestRays = std::uint64_t(v[0]);
    total.shadowRays = std::uint64_t(v[1]);
    total.invalidSamples = std::uint64_t(v[2]);
    total.gpuMilliseconds = v[3];
    return total;
}

void printRanksSummary(const Comm& comm, const RenderPlan& plan, const RanksOutcome& r, const RenderStats& st,
                       double reduceSeconds, double sampled) {
    if (st.invalidSamples)
        std::fprintf(stderr, "penumbra: warning: %llu path samples were NaN or infinite and were dropped\n",
                     static_cast<unsigned long long>(st.invalidSamples));
    if (plan.job.quiet) return;
    const double rays = double(st.closestRays + st.shadowRays), gpuSeconds = st.gpuMilliseconds * 1e-3;
    std::string why = r.reason == StopReason::TimeLimit ? ", time limit reached" : "";
    if (plan.job.adaptive.enabled())
        why += ", adaptive: " + std::to_string(int(100 * sampled + 0.5)) + "% of the samples traced";
    std::fprintf(stderr,
                 "penumbra: %s %ux%u, %u spp%s, on %d rank%s, in %.2f s (GPU %.2f s over all ranks, reduction %.3f s), "
                 "%.1f Mrays/s per GPU second -> %s\n",
                 plan.scene.name.c_str(), plan.job.settings.width, plan.job.settings.height,
                 r.passes * plan.job.settings.samplesPerPass,
                 why.c_str(), comm.size(), comm.size() == 1 ? "" : "s", r.seconds, gpuSeconds,
                 reduceSeconds, gpuSeconds > 0 ? rays / gpuSeconds * 1e-6 : 0.0, plan.output.string().c_str());
}

std::string keyText(const RenderKey& key) { return std::to_string(key[0]) + ":" + std::to_string(key[1]); }

}  // namespace

void renderFrameOnRanks(Comm& comm, RenderPlan& plan, double sceneTime) {
    FrameJob& job = plan.job;
    applySceneTime(plan.scene, sceneTime);
    job.settings.time = textureTime(sceneTime);
    std::unique_ptr<Renderer> renderer;
    std::unique_ptr<FinalFramePasses> passes;
    distributed::agree(comm, [&] {
        renderer = std::make_unique<Renderer>(*plan.ctx, plan.scene, job.settings);
        if (comm.primary()) passes = std::make_unique<FinalFramePasses>(*plan.ctx, *renderer);
    });
    // Every rank must render the same thing: the key hashes the uploaded scene and the settings,
    // so a scene file that differs between hosts is caught here.
    const std::vector<std::string> keys = comm.allGather(keyText(renderKey(*renderer, job.adaptive)));
    distributed::agree(comm, [&] {
        if (keys[std::size_t(comm.rank())] != keys[0])
            throw Error("its scene or settings differ from rank 0's; are the scene's files the same on every host?");
    });
    PixelAccumulator total(1, 1, false);
    RanksOutcome outcome;
    RenderStats stats;
    double reduceSeconds = 0;
    distributed::failOnError(comm, [&] {
        PixelAccumulator sums(job.settings.width, job.settings.height, job.adaptive.enabled());
        outcome = renderRounds(comm, *renderer, job, sums);
        comm.barrier();  // the reduction's own time, not the wait for the slowest rank
        const auto start = Clock::now();
        total = reduceSums(comm, sums, job.adaptive.enabled());
        reduceSeconds = secondsSince(start);
        stats = reduceStats(comm, renderer->stats());
    });
    // Rank 0 writes; a failure to write is every rank's verdict (no rank is left waiting).
    distributed::agree(comm, [&] {
        if (!comm.primary()) return;
        writeFrameOutputs(plan.output, job, total, *passes, true);
        printRanksSummary(comm, plan, outcome, stats, reduceSeconds, sampledFraction(total));
    });
}

}  // namespace penumbra::app
