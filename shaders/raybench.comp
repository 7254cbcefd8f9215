#version 460
// Ray-throughput benchmark, one ray kind per dispatch so each is timed alone (lib/raybench_rays.glsl).
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

#include "lib/raybench_rays.glsl"

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (pixel.x >= frame.width || pixel.y >= frame.height) return;
    benchRay(pixel, pixel.y * frame.width + pixel.x);
}
