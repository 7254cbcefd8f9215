// The tracing kernels' feature bits (specialization constant 0).
// Valid GLSL and C++ (see types.h).
#ifndef PENUMBRA_SHADER_FEATURES_H
#define PENUMBRA_SHADER_FEATURES_H

// ---- kernel features: specialization constant 0 of the tracing kernels, a bit set. A pipeline
// made for a scene leaves out what the scene does not use (render/kernel_features.h); the
// shader's default, every bit, handles any scene. ----
#define PN_FEATURE_SPHERES 1u       // analytic spheres among the primitives
#define PN_FEATURE_ALPHA_TEST 2u    // alpha-tested triangles
#define PN_FEATURE_TEXTURES 4u      // base colour, metallic-roughness or emission textures
#define PN_FEATURE_NORMAL_MAPS 8u
#define PN_FEATURE_ABSORPTION 16u   // materials with Beer absorption
#define PN_FEATURE_TRANSMISSION 32u // glass
#define PN_FEATURE_ENV_MAP 64u      // an environment map (else the constant background)
#define PN_FEATURE_BRUTE_FORCE 128u // --accel brute
#define PN_FEATURE_SPRITES 256u     // sprites (PN_TRI_SPRITE) among the primitives
#define PN_FEATURE_SKY_PORTALS 512u // materials that show the environment (PN_MATERIAL_SKY_PORTAL)
#define PN_FEATURE_INSTANCES 1024u // a two-level BVH (instances); without it the flat walk carries none of that code
#define PN_FEATURE_WIDE_BVH 2048u  // --accel wide (lib/wide_bvh.glsl); other kernels carry none of its code
#define PN_FEATURE_LIGHT_GRID 4096u // light picks from the light grid (render/light_grid.h); without one, none of its code
// The shadow-ray roulette (lib/path.glsl keepShadowRay), for scenes of many lights, where a light
// sample often carries little (render/kernel_features.h); without it every shadow ray is traced
// and the pixel estimates are never read, whatever FrameUniforms::shadowRouletteShare says.
#define PN_FEATURE_SHADOW_ROULETTE 32768u
// Materials with a specular lobe: metallic or a coat (glass is PN_FEATURE_TRANSMISSION). Without
// either, every surface is Lambertian and the BSDF's Fresnel and GGX code is left out
// (BsdfParams.lambertian, lib/bsdf/bsdf.glsl): a Doom level's or the Cornell box's kernels.
#define PN_FEATURE_GLOSSY 65536u
#define PN_FEATURE_ALL (0x1fffu | PN_FEATURE_SHADOW_ROULETTE | PN_FEATURE_GLOSSY)  // every feature above
// Not a capability but a promise, so not in PN_FEATURE_ALL (which must handle any scene): the
// scene has exactly one top-level light (a WAD level's torch), whose bound a pick then weighs once.
#define PN_FEATURE_ONE_TOP_LIGHT 8192u
// Not a scene's feature but a kernel variant: the wavefront's bounce-0 extend and shade, which make
// their camera paths in place (PN_WAVE_CAMERA_IN_PLACE); the later rounds' kernels carry none of
// that code (measured: DOOM1's shading 1-2% faster; the driver kept the registers, docs/PERFORMANCE.md).
#define PN_FEATURE_CAMERA_IN_PLACE 16384u
// Not a scene's feature but a traversal option (--cull-backfaces), so not in PN_FEATURE_ALL: the
// closest-hit walks skip triangles whose geometric normal (e1 x e2, counter-clockwise front) faces
// away from the ray, except those flagged PN_TRI_KEEP_BACK; any-hit (shadow) rays cull nothing,
// so light never leaks through a wall seen from behind. lib/bvh.glsl hitPrimitive.
#define PN_FEATURE_CULL_BACKFACES 131072u
// Not a scene's feature but a measurement: the trace kernels count primitive tests, closest hits
// and blocked shadow rays into RayCounters (lib/trace_outputs.glsl); without it none of that code.
#define PN_FEATURE_FRAME_STATS 262144u

#endif
