// Every struct and constant that crosses between host and shader, one header per audience; this
// file only includes them all, for the files that use several. Each header is valid GLSL and valid
// C++ and is the only place its layouts are written (see ../../../shared/design.md).
#ifndef PENUMBRA_SHADER_TYPES_H
#define PENUMBRA_SHADER_TYPES_H

#include "shared/bindings.h"      // descriptor set 0's binding numbers, workgroup sizes
#include "shared/features.h"      // the tracing kernels' feature bits
#include "shared/geometry.h"      // BVH nodes, instances, triangles
#include "shared/materials.h"     // materials, textures
#include "shared/lights.h"        // light refs, light tree and grid, punctual and sphere lights, env table
#include "shared/frame.h"         // FrameUniforms, PassPush, the trace pass's modes
#include "shared/wavefront.h"     // the wavefront pass's shapes and WaveControl
#include "shared/viewer.h"        // the viewer's passes: G-buffer, history, uniforms, debug views
#include "shared/counters.h"      // RayCounters
#include "shared/test_kernels.h"  // rays, hits and BSDF records of the test and benchmark kernels

#endif
