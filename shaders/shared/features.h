// What a tracing kernel is specialised for: four specialization constants, each one kind of choice
// (shaders/lib/scene_bindings.glsl declares them; render/kernel_features.h fills them, with one
// table naming every bit, how it is detected and which scene edits can change it).
//   0  capabilities (PN_FEATURE_*): what the scene contains. The default, every bit, handles any
//      scene; a bit left out removes its code from the kernel.
//   1  the walk (PN_ACCEL_* or PN_WALK_ANY; shared/accel_layouts.h).
//   2  the camera variant (PN_CAMERA_*): where bounce 0's paths come from.
//   3  promises and modes (PN_OPTION_*): things the host vouches for or asks for. The default, none,
//      is always correct.
// Valid GLSL and C++ (see types.h).
#ifndef PENUMBRA_SHADER_FEATURES_H
#define PENUMBRA_SHADER_FEATURES_H

// ---- constant 0: capabilities ----
#define PN_FEATURE_SPHERES 1u       // analytic spheres among the primitives
#define PN_FEATURE_ALPHA_TEST 2u    // alpha-tested triangles
#define PN_FEATURE_TEXTURES 4u      // base colour, metallic-roughness or emission textures
#define PN_FEATURE_NORMAL_MAPS 8u
#define PN_FEATURE_ABSORPTION 16u   // materials with Beer absorption
#define PN_FEATURE_TRANSMISSION 32u // glass
#define PN_FEATURE_ENV_MAP 64u      // an environment map (else the constant background)
#define PN_FEATURE_SPRITES 128u     // sprites (PN_TRI_SPRITE) among the primitives
#define PN_FEATURE_SKY_PORTALS 256u // materials that show the environment (PN_MATERIAL_SKY_PORTAL)
#define PN_FEATURE_INSTANCES 512u   // a two-level BVH (instances); without it the flat walk carries none of that code
#define PN_FEATURE_LIGHT_GRID 1024u // light picks from the light grid (render/light_grid.h); without one, none of its code
// The shadow-ray roulette (lib/path.glsl keepShadowRay), for scenes of many lights, where a light
// sample often carries little (render/kernel_features.h); without it every shadow ray is traced
// and the pixel estimates are never read, whatever FrameUniforms::shadowRouletteShare says.
#define PN_FEATURE_SHADOW_ROULETTE 2048u
// Materials with a specular lobe: metallic or a coat (glass is PN_FEATURE_TRANSMISSION). Without
// either, every surface is Lambertian and the BSDF's Fresnel and GGX code is left out
// (BsdfParams.lambertian, lib/bsdf/bsdf.glsl): a Doom level's or the Cornell box's kernels.
#define PN_FEATURE_GLOSSY 4096u
#define PN_FEATURE_ALL 0x1fffu  // every capability above

// ---- constant 2: the camera variant ----
#define PN_CAMERA_FROM_QUEUE 0u  // paths come from the wavefront's queues (and the megakernel makes its own)
// The wavefront's bounce-0 extend and shade, which make their camera paths in place
// (PN_WAVE_CAMERA_IN_PLACE); the later rounds' kernels carry none of that code (measured: DOOM1's
// shading 1-2% faster; the driver kept the registers, docs/PERFORMANCE.md).
#define PN_CAMERA_IN_PLACE 1u

// ---- constant 3: promises and modes ----
// A promise: the scene has exactly one top-level light (a WAD level's torch), whose bound a pick
// then weighs once.
#define PN_OPTION_ONE_TOP_LIGHT 1u
// A traversal mode (--cull-backfaces): the closest-hit walks skip triangles whose geometric normal
// (e1 x e2, counter-clockwise front) faces away from the ray, except those flagged PN_TRI_KEEP_BACK;
// any-hit (shadow) rays cull nothing, so light never leaks through a wall seen from behind.
// lib/bvh.glsl hitPrimitive.
#define PN_OPTION_CULL_BACKFACES 2u
// A measurement: the trace kernels count primitive tests, closest hits and blocked shadow rays
// into RayCounters (lib/trace_outputs.glsl); without it none of that code.
#define PN_OPTION_FRAME_STATS 4u
#define PN_OPTION_NONE 0u

#endif
