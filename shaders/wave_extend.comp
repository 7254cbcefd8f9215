#version 460
// Wavefront trace, step 2: the closest hit of every live path's ray. Nothing but the traversal
// lives here, so the kernel keeps few registers and many rays in flight.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = PN_WAVE_GROUP) in;

#include "lib/scene_bindings.glsl"
#include "lib/trace_outputs.glsl"
#include "lib/path.glsl"
#include "lib/wave_state.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    bool live = i < liveRays();
    uint slot = live ? liveSlot(i) : 0u;
    // A camera ray shared by a pixel's samples is traced for the first one (hitSlot).
    live = live && hitSlot(slot) == slot;
    if (live) {
        vec3 origin, direction;
        if (cameraInPlace()) {
            Path camera = cameraPath(slotPixel(slot));
            origin = camera.origin;
            direction = camera.direction;
        } else {
            origin = unpackVec(pathField(0u, slot));
            direction = unpackVec(pathField(1u, slot));
        }
        storeHit(slot, traceClosest(origin, direction, PN_INFINITY));
    }
    countRays(live ? 1u : 0u, 0u);
}
