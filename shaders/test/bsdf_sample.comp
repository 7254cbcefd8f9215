#version 460
// Test kernel: the real BSDF (lib/bsdf/bsdf.glsl) with the material materials[0] of the bound
// scene, packed as the path tracer packs it (lib/material.glsl, at uv 0). Modes:
//   PN_BSDF_TEST_SAMPLE: item i draws one sample for queries[0].wo (random numbers seeded by
//                        frame.seed and i): wi, the mixture pdf, weight = f cos / pdf, isDelta.
//   PN_BSDF_TEST_EVAL:   item i evaluates f and the pdf of (queries[i].wo, queries[i].wi).
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_LINEAR_GROUP) in;

#include "lib/scene_bindings.glsl"
#include "lib/rng.glsl"
#include "lib/material.glsl"

layout(std430, set = 0, binding = PN_BINDING_SCRATCH) readonly buffer QueryBuffer { BsdfTestQuery queries[]; };
layout(std430, set = 0, binding = PN_BINDING_SCRATCH2) writeonly buffer ResultBuffer { BsdfTestResult results[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.itemCount) return;
    BsdfTestQuery q = queries[push.mode == PN_BSDF_TEST_SAMPLE ? 0u : i];
    BsdfParams p = materialBsdf(materials[0], vec2(0.0), q.entering != 0u);
    if (push.mode == PN_BSDF_TEST_SAMPLE) {
        uint rng = rngSeed(i, push.passIndex, frame.seed);
        vec3 u = vec3(rngNext2(rng), rngNext(rng));
        BsdfSample s = bsdfSample(p, q.wo, u);
        results[i] = BsdfTestResult(s.wi, s.pdf, s.weight, s.isDelta ? 1u : 0u);
    } else {
        results[i] = BsdfTestResult(vec3(0.0), bsdfPdf(p, q.wo, q.wi), bsdfEval(p, q.wo, q.wi), 0u);
    }
}
