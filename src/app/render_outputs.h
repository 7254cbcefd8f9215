// Writing a final render's files: the image (PNG tone mapped, EXR linear), denoised when asked,
// and the AOV layers in a multi-layer EXR (docs/RENDERING.md, "AOVs").
#pragma once

#include <filesystem>

#include "app/render_options.h"
#include "render/final_passes.h"
#include "render/progressive.h"

namespace penumbra::app {

// Where the AOV layers go: the output itself when it is an EXR, else the output with .exr.
std::filesystem::path aovPathFor(const std::filesystem::path& output);

// final = false (checkpoints, interrupts): the noisy image only, quickly. final = true: the
// denoised image when job.denoise, and the AOVs.
void writeFrameOutputs(const std::filesystem::path& output, const FrameJob& job, ProgressiveRender& render,
                       FinalFramePasses& passes, bool final);
// The same from sums made elsewhere (a render across ranks, reduced on rank 0).
void writeFrameOutputs(const std::filesystem::path& output, const FrameJob& job, const PixelAccumulator& sums,
                       FinalFramePasses& passes, bool final);

}  // namespace penumbra::app
