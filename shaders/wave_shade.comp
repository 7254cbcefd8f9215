#version 460
// Wavefront trace, step 3: each live path meets its hit (lib/path.glsl extendPath: emission, one
// light sample, one BSDF sample, roulette); the paths that go on are queued for the next bounce
// and the light samples' shadow rays for the shadow pass.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = PN_WAVE_GROUP) in;

#include "lib/scene_bindings.glsl"
#include "lib/trace_outputs.glsl"
#include "lib/path.glsl"
#include "lib/wave_state.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    uint slot = 0u;
    bool alive = false;
    PendingShadow shadow = noShadow();
    if (i < liveRays()) {
        slot = liveSlot(i);
        Hit hit = loadHit(hitSlot(slot));
        uvec3 p = slotPixel(slot);
        bool inPlace = cameraInPlace();
        Path path = inPlace ? cameraPath(p) : loadPathForShading(slot, p, hit);
        alive = extendPath(path, hit, p.y * frame.width + p.x, shadow);
        // The path's own light (emission, an escape) is rare: read-modify-write only then. A path
        // made in place has no stored result yet: it starts it.
        if (inPlace) setPathResult(slot, path.result);
        else if (path.result != vec3(0.0)) addToPathResult(slot, path.result);
        if (alive) storePath(slot, path);
    }
    uint next = appendIndex(alive, (push.waveBounce + 1u) & 1u);
    if (alive) queueNext(next, slot);
    uint queued = appendIndex(shadow.pending, 2u);
    if (shadow.pending) storeShadow(queued, slot, shadow, alive);
    if (alive) setPendingShadow(slot, shadow.pending ? queued + 1u : 0u);
}
