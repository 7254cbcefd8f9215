// What every GPU BVH build kernel (shaders/lbvh_*.comp) shares: its buffers, its push constants
// and the float order trick. Every kernel's pipeline binds all of them (render/gpu_bvh_build.cpp).
#include "shared/geometry.h"
#include "shared/lbvh.h"

layout(local_size_x = PN_LBVH_GROUP) in;

layout(std430, set = 0, binding = PN_LBVH_BIND_BOXES) readonly buffer Boxes { BvhNode boxes[]; };
layout(std430, set = 0, binding = PN_LBVH_BIND_STATE) coherent buffer State { LbvhState state; };
layout(std430, set = 0, binding = PN_LBVH_BIND_KEYS_A) buffer KeysA { uint keysA[]; };
layout(std430, set = 0, binding = PN_LBVH_BIND_VALUES_A) buffer ValuesA { uint valuesA[]; };
layout(std430, set = 0, binding = PN_LBVH_BIND_KEYS_B) buffer KeysB { uint keysB[]; };
layout(std430, set = 0, binding = PN_LBVH_BIND_VALUES_B) buffer ValuesB { uint valuesB[]; };
layout(std430, set = 0, binding = PN_LBVH_BIND_COUNTS) buffer Counts { uint counts[]; };
layout(std430, set = 0, binding = PN_LBVH_BIND_NODES) buffer Nodes { LbvhNode nodes[]; };
layout(std430, set = 0, binding = PN_LBVH_BIND_OUTPUT) writeonly buffer Output { BvhNode outNodes[]; };
layout(std430, set = 0, binding = PN_LBVH_BIND_DONE) buffer Done { uint donePass[]; };
layout(push_constant) uniform PushBlock { LbvhPush push; };

// A float's bits mapped to a uint with the same order (negatives flipped whole, positives' sign
// bit set), so atomicMin/atomicMax on uints reduce floats.
uint pnOrderedFromFloat(float f) {
    uint u = floatBitsToUint(f);
    return (u & 0x80000000u) != 0u ? ~u : (u | 0x80000000u);
}
float pnFloatFromOrdered(uint u) {
    return uintBitsToFloat((u & 0x80000000u) != 0u ? (u & 0x7fffffffu) : ~u);
}

float pnHalfArea(vec3 lo, vec3 hi) {
    vec3 d = max(hi - lo, vec3(0.0));
    return d.x * d.y + d.y * d.z + d.z * d.x;
}
