#version 460
// The path tracer: one thread per pixel, samplesPerPass paths each (tracePixel), added into the
// accumulation buffer (rgb = sum of radiance, a = sum of squared luminance, for variance estimates).
// Unidirectional path tracing with next event estimation (one light per vertex, chosen among
// emissive triangles and spheres, punctual lights, sun disks and the environment by
// lib/light_sampler.glsl), combined with BSDF sampling per frame.misMode (lib/mis.glsl); every
// surface is shaded by the one principled BSDF (lib/bsdf/bsdf.glsl) in its local shading frame.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

#include "lib/scene_bindings.glsl"
#include "lib/trace_outputs.glsl"
#include "lib/path.glsl"

uint closestRays = 0u;
uint shadowRays = 0u;

// The pixel's samplesPerPass paths, each followed to its end before the next starts.
void tracePixel(uvec2 pixel, uint pixelIndex) {
    uint firstSample = push.passIndex * frame.samplesPerPass;
    vec3 sum = vec3(0.0);
    float sumSquares = 0.0;
    for (uint k = 0u; k < frame.samplesPerPass; ++k) {
        Path path = startPath(pixel, pixelIndex, firstSample + k, (push.mode & PN_TRACE_SHARED_CAMERA) != 0u);
        finishPath(path, pixelIndex, closestRays, shadowRays);
        addSample(path.result, sum, sumSquares);
    }
    storePixelSums(pixelIndex, vec4(sum, sumSquares));
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy + uvec2(push.tileX, push.tileY);
    // Whole tiles share a mask entry, so the threads of a workgroup mostly agree and skip together.
    if (pixelSampled(pixel)) tracePixel(pixel, pixel.y * frame.width + pixel.x);
    countRays(closestRays, shadowRays);
}
