#version 460
// BVH heat map: BVH nodes visited and triangles tested by each pixel's primary ray. The same
// traversal code as the path tracer, compiled here with counting hooks, so trace.comp pays
// nothing for it.
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

uint heatNodes = 0u;
uint heatTriangles = 0u;
#define PN_COUNT_NODE() ++heatNodes
#define PN_COUNT_TRIANGLE() ++heatTriangles

#include "lib/scene_bindings.glsl"
#define PN_HAVE_FRAME
#include "lib/viewer_common.glsl"
#include "lib/bvh.glsl"

layout(std430, set = 0, binding = PN_BINDING_FILTER_OUT) writeonly buffer HeatOut { vec4 heat[]; };
layout(std430, set = 0, binding = PN_BINDING_SCRATCH) buffer HeatMax { HeatCounters heatMax; };

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (!insideImage(p)) return;
    traceClosest(frame.cameraPosition, viewDirection(vec2(p) + 0.5), PN_INFINITY);
    heat[pixelIndex(p)] = vec4(float(heatNodes), float(heatTriangles), 0.0, 0.0);
    atomicMax(heatMax.maxNodes, heatNodes);
    atomicMax(heatMax.maxTris, heatTriangles);
}
