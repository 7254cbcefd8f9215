#version 460
// Wavefront trace, between bounces: the indirect dispatch sizes of this bounce's extend and shade
// passes (its live paths) and of the last bounce's shadow pass (its queued shadow rays), and the
// counters the next shade pass appends to, emptied. One invocation.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = 1) in;

layout(std430, set = 0, binding = PN_BINDING_WAVE_CONTROL) buffer WaveControlBuffer { WaveControl control; };
layout(push_constant) uniform PushBlock { PassPush push; };

uint groupsFor(uint items) { return (items + PN_WAVE_GROUP - 1u) / PN_WAVE_GROUP; }

void main() {
    control.extendGroups = uint[4](groupsFor(control.rayCount[push.waveBounce & 1u]), 1u, 1u, 0u);
    control.rayCount[(push.waveBounce + 1u) & 1u] = 0u;
    control.shadowLive = control.shadowCount;
    control.shadowGroups = uint[4](groupsFor(control.shadowCount), 1u, 1u, 0u);
    control.shadowCount = 0u;
}
