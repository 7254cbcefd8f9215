#version 460
// Wavefront trace, between bounces: the indirect dispatch sizes of this bounce's extend and shade
// passes (its live paths) and of the last bounce's shadow pass (its queued shadow rays), and the
// counters the next shade pass appends to, emptied. One invocation. When few paths are left
// (push.waveTailPaths or fewer), they go to the tail kernel instead, which follows each to its
// end: a round of extend, shade and shadow for a handful of paths costs its barriers and the
// latency of its slowest ray, whatever the count.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = 1) in;

layout(std430, set = 0, binding = PN_BINDING_WAVE_CONTROL) buffer WaveControlBuffer { WaveControl control; };
layout(push_constant) uniform PushBlock { PassPush push; };

uint groupsFor(uint items) { return (items + PN_WAVE_GROUP - 1u) / PN_WAVE_GROUP; }

void main() {
    // PN_WAVE_CAMERA_IN_PLACE: bounce 0's paths are every slot, never queued (wave_state.glsl).
    uint live = PN_WAVE_MAKES_CAMERA_PATHS(push.mode, push.waveBounce) ? push.itemCount : control.rayCount[push.waveBounce & 1u];
    bool tail = live <= push.waveTailPaths;
    control.extendGroups = uint[4](tail ? 0u : groupsFor(live), 1u, 1u, 0u);
    control.tailGroups = uint[4](tail ? groupsFor(live) : 0u, 1u, 1u, 0u);
    control.rayCount[(push.waveBounce + 1u) & 1u] = 0u;
    control.shadowLive = control.shadowCount;
    control.shadowGroups = uint[4](groupsFor(control.shadowCount), 1u, 1u, 0u);
    control.shadowCount = 0u;
}
