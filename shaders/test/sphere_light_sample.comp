#version 460
// Test kernel: draws samples of the scene's first sphere light (lib/sphere_lights.glsl) from given
// shading points, for the chi-square and geometry tests of the sampler.
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_LINEAR_GROUP) in;

#include "lib/scene_bindings.glsl"
#include "lib/rng.glsl"
#include "lib/sampling.glsl"
#include "lib/bvh.glsl"
#include "lib/surface.glsl"
#include "lib/sphere_lights.glsl"

// One shading point per ray (origin); PassPush.mode samples are drawn from each.
layout(std430, set = 0, binding = PN_BINDING_SCRATCH) readonly buffer PointBuffer { RayDesc points[]; };
// Two vec4 per sample: (wi, pdf) and (position, radiance luminance).
layout(std430, set = 0, binding = PN_BINDING_SCRATCH2) writeonly buffer SampleBuffer { vec4 samples[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.itemCount) return;
    uint rng = rngSeed(i, 0u, frame.seed);
    SphereLightSample ls = sampleSphereLight(sphereLights[0], points[i / push.mode].origin, rngNext2(rng));
    samples[2u * i] = vec4(ls.wi, ls.pdf);
    samples[2u * i + 1u] = vec4(ls.position, luminance(ls.radiance));
}
