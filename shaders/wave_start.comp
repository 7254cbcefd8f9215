#version 460
// Wavefront trace, step 1 (render/passes/wavefront_pass.h): a path per slot of the tile, its
// camera ray generated as the megakernel (trace.comp) would, its slot queued for bounce 0.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = PN_WAVE_GROUP) in;

#include "lib/scene_bindings.glsl"
#include "lib/trace_outputs.glsl"
#include "lib/path.glsl"
#include "lib/wave_state.glsl"

void main() {
    uint slot = gl_GlobalInvocationID.x;
    bool started = false;
    if (slot < push.itemCount) {
        uvec3 p = slotPixel(slot);
        if (pixelSampled(p.xy)) {
            storePath(slot, cameraPath(p));
            startPathResult(slot);
            started = true;
        }
    }
    uint index = appendIndex(started, 0u);
    if (started) waveQueues[index] = slot;
}
