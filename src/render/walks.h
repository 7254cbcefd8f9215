// The ray walks a render can use (--accel), one table: each walk's name on the command line, its
// number in the shaders (FrameUniforms.accel and the kernels' walk specialization constant,
// shared/types.h and shared/accel_layouts.h) and what it is. A walk is chosen apart from the
// kernel's capability bits (render/kernel_features.h), as issue 38 asks.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "render/scene_arrays.h"
#include "render/settings.h"

namespace penumbra {

struct WalkInfo {
    Accel accel;
    const char* name;       // --accel's value
    std::uint32_t shaderId; // PN_ACCEL_*
    const char* summary;    // one line for --help and docs
};

// In the order --help lists them.
std::span<const WalkInfo> walks();
const WalkInfo& walkInfo(Accel accel);
// "bvh, wide, stackless, objects or brute", for help texts and errors.
std::string walkNameList();
// --accel's help: every walk with its summary.
std::string accelHelp();

// Builds what `accel` walks beyond the binary tree (the stackless walk's threaded nodes, the
// objects' boxes) into arrays built by buildSceneArrays, and sets arrays.walk: the walk the
// kernels are specialised for (wide without a wide tree, as in two-level scenes, walks the
// binary one). Throws Error when the tree does not fit the walk's records.
void buildWalkRecords(SceneArrays& arrays, Accel accel);
// After a rebuild of the top level in place (instances moved, render/instance_arrays.h): the
// records buildWalkRecords made of it, made again. Their sizes stay the same, so the GPU's copies
// can be overwritten (render/instance_upload.h).
void refreshTopLevelRecords(SceneArrays& arrays);

}  // namespace penumbra
