#include "app/render_ranks.h"

#include <cstdlib>

#include "core/error.h"
#include "distributed/agree.h"
#include "distributed/launch.h"

namespace penumbra::app {
namespace {

// What must agree across ranks, said the way a user typed it.
std::string fingerprintOf(const RenderPlan& p) {
    const RenderSettings& s = p.job.settings;
    std::string f = "scene " + p.scene.name + ", output " + p.output.string() + ", " + std::to_string(s.width) + "x" +
                    std::to_string(s.height) + ", " + std::to_string(s.samplesPerPixel) + " spp, seed " +
                    std::to_string(s.seed) + ", " + std::to_string(s.maxBounces) + " bounces";
    if (p.sequence) f += ", frames " + std::to_string(p.frames.first) + ".." + std::to_string(p.frames.last);
    return f;
}

}  // namespace

std::unique_ptr<distributed::Comm> startRanks(bool asked) {
    const distributed::Launch launch = distributed::launchFromEnvironment();
    if (!asked && !launch.underMpirun) return nullptr;
    if (!distributed::mpiBuilt() && launch.rank != 0) throw distributed::Reported(2);  // rank 0 says why
    return distributed::Comm::start();
}

std::string deviceForRank(const distributed::Comm& comm, const std::string& selector) {
    if (!selector.empty()) return selector;
    if (const char* env = std::getenv("PENUMBRA_DEVICE"); env && *env) return env;
    std::string error;
    std::vector<std::uint32_t> gpus;
    for (const gpu::DeviceInfo& d : gpu::Context::listDevices(&error))
        if (d.suitable && d.type != VK_PHYSICAL_DEVICE_TYPE_CPU) gpus.push_back(d.index);
    if (gpus.empty())
        throw UsageError("no GPU here" + (error.empty() ? std::string() : " (" + error + ")") +
                         "; to render on this host's CPU (lavapipe), pass --device llvmpipe or set PENUMBRA_DEVICE=llvmpipe");
    return std::to_string(gpus[std::size_t(comm.localRank()) % gpus.size()]);
}

void renderOnRanks(distributed::Comm& comm, const RenderArgs& args, const PrepareRender& prepare) {
    RenderPlan plan;
    distributed::agree(comm, [&] {
        if (args.frames.empty() && (!args.resume.empty() || args.checkpointSeconds > 0))
            throw UsageError("--checkpoint and --resume of a single image do not work across MPI ranks yet; "
                             "render it without mpirun, or split a long render into a sequence");
        const std::string device = deviceForRank(comm, args.device);
        // One image: only rank 0 writes. A sequence: every rank writes the frames it renders.
        plan = prepare(device, comm.primary() || !args.frames.empty());
        // mpirun's SIGTERM after a failure must leave nothing half done; each rank shows no bar.
        plan.job.stopOnSignals = false;
    });
    // Ranks started with different commands (mpirun's MPMD form, or a script's mistake) would
    // render different things into one output.
    const std::vector<std::string> fingerprints = comm.allGather(fingerprintOf(plan));
    distributed::agree(comm, [&] {
        if (fingerprints[std::size_t(comm.rank())] != fingerprints[0])
            throw UsageError("its options differ from rank 0's (" + fingerprints[std::size_t(comm.rank())] + " against " +
                             fingerprints[0] + "); start every rank with the same command");
    });
    if (plan.sequence) renderSequenceOnRanks(comm, plan);
    else renderFrameOnRanks(comm, plan, args.time);
}

}  // namespace penumbra::app
