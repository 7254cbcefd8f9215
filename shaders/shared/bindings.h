// The scene descriptor set's binding numbers (set 0) and the workgroup sizes of the kernels:
// every pipeline and every kernel agree on them here.
// Valid GLSL and C++ (see types.h).
#ifndef PENUMBRA_SHADER_BINDINGS_H
#define PENUMBRA_SHADER_BINDINGS_H

// ---- limits and workgroup sizes (macros so GLSL layout qualifiers can use them) ----
#define PN_TRACE_GROUP_X 8
#define PN_TRACE_GROUP_Y 8
#define PN_LINEAR_GROUP 64

// ---- binding indices of the scene descriptor set (set 0) ----
#define PN_BINDING_NODES 0
#define PN_BINDING_TRI_VERTS 1
#define PN_BINDING_TRI_ATTRIBS 2
#define PN_BINDING_MATERIALS 3
#define PN_BINDING_LIGHTS 4  // LightRef per light the unified sampler can pick (top-level entries first)
#define PN_BINDING_FRAME 5
#define PN_BINDING_ACCUM 6
#define PN_BINDING_COUNTERS 7
#define PN_BINDING_SCRATCH 8  // pass-specific buffer (bench hits, test rays)
#define PN_BINDING_SCRATCH2 9
#define PN_BINDING_TEXTURES 10  // TextureInfo per texture
#define PN_BINDING_TEXELS 11    // every texture's RGBA8 texels, one uint each
#define PN_BINDING_PUNCTUAL 12  // PunctualLight per point, spot or directional light
#define PN_BINDING_SPHERE_LIGHTS 14  // SphereLight per emissive sphere or spot light with a radius
#define PN_BINDING_ENV_TABLE 15      // EnvAlias per environment texel (importance sampling)
// Bindings 16-23 are for the viewer's passes (G-buffer, history, denoiser, debug views).
#define PN_BINDING_VIEWER 16        // ViewerUniforms
#define PN_BINDING_GBUFFER 17       // GBufferTexel per pixel, this frame
#define PN_BINDING_GBUFFER_PREV 18  // GBufferTexel per pixel, last frame
#define PN_BINDING_HISTORY 19       // HistoryTexel per pixel, last frame (read)
#define PN_BINDING_HISTORY_OUT 20   // HistoryTexel per pixel, this frame (written)
#define PN_BINDING_FILTER_IN 21     // vec4 per pixel: denoiser input (rgb illumination, a variance)
#define PN_BINDING_FILTER_OUT 22    // vec4 per pixel: denoiser output
#define PN_BINDING_DISPLAY 23       // uint per pixel: RGBA8 (r in the low byte), what the window shows
#define PN_BINDING_ENV_TEXELS 24     // environment radiance, one vec4 (rgb, unused) per texel
#define PN_BINDING_OVERLAY_BOXES 25  // BvhNode per box the viewer's box overlay outlines (bounds only)
#define PN_BINDING_LIGHT_NODES 26    // LightNode per top-level light (the first FrameUniforms.topLightCount LightRefs)
#define PN_BINDING_DENOISE_GUIDE 27  // vec4 per pixel: what the a-trous passes compare (PN_DENOISE_GUIDE_BYTES)
#define PN_BINDING_INSTANCES_PREV 28  // the viewer's Instance entries as the previous frame placed them (gbuffer.comp's object motion)
#define PN_BINDING_ACTIVE_MASK 29    // uint per pixel: 0 skips the pixel in trace.comp when PN_TRACE_MASKED is set
#define PN_BINDING_INSTANCES 30      // Instance per placed bottom level (two-level scenes; see FrameUniforms.instanceCount)
// The wavefront trace pass's working buffers (render/passes/wavefront_pass.h, shaders/wave_*.comp).
#define PN_BINDING_WAVE_PATHS 31    // vec4 x PN_WAVE_PATH_VEC4S per path slot, field-major (stride PassPush.waveStride)
#define PN_BINDING_WAVE_HITS 32     // uvec4 per slot (t, primitive, u, v), then uint per slot (instance)
#define PN_BINDING_WAVE_SHADOWS 33  // vec4 x PN_WAVE_SHADOW_VEC4S per queued shadow ray, field-major
#define PN_BINDING_WAVE_QUEUES 34   // uint x 2 x waveStride: the live path slots, this bounce's and the next's
#define PN_BINDING_WAVE_CONTROL 35  // WaveControl
#define PN_BINDING_LIGHT_TREE 36    // LightTreeNode per node of the light BVH (root first, children side by side)
#define PN_BINDING_TRI_UVS 37       // TriUvs: entry 0 all zero, then the triangles that have texture coordinates
#define PN_BINDING_PIXEL_ESTIMATES 38  // vec4 per pixel: rgb = its value so far per sample, the shadow-ray roulette's scale

#endif
