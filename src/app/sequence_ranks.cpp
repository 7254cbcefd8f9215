// A sequence across ranks: rank 0 lists the frames to render (with --resume, only the unfinished
// ones, as renderSequence decides), hands them out one at a time to whichever rank asks, and
// prints a line for each finished frame. Each rank writes the frames it renders, atomically.
#include <cstdio>

#include "app/render_ranks.h"
#include "distributed/agree.h"
#include "distributed/frame_queue.h"

namespace penumbra::app {

void renderSequenceOnRanks(distributed::Comm& comm, RenderPlan& plan) {
    const SequenceOptions& o = plan.sequenceOptions;
    std::vector<std::int64_t> frames;
    std::int64_t skipped = 0;
    if (comm.primary())
        for (std::int64_t frame = o.frames.first; frame <= o.frames.last; ++frame) {
            if (o.resume && frameFinished(plan.output, frame)) ++skipped;
            else frames.push_back(frame);
        }
    // Ranks draw no bars of their own; rank 0 reports every finished frame.
    FrameJob job = plan.job;
    job.quiet = true;
    job.progress = ProgressMode::Off;
    const bool report = !plan.job.quiet && comm.primary();
    std::size_t finished = 0;
    const auto onDone = [&](const distributed::FrameDone& d) {
        ++finished;
        if (!report) return;
        std::fprintf(stderr, "penumbra: frame %lld (%zu of %zu) at t = %.4g s on rank %d (%s): %u spp in %.2f s -> %s\n",
                     static_cast<long long>(d.frame), finished, frames.size(), double(d.frame) / o.fps + o.offsetSeconds,
                     d.rank, comm.hostOf(d.rank).c_str(), d.samplesPerPixel, d.seconds,
                     framePath(plan.output, d.frame).string().c_str());
        std::fflush(stderr);
    };
    distributed::failOnError(comm, [&] {
        distributed::FrameQueue queue(comm, frames, onDone);
        if (!queue.renders()) {
            queue.serve();
            return;
        }
        std::optional<distributed::FrameDone> done;
        while (const std::optional<std::int64_t> frame = queue.next(done)) {
            const FrameOutcome r = renderSequenceFrame(*plan.ctx, plan.scene, job, plan.output, o, *frame);
            done = distributed::FrameDone{*frame, comm.rank(), r.samplesPerPixel, r.seconds};
        }
        queue.finish();
    });
    distributed::agree(comm, [&] {
        if (report && skipped)
            std::fprintf(stderr, "penumbra: %lld finished frames were skipped (--resume)\n", static_cast<long long>(skipped));
    });
}

}  // namespace penumbra::app
