// penumbra render across the ranks of an MPI job (docs/DISTRIBUTED.md). Every rank loads the
// scene and opens its own device. One image: the passes are shared out (distributed/work_split.h)
// and the sums reduced in double precision to rank 0, which writes the file. A sequence: rank 0
// hands frames to free ranks, and each writes the frames it renders.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "app/render_options.h"
#include "app/render_sequence.h"
#include "app/render_video.h"
#include "distributed/comm.h"
#include "gpu/context.h"
#include "scene/scene.h"

namespace penumbra::app {

// What a render needs once the flags are checked: the same on every rank but the device.
struct RenderPlan {
    Scene scene;
    FrameJob job;
    bool sequence = false;
    FrameRange frames;
    std::filesystem::path output;  // the image, or the sequence's pattern
    std::unique_ptr<gpu::Context> ctx;
    SequenceOptions sequenceOptions;
    // A walk (--walk) or a video output: frames into one output (render_video.h).
    std::optional<VideoJob> video;
};
using PrepareRender = std::function<RenderPlan(const std::string& device, bool writesOutput)>;

// The job this process is a rank of: started by mpirun, or asked for with --mpi; nullptr when
// neither. Without MPI support built in, rank 0 throws the UsageError that says so and the other
// ranks throw Reported.
std::unique_ptr<distributed::Comm> startRanks(bool asked);

// The device a rank opens: `selector` (--device, or PENUMBRA_DEVICE) when given; else the GPU
// numbered by the rank's place on its host among the host's GPUs (wrapping around). A host with
// no GPU is a UsageError: its CPU (lavapipe) renders only when asked for with --device llvmpipe.
std::string deviceForRank(const distributed::Comm& comm, const std::string& selector);

void renderOnRanks(distributed::Comm& comm, const RenderArgs& args, const PrepareRender& prepare);

// The two halves (frame_ranks.cpp, sequence_ranks.cpp).
void renderFrameOnRanks(distributed::Comm& comm, RenderPlan& plan, double sceneTime);
void renderSequenceOnRanks(distributed::Comm& comm, RenderPlan& plan);

}  // namespace penumbra::app
