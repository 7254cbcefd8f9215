#version 460
// Wavefront trace, last step: each sampled pixel of the tile sums its paths' radiance, sample by
// sample in the megakernel's order, into the accumulation buffer.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = PN_WAVE_GROUP) in;

#include "lib/scene_bindings.glsl"
#include "lib/trace_outputs.glsl"
#include "lib/path.glsl"
#include "lib/wave_state.glsl"

void main() {
    uint local = gl_GlobalInvocationID.x;
    if (local >= push.tileWidth * push.tileHeight) return;
    uvec2 pixel = uvec2(push.tileX + local % push.tileWidth, push.tileY + local / push.tileWidth);
    if (!pixelSampled(pixel)) return;
    vec3 sum = vec3(0.0);
    float sumSquares = 0.0;
    for (uint k = 0u; k < frame.samplesPerPass; ++k) addSample(pathResult(slotOf(pixel, k)), sum, sumSquares);
    storePixelSums(pixel.y * frame.width + pixel.x, vec4(sum, sumSquares));
}
