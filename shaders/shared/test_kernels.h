// The records of the test and benchmark kernels (shaders/test/*.comp, raybench*.comp): rays in,
// hits and BSDF samples out, and their modes.
// Valid GLSL and C++ (see types.h); each struct's size and offsets are checked beside it.
#ifndef PENUMBRA_SHADER_TEST_KERNELS_H
#define PENUMBRA_SHADER_TEST_KERNELS_H

#include "shared/prelude.h"

#ifdef __cplusplus
namespace penumbra::shader {
#endif

// ---- ray benchmark modes (raybench.comp) ----
#define PN_RAYBENCH_PRIMARY 0u
#define PN_RAYBENCH_SHADOW 1u
#define PN_RAYBENCH_DIFFUSE 2u
// raybench_count.comp's word per pixel: the nodes a ray visited (low PN_RAY_WORK_BITS bits) and
// the primitives it tested (the high bits), each saturating at PN_RAY_WORK_MAX.
#define PN_RAY_WORK_BITS 16u
#define PN_RAY_WORK_MAX 0xffffu

// ---- BSDF test kernel (shaders/test/bsdf_sample.comp) modes ----
#define PN_BSDF_TEST_SAMPLE 0u  // itemCount samples of queries[0]: wi, pdf, weight, isDelta
#define PN_BSDF_TEST_EVAL 1u    // per query: eval (f) and pdf of (wo, wi)

// A ray for the test and benchmark kernels, 32 bytes.
PN_STRUCT(RayDesc) {
    vec3 origin;
    float tMax;
    vec3 direction;
    float pad;
};
#ifdef __cplusplus
static_assert(sizeof(RayDesc) == 32 && offsetof(RayDesc, tMax) == 12 && offsetof(RayDesc, direction) == 16);
#endif

// A hit from the test and benchmark kernels, 16 bytes.
PN_STRUCT(HitRecord) {
    float t;
    uint triangle;   // PN_NO_HIT when nothing was hit
    float u;
    float v;
};
#ifdef __cplusplus
static_assert(sizeof(HitRecord) == 16 && offsetof(HitRecord, v) == 12);
#endif

// A primary hit kept by the ray benchmark for its shadow and bounce passes, 32 bytes.
PN_STRUCT(SurfacePoint) {
    vec3 position;
    uint valid;
    vec3 normal;
    float pad;
};
#ifdef __cplusplus
static_assert(sizeof(SurfacePoint) == 32 && offsetof(SurfacePoint, valid) == 12 &&
              offsetof(SurfacePoint, normal) == 16);
#endif

// One query of the BSDF test kernel, 32 bytes: the material is materials[0] of the test scene.
PN_STRUCT(BsdfTestQuery) {
    vec3 wo;        // local shading frame, z = the normal on wo's side
    uint entering;  // nonzero: wo is outside the material (glass refracts with eta = ior)
    vec3 wi;        // PN_BSDF_TEST_EVAL: the direction to evaluate
    uint pad;
};
#ifdef __cplusplus
static_assert(sizeof(BsdfTestQuery) == 32 && offsetof(BsdfTestQuery, entering) == 12 &&
              offsetof(BsdfTestQuery, wi) == 16);
#endif

// One result of the BSDF test kernel, 32 bytes.
PN_STRUCT(BsdfTestResult) {
    vec3 wi;        // sampled direction (PN_BSDF_TEST_SAMPLE)
    float pdf;      // solid-angle pdf (of the sampled direction, or of the query's wi)
    vec3 value;     // weight = f cos / pdf (sample), or f (eval)
    uint isDelta;   // the sample came from a delta lobe (its pdf is that lobe's probability)
};
#ifdef __cplusplus
static_assert(sizeof(BsdfTestResult) == 32 && offsetof(BsdfTestResult, pdf) == 12 &&
              offsetof(BsdfTestResult, value) == 16 && offsetof(BsdfTestResult, isDelta) == 28);
#endif

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
