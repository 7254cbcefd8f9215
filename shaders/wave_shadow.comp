#version 460
// Wavefront trace, step 4: the queued shadow rays; an unblocked one adds its light to its path.
// Each path queues at most one per bounce, so no two invocations touch the same path. In a round
// the tail takes, the rays of the paths that go on are the tail's (wave_tail.comp), which runs
// beside this pass.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = PN_WAVE_GROUP) in;

#include "lib/scene_bindings.glsl"
#include "lib/trace_outputs.glsl"
#include "lib/path.glsl"
#include "lib/wave_state.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    bool tailRound = control.tailGroups[0] != 0u;
    bool traced = i < control.shadowLive && !(tailRound && shadowPathGoesOn(i));
    if (traced) {
        uint slot;
        PendingShadow s = loadShadow(i, slot);
        if (!traceOccluded(s.ray.origin, s.ray.direction, s.ray.tMax)) addToPathResult(slot, s.light);
    }
    countRays(0u, traced ? 1u : 0u);
}
