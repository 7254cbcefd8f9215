#version 460
// Test kernel: the environment and sun-disk samplers (lib/environment.glsl, lib/sun.glsl) as
// the tracer uses them, one item per thread, for chi-square and integral tests on the CPU.
//   mode 0: sample the environment from a surface of normal kTestNormal;
//           out[2i] = (direction, pdf it reported), out[2i+1] = (environmentPdf, its radiance)
//   mode 1: look up given directions in[i].xyz; out[i] = (environmentRadiance, environmentPdf)
//   mode 2: sample the disk of punctual light 0; out[i] = (direction, its cone pdf)
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_LINEAR_GROUP) in;

#include "lib/scene_bindings.glsl"
#include "lib/rng.glsl"
#include "lib/sampling.glsl"
#include "lib/bvh.glsl"
#include "lib/lights.glsl"
#include "lib/environment.glsl"
#include "lib/sun.glsl"

layout(std430, set = 0, binding = PN_BINDING_SCRATCH) readonly buffer InBuffer { vec4 directions[]; };
layout(std430, set = 0, binding = PN_BINDING_SCRATCH2) writeonly buffer OutBuffer { vec4 results[]; };

const vec3 kTestNormal = vec3(0.3, 0.8, -0.52);  // unit to 1e-3; normalized below

void main() {
    vec3 n = normalize(kTestNormal);
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.itemCount) return;
    uint rng = rngSeed(i, push.passIndex, frame.seed);
    if (push.mode == 0u) {
        EnvSample es = sampleEnvironment(n, rng);
        results[2u * i] = vec4(es.direction, es.pdf);
        results[2u * i + 1u] = vec4(environmentPdf(es.direction, n), es.radiance);
    } else if (push.mode == 1u) {
        vec3 d = directions[i].xyz;
        results[i] = vec4(environmentRadiance(d), environmentPdf(d, n));
    } else {
        PunctualLight l = punctualLights[0];
        results[i] = vec4(sampleSunDisk(l, rngNext2(rng)), sunConePdf(l));
    }
}
