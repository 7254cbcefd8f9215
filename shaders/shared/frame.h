// What every tracing dispatch is told: the per-frame uniforms (camera, counts, settings) and
// the per-dispatch push constants, with the trace pass's mode bits.
// Valid GLSL and C++ (see types.h); each struct's size and offsets are checked beside it.
#ifndef PENUMBRA_SHADER_FRAME_H
#define PENUMBRA_SHADER_FRAME_H

#include "shared/prelude.h"

#ifdef __cplusplus
namespace penumbra::shader {
#endif

// A pixel's value so far scales the shadow-ray roulette only once it rests on this many samples:
// fewer give too noisy a scale. Measured on the H200 (docs/PERFORMANCE.md, session 33): from 4
// samples, DOOM1 E1M1's raw error at equal time from a fresh 1-spp history was 5-10% worse than
// without the roulette; from 16, the same.
#define PN_PIXEL_ESTIMATE_MIN_SAMPLES 16u

// ---- estimators the integrator combines (FrameUniforms.misMode) ----
#define PN_MIS_BOTH 0u        // light sampling and BSDF sampling, power heuristic
#define PN_MIS_LIGHT_ONLY 1u  // direct light from light sampling only
#define PN_MIS_BSDF_ONLY 2u   // direct light from BSDF-sampled hits only

// ---- acceleration modes ----
#define PN_ACCEL_BVH 0u
#define PN_ACCEL_BRUTE 1u
#define PN_ACCEL_WIDE 2u  // the compressed 8-wide BVH (WideNode); flat scenes only

// Per-frame constants (uniform buffer), 192 bytes.
PN_STRUCT(FrameUniforms) {
    vec3 cameraPosition;
    float tanHalfFovY;
    vec3 cameraRight;    // unit
    float aspect;        // width / height
    vec3 cameraUp;       // unit
    uint width;
    vec3 cameraForward;  // unit
    uint height;
    uint maxBounces;     // path segments after the camera ray (pbrt's maxdepth)
    uint rouletteStart;  // bounce from which Russian roulette may end paths
    uint lightNodeCount; // nodes of the light BVH (0: no bounded lights)
    uint triCount;       // primitive slots: triangles and spheres (PN_TRI_SPHERE)
    uint nodeCount;
    uint accel;          // PN_ACCEL_*
    uint seed;
    uint samplesPerPass;
    vec3 background;     // radiance of rays that leave the scene
    uint punctualCount;  // entries in the punctual light buffer
    // Thin-lens camera (0 radius: pinhole) and sphere lights.
    float lensRadius;      // metres
    float focusDistance;   // metres along cameraForward
    uint sphereLightCount; // entries in the emissive-sphere table
    // Environment light: an equirectangular map (envWidth x envHeight texels at
    // PN_BINDING_ENV_TEXELS), or the constant background when envWidth is 0.
    uint envWidth;         // 0: no map
    float envIntensity;    // multiplies the map or the background
    float envRotation;     // radians about +y (world direction = rotation * map direction)
    uint envHeight;
    uint misMode;          // PN_MIS_*: which estimators the integrator combines (tests compare them)
    uint instanceCount;    // 0: one flat BVH rooted at node 0 (no instancing); else the Instance entries
    float time;            // seconds: the moment animated textures show
    // The unified light sampler.
    uint topLightCount;    // LightRef entries picked directly at every shading point
    float envLuminance;    // mean luminance of the environment over directions (intensity 1)
    uint lightRefCount;    // LightRef entries in all
    uint lightPickUniform; // nonzero: pick every light with the same probability (a test oracle)
    uint topRoot;          // the walk's root: top level (instanceCount > 0), rest tree (at rest, 0 instances), or 0 (flat)
    uint lightGridOffset;  // word of the light grid (its LightGridHeader) in the light tree's buffer (0: none, walk the tree)
    float shadowRouletteShare;  // shadow-ray roulette below this share of the pixel's estimate (lib/path.glsl); 0: off
    float textureSaturation;    // of base-colour textures (shared/view_limits.h); 1: as they are
    float renderDistance;       // metres across the floor from the camera; nothing beyond is hit; 0: no limit
    uint flags;                 // PN_FRAME_*
};
#ifdef __cplusplus
static_assert(sizeof(FrameUniforms) == 192 && offsetof(FrameUniforms, tanHalfFovY) == 12 &&
              offsetof(FrameUniforms, cameraRight) == 16 && offsetof(FrameUniforms, aspect) == 28 &&
              offsetof(FrameUniforms, cameraUp) == 32 && offsetof(FrameUniforms, width) == 44 &&
              offsetof(FrameUniforms, cameraForward) == 48 && offsetof(FrameUniforms, height) == 60 &&
              offsetof(FrameUniforms, maxBounces) == 64 && offsetof(FrameUniforms, samplesPerPass) == 92 &&
              offsetof(FrameUniforms, background) == 96 && offsetof(FrameUniforms, punctualCount) == 108 &&
              offsetof(FrameUniforms, lensRadius) == 112 && offsetof(FrameUniforms, sphereLightCount) == 120 &&
              offsetof(FrameUniforms, envWidth) == 124 && offsetof(FrameUniforms, envHeight) == 136 &&
              offsetof(FrameUniforms, misMode) == 140 && offsetof(FrameUniforms, instanceCount) == 144 &&
              offsetof(FrameUniforms, time) == 148 && offsetof(FrameUniforms, topLightCount) == 152 &&
              offsetof(FrameUniforms, envLuminance) == 156 && offsetof(FrameUniforms, lightPickUniform) == 164 &&
              offsetof(FrameUniforms, topRoot) == 168 && offsetof(FrameUniforms, lightGridOffset) == 172 &&
              offsetof(FrameUniforms, textureSaturation) == 180 && offsetof(FrameUniforms, renderDistance) == 184 &&
              offsetof(FrameUniforms, flags) == 188);
#endif
// FrameUniforms.flags. NO_JITTER: camera rays go through pixel centres (no anti-aliasing; the
// random draws are made all the same, so the rest of each path's numbers do not change).
#define PN_FRAME_NO_JITTER 1u

#define PN_TRACE_MASKED 1u       // PassPush.mode bit of trace.comp: read the active mask (adaptive sampling)
#define PN_TRACE_REPLACE 2u      // PassPush.mode bit of trace.comp and wave_finish.comp: store the pixel's sums
                                 // instead of adding them (a pass that samples every pixel: no clear before it)
// PassPush.mode bit of trace.comp and the wavefront: a pixel's samples in one pass share their camera
// ray (shared/pass_jitter.h), so the wavefront traces it once per pixel. For the viewer, whose
// many passes spread it over the pixel; set only for passes of more than one sample.
#define PN_TRACE_SHARED_CAMERA 4u

// PassPush.mode bit of trace.comp and the wavefront: the pixel estimates buffer holds each pixel's
// value so far (the viewer's history); without it a pass that adds to the accumulation buffer
// estimates from its sums, and one that replaces them has no estimate (lib/trace_outputs.glsl).
#define PN_TRACE_PIXEL_ESTIMATES 16u

// Per-dispatch constants, 48 bytes.
PN_STRUCT(PassPush) {
    uint passIndex;      // which progressive pass this is; with seed it decorrelates samples
    uint mode;           // pass-specific (raybench mode, test kernel mode)
    uint itemCount;      // pass-specific (rays in a test batch)
    uint countRays;      // nonzero: add traced rays to the counters buffer
    uint tileX;          // trace.comp: the first pixel of this dispatch; a long pass is split into
    uint tileY;          //   tiles so no dispatch trips a display watchdog (render/passes/trace_tiles.h)
    uint tileWidth;      // wave_*.comp: the tile's size in pixels (its path slots are sample-major:
    uint tileHeight;     //   slot = sample * tileWidth * tileHeight + row * tileWidth + column)
    uint waveStride;     // wave_*.comp: path slots in the working buffers (their field stride)
    uint waveBounce;     // wave_*.comp: which bounce this is (picks the queue it reads)
    uint waveTailPaths;  // wave_args.comp: at most this many live paths go to wave_tail.comp instead
    uint pad1;           //   of another round of extend, shade and shadow (0: never)
};
#ifdef __cplusplus
static_assert(sizeof(PassPush) == 48 && offsetof(PassPush, countRays) == 12 && offsetof(PassPush, tileX) == 16 &&
              offsetof(PassPush, tileY) == 20 && offsetof(PassPush, tileWidth) == 24 && offsetof(PassPush, waveStride) == 32 &&
              offsetof(PassPush, waveBounce) == 36 && offsetof(PassPush, waveTailPaths) == 40);
#endif

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
