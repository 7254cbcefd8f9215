#version 460
// The ray benchmark's rays (lib/raybench_rays.glsl) with the walk's counting hooks on: per pixel,
// the nodes its ray visited and the primitives it tested, for render/ray_bench.cpp's work per ray
// and the share of a warp's lanes busy while its longest walk runs. Untimed; raybench.comp,
// which the figures time, carries none of this.
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

uint countedNodes = 0u;
uint countedPrimitives = 0u;
#define PN_COUNT_NODE() ++countedNodes
#define PN_COUNT_TRIANGLE() ++countedPrimitives

#include "lib/raybench_rays.glsl"

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (pixel.x >= frame.width || pixel.y >= frame.height) return;
    uint index = pixel.y * frame.width + pixel.x;
    benchRay(pixel, index);
    // 0: no ray (a missed primary's point, or no light to sample); a traced ray visits the root
    // or, under brute force, tests a primitive.
    results[index] = uintBitsToFloat(min(countedNodes, PN_RAY_WORK_MAX) | (min(countedPrimitives, PN_RAY_WORK_MAX) << PN_RAY_WORK_BITS));
}
