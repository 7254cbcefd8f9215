#version 460
// Wavefront trace, the tail (wave_args.comp decides when): each of the few live paths left is
// followed to its end in one invocation, as the megakernel would (lib/path.glsl finishPath), so
// the last bounces cost one dispatch instead of a round of extend, shade and shadow each. It runs
// beside that round's shadow pass: each path first traces the shadow ray its last vertex queued
// (the shadow pass leaves those to it), then goes on, adding light in the megakernel's order.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = PN_WAVE_GROUP) in;

#include "lib/scene_bindings.glsl"
#include "lib/trace_outputs.glsl"
#include "lib/path.glsl"
#include "lib/wave_state.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    uint closestRays = 0u, shadowRays = 0u;
    if (i < liveRays()) {
        uint slot = queueIn(i);
        uvec3 p = slotPixel(slot);
        Path path = loadPathToFinish(slot, p);
        if (tracePendingShadow(slot, path.result)) ++shadowRays;
        finishPath(path, p.y * frame.width + p.x, closestRays, shadowRays);
        setPathResult(slot, path.result);
    }
    countRays(closestRays, shadowRays);
}
