// The wavefront trace pass's shapes (render/passes/wavefront_pass.h, shaders/wave_*.comp).
// Valid GLSL and C++ (see types.h); each struct's size and offsets are checked beside it.
#ifndef PENUMBRA_SHADER_WAVEFRONT_H
#define PENUMBRA_SHADER_WAVEFRONT_H

#include "shared/prelude.h"

#ifdef __cplusplus
namespace penumbra::shader {
#endif

#define PN_WAVE_GROUP 128       // threads per workgroup of the wavefront kernels (one path slot each)
#define PN_WAVE_PATH_VEC4S 7    // vec4 fields of a path's state in the wavefront buffers (wave_state.glsl)
#define PN_WAVE_SHADOW_VEC4S 3  // vec4 fields of a queued shadow ray

// PassPush.mode bit the wavefront sets for itself: bounce 0's extend and shade make each slot's
// camera path where they need it (startPath) instead of reading what a start step stored, and take
// slot i as queue entry i (every slot is live: not for masked passes, nor for a tail from the start).
#define PN_WAVE_CAMERA_IN_PLACE 8u
#define PN_WAVE_MAKES_CAMERA_PATHS(mode, bounce) (((mode) & PN_WAVE_CAMERA_IN_PLACE) != 0u && (bounce) == 0u)

// The wavefront pass's queue counts and the indirect dispatch sizes computed from them
// (wave_args.comp), 64 bytes.
PN_STRUCT(WaveControl) {
    uint rayCount[2];    // live paths in each queue (read at bounce b: rayCount[b & 1])
    uint shadowCount;    // shadow rays queued by the last shade pass
    uint shadowLive;     // the shadow count the pending shadow pass reads (shadowCount is refilled meanwhile)
    uint extendGroups[4];  // VkDispatchIndirectCommand (x, y, z) + pad, for extend and shade
    uint shadowGroups[4];  // VkDispatchIndirectCommand, for the shadow pass
    uint tailGroups[4];    // VkDispatchIndirectCommand, for the tail (the live paths to their end)
};
#ifdef __cplusplus
static_assert(sizeof(WaveControl) == 64 && offsetof(WaveControl, shadowLive) == 12 &&
              offsetof(WaveControl, extendGroups) == 16 && offsetof(WaveControl, shadowGroups) == 32 &&
              offsetof(WaveControl, tailGroups) == 48);
#endif

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
