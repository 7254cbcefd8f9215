// Every struct and constant that crosses between host and shader. This file is valid GLSL and
// valid C++; it is the only place these layouts are written (see ../../../shared/design.md).
// Layouts follow std430 by hand: each vec3 is followed by a 4-byte scalar so that nothing is
// padded implicitly, and the C++ side checks every size and offset below.
#ifndef PENUMBRA_SHADER_TYPES_H
#define PENUMBRA_SHADER_TYPES_H

#ifdef __cplusplus
#include "core/gpu_types.h"
#define PN_STRUCT(name) struct alignas(16) name
// A struct whose widest member is a vec2 (std430 base alignment 8) or a scalar (4): std430 packs
// its array elements at its own size, with no rounding to 16 bytes.
#define PN_STRUCT8(name) struct alignas(8) name
#define PN_STRUCT4(name) struct alignas(4) name
namespace penumbra::shader {
using namespace penumbra::gpu_types;
#else
#define PN_STRUCT(name) struct name
#define PN_STRUCT8(name) struct name
#define PN_STRUCT4(name) struct name
#endif

// ---- limits and workgroup sizes (macros so GLSL layout qualifiers can use them) ----
#define PN_TRACE_GROUP_X 8
#define PN_TRACE_GROUP_Y 8
#define PN_LINEAR_GROUP 64
#define PN_BVH_STACK_SIZE 64  // traversal stack entries; > PN_BVH_MAX_DEPTH, which the builder guarantees
#define PN_BVH_MAX_DEPTH 60
#define PN_WAVE_GROUP 128       // threads per workgroup of the wavefront kernels (one path slot each)
#define PN_WAVE_PATH_VEC4S 7    // vec4 fields of a path's state in the wavefront buffers (wave_state.glsl)
#define PN_WAVE_SHADOW_VEC4S 3  // vec4 fields of a queued shadow ray

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
#define PN_BINDING_SPHERES 13        // reserved; spheres live in the triangle arrays (PN_TRI_SPHERE)
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
// A pixel's value so far scales the shadow-ray roulette only once it rests on this many samples:
// fewer give too noisy a scale. Measured on the H200 (docs/PERFORMANCE.md, session 33): from 4
// samples, DOOM1 E1M1's raw error at equal time from a fresh 1-spp history was 5-10% worse than
// without the roulette; from 16, the same.
#define PN_PIXEL_ESTIMATE_MIN_SAMPLES 16u

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

// ---- estimators the integrator combines (FrameUniforms.misMode) ----
#define PN_MIS_BOTH 0u        // light sampling and BSDF sampling, power heuristic
#define PN_MIS_LIGHT_ONLY 1u  // direct light from light sampling only
#define PN_MIS_BSDF_ONLY 2u   // direct light from BSDF-sampled hits only

// ---- acceleration modes ----
#define PN_ACCEL_BVH 0u
#define PN_ACCEL_BRUTE 1u
#define PN_ACCEL_WIDE 2u  // the compressed 8-wide BVH (WideNode); flat scenes only

// ---- ray benchmark modes (raybench.comp) ----
#define PN_RAYBENCH_PRIMARY 0u
#define PN_RAYBENCH_SHADOW 1u
#define PN_RAYBENCH_DIFFUSE 2u
// raybench_count.comp's word per pixel: the nodes a ray visited (low PN_RAY_WORK_BITS bits) and
// the primitives it tested (the high bits), each saturating at PN_RAY_WORK_MAX.
#define PN_RAY_WORK_BITS 16u
#define PN_RAY_WORK_MAX 0xffffu

// ---- material flags ----
#define PN_MATERIAL_EMISSIVE 1u
#define PN_MATERIAL_ALPHA_TESTED 2u  // texels with alpha below alphaCutoff are holes
#define PN_MATERIAL_ONE_SIDED 4u     // the back face reflects nothing (glTF doubleSided = false)
// Shows the environment seen through it plus its emission (a Doom sky ceiling and its fill light).
#define PN_MATERIAL_SKY_PORTAL 8u
#define PN_MATERIAL_HIDDEN_EMISSION 16u  // camera rays do not see `emission` (Doom's sector light)

// Perceptual roughness below this is shaded as perfectly smooth (delta lobes); at or above it the
// GGX lobes use alpha = roughness^2 (so alpha >= PN_SMOOTH_ROUGHNESS^2, which keeps D finite).
#define PN_SMOOTH_ROUGHNESS 0.02

// ---- BSDF test kernel (shaders/test/bsdf_sample.comp) modes ----
#define PN_BSDF_TEST_SAMPLE 0u  // itemCount samples of queries[0]: wi, pdf, weight, isDelta
#define PN_BSDF_TEST_EVAL 1u    // per query: eval (f) and pdf of (wo, wi)

// ---- triangle flags (TriVerts.flags, read during traversal) ----
#define PN_TRI_ALPHA_TESTED 1u  // its material is alpha tested: check the texture before accepting a hit
// The slot holds an analytic sphere, not a triangle: v0 = centre, e1.x = radius (e2 unused).
// Spheres share the triangles' arrays so a leaf stays one contiguous primitive range.
#define PN_TRI_SPHERE 2u
// The slot holds a sprite (lib/sprite.glsl): an upright card through the vertical axis at v0 that
// turns to face each ray's origin. e1 = (left, right, bottom), e2.x = top: its extent around v0
// in metres (x along the card, to the viewer's right); e2.y = the direction the thing faces, in
// radians counter-clockwise (seen from above) from +x toward -z; e2.z = its views (1 or 8).
#define PN_TRI_SPRITE 4u
// Never culled by PN_FEATURE_CULL_BACKFACES: its material transmits (a path inside glass must
// find the back faces to leave it).
#define PN_TRI_KEEP_BACK 8u

// ---- texture flags and sampler words (a material's *Wrap fields: PN_WRAP_* for u,
// | PN_WRAP_* for v << 8, | PN_SAMPLER_NEAREST) ----
#define PN_TEXTURE_SRGB 1u
#define PN_WRAP_REPEAT 0u
#define PN_WRAP_CLAMP 1u
#define PN_WRAP_MIRROR 2u
#define PN_SAMPLER_NEAREST 0x10000u  // the nearest texel instead of bilinear filtering
#define PN_NO_TEXTURE 0xffffffffu

// ---- punctual light types ----
#define PN_LIGHT_POINT 0u
#define PN_LIGHT_SPOT 1u
#define PN_LIGHT_DIRECTIONAL 2u

// ---- the unified light sampler (lib/light_sampler.glsl) ----
#define PN_LIGHTREF_TRIANGLE 0u     // LightRef.index: primitive slot of an emissive triangle
#define PN_LIGHTREF_SPHERE 1u       // LightRef.index: entry of the sphere-light table
#define PN_LIGHTREF_PUNCTUAL 2u     // LightRef.index: entry of the punctual-light table
#define PN_LIGHTREF_ENVIRONMENT 3u  // the environment (map or constant background)
#define PN_NO_LIGHT 0xffffffffu     // TriAttribs.lightIndex of a primitive that is no light
#define PN_LIGHT_TREE_MAX_DEPTH 64u // the bit trail of a light has 64 bits (two uints)
// The light-tree walk weighs children by their importance at the shading point on its first
// levels, below them by power alone (lib/light_sampler.glsl firstChildProbability).
#define PN_LIGHT_TREE_IMPORTANCE_LEVELS 5u
// The light grid (render/light_grid.h): for every cell of a grid over the scene and every bin of
// shading normals, a table that picks among the light tree's clusters (its nodes on one level L,
// and leaves above it) by their importance bound over the whole cell and bin, in place of the
// walk's importance levels. Words after the tree's records in its buffer, from
// FrameUniforms.lightGridOffset: origin (3 floats), inverse cell size, cells along x, y and z,
// the clusters' count, L, the first table's word, the first mass's word; at PN_LIGHT_GRID_PREFIXES
// the cluster of every trail prefix of L bits (2^L words), then each cluster's words (node word,
// level, first light entry, lights); then per cluster an alias table over its lights by power
// (what the walk below it would choose), one entry per light: (threshold | alias << 17, LightRef);
// then per LightRef its mass in its cluster's table; then per cell (x fastest) and bin, the tree
// root's bound over the cell and bin (a float: the tree's weight against the top-level lights);
// then per cell and bin, one alias entry per cluster: (threshold | alias << 17, mass). Every word
// offset is from the grid's first word.
#define PN_LIGHT_GRID_COUNT 7u             // header word: the clusters
#define PN_LIGHT_GRID_LEVELS 8u            // header word: L
#define PN_LIGHT_GRID_FIRST_TABLE 9u       // header word: where the tables start
#define PN_LIGHT_GRID_FIRST_MASS 10u       // header word: where the lights' masses start (one per LightRef)
#define PN_LIGHT_GRID_FIRST_TREE 11u       // header word: where the tree's weights start (one per table)
#define PN_LIGHT_GRID_PREFIXES 16u         // word of the prefix -> cluster map
#define PN_LIGHT_GRID_CLUSTER_WORDS 4u     // per cluster: node word, level, first light entry, lights (0: walk below)
#define PN_LIGHT_GRID_MAX_LEVELS 8u        // at most 256 clusters
#define PN_LIGHT_GRID_BINS 6u              // shading normals by their largest component: +x, -x, +y, -y, +z, -z
#define PN_LIGHT_GRID_MASS_BITS 16u        // an entry's threshold is out of 2^16; a table's masses sum to 2^16 x clusters
#define PN_LIGHT_GRID_ALIAS_SHIFT 17u      // an alias entry's word: threshold (0 to 2^16, 17 bits) | alias << 17
#define PN_LIGHT_GRID_THRESHOLD_MASK 0x1ffffu
#define PN_LIGHT_NODE_LEAF 0x80000000u       // LightNode / LightTreeNode.childOrLight: a leaf
#define PN_LIGHT_NODE_TWO_SIDED 0x40000000u  // LightTreeNode.childOrLight: emits both ways
#define PN_LIGHT_NODE_INDEX 0x3fffffffu      // LightTreeNode.childOrLight: the child record or the LightRef

#define PN_NO_HIT 0xffffffffu

// BVH node, 32 bytes. Nodes are stored depth-first, so an interior node's left child is the node
// right after it.
//   triCount == 0 (interior): firstOrRight = index of the right child
//   triCount  > 0 (leaf):     firstOrRight = index of the first triangle (triangles are stored in
//                             leaf order, so a leaf's triangles are contiguous)
PN_STRUCT(BvhNode) {
    vec3 boundsMin;     // 12
    uint firstOrRight;  //  4
    vec3 boundsMax;     // 12
    uint triCount;      //  4
};

// What the GPU walk reads for binary node i (bvh/child_pairs.h), 64 bytes, same indices as the
// BvhNode array: an interior node's two children, boxes and indices side by side, so each step of
// the walk is one load of 64 contiguous bytes (Aila & Laine 2009) where BvhNodes took the node and
// then its two children from two places. A leaf's record holds its primitives.
//   leafCount == 0 (interior): left = i + 1, right = BvhNode.firstOrRight; their boxes
//   leafCount  > 0 (leaf):     left = its first primitive (top level: its instance); boxes unused
PN_STRUCT(BvhPair) {
    vec3 leftMin;
    uint left;
    vec3 leftMax;
    uint leafCount;
    vec3 rightMin;
    uint right;
    vec3 rightMax;
    uint pad0;
};

// Compressed 8-wide BVH node (the CWBVH layout of Ylitie, Karras and Laine 2017), 80 bytes.
// Wide nodes are uploaded after the binary walk's records (BvhPair) in the same buffer (GLSL
// reads them as five uvec4 from uvec4 frame.nodeCount * 4 on), root first. Child slot i (0-7) has
// a box quantized to 8 bits per plane: lo = origin + q * 2^e, with the three exponents stored as
// float exponent bits so the shader builds 2^e with one shift. Its meta byte says what the slot
// holds:
//   0                          empty
//   001 11sss (0x38 | slot)    an interior child: node childBase + (interior slots below it)
//   ccc ooooo                  a leaf: primitives primBase + o, o + 1, ... with ccc = 1, 3 or 7
//                              (one, two or three primitives, unary); o < 24
// The builder assigns slots so that slot i holds the child nearest to a ray whose direction has
// sign bits i (bit k set: negative along axis k), which the traversal turns into near-first order.
PN_STRUCT(WideNode) {
    vec3 origin;        // 12: the node box's lower corner
    uint exponentsMask; //  4: biased exponents x | y << 8 | z << 16, interior-slot mask << 24
    uint childBase;     //  4: first interior child in the wide node array (they are contiguous)
    uint primBase;      //  4: first primitive slot of the leaves (TriVerts index)
    uint meta[2];       //  8: slot i in byte i % 4 of meta[i / 4]
    uint loX[2];        //  8: quantized lower x plane of slot i, byte i % 4 of loX[i / 4]
    uint hiX[2];        //  8
    uint loY[2];        //  8
    uint hiY[2];        //  8
    uint loZ[2];        //  8
    uint hiZ[2];        //  8
};

// One placement of a bottom-level BVH in a two-level scene, 112 bytes. Bottom levels live in the
// node and triangle arrays like the single-level BVH, with absolute indices (interior nodes name
// their right child in the node array, leaves their first slot in TriVerts), so a bottom level is
// walked exactly as the flat BVH is, only in the instance's space. The top level's nodes follow
// every bottom level's (root at FrameUniforms.topRoot); its leaves hold one instance each
// (firstOrRight = instance index, triCount = 1).
PN_STRUCT(Instance) {
    vec4 objectToWorld[3];  // 48: rows of the 3x4 affine transform (row i: xyz = linear part, w = translation)
    vec4 worldToObject[3];  // 48: its inverse; normals go to world space by its transpose
    uint rootNode;          //  4: root of the bottom level in the node array, | PN_INSTANCE_IDENTITY
    uint firstPrimitive;    //  4: the bottom level's slots are [firstPrimitive, firstPrimitive + primitiveCount)
    uint primitiveCount;    //  4: (what --accel brute loops over)
    uint id;                //  4: the scene's instance number (stable across top-level rebuilds)
};
// Set in Instance.rootNode when the transform is exactly the identity (the world's own geometry,
// a mesh placed where it was modelled): the walk enters it keeping the world ray, no transform.
#define PN_INSTANCE_IDENTITY 0x80000000u

// Hot triangle data, read on every traversal step: 48 bytes. Edges are precomputed for
// Moller-Trumbore (e1 = v1 - v0, e2 = v2 - v0).
PN_STRUCT(TriVerts) {
    vec3 v0;
    uint flags;    // PN_TRI_*
    vec3 e1;
    uint uvIndex;  // the triangle's TriUvs entry (0: all zero, as for a mesh without UVs); fills
                   // padding that the 16-byte loads of the walk carry anyway
    vec3 e2;
    float pad2;
};

// Cold triangle data, read once for the closest hit: 24 bytes (std430 packs these at 24; the
// texture coordinates live in TriUvs, so that meshes without them pay nothing). Shading normals
// are packed (shared/unit_vector.h: unpackUnitVector).
PN_STRUCT4(TriAttribs) {
    uint materialId;  //  4
    uint lightIndex;  //  4: LightRef of this emitter, or PN_NO_LIGHT
    float area;       //  4: world-space area, for converting light pdfs
    uint n0;          //  4: per-vertex shading normals, octahedral (packUnitVector)
    uint n1;          //  4
    uint n2;          //  4
};

// A triangle's texture coordinates at its three vertices, 24 bytes, at TriVerts.uvIndex. They stay
// full floats, since tiled surfaces (a Doom wall) run to coordinates in the hundreds, where half
// floats would miss texels. Triangles whose coordinates are all zero share entry 0.
PN_STRUCT8(TriUvs) {
    vec2 uv0;  //  8
    vec2 uv1;  //  8
    vec2 uv2;  //  8
};

// One principled material (see docs/MATERIALS.md), 96 bytes. Lobes: a Lambertian base under a
// dielectric GGX coat (weight `specular`), a GGX conductor (weight `metallic`) and a dielectric
// that refracts (weight (1 - metallic) * transmission). roughness below PN_SMOOTH_ROUGHNESS makes
// the specular lobes perfectly smooth (delta) ones.
PN_STRUCT(Material) {
    vec3 albedo;          // base colour, each channel in [0, 1]; multiplies the texture
    uint flags;           // PN_MATERIAL_*
    vec3 emission;        // emitted radiance from the front face (winding order), W/(m^2 sr) per channel
    float alphaCutoff;    // with PN_MATERIAL_ALPHA_TESTED
    vec3 absorption;      // Beer-Lambert coefficient inside a transmissive material, per metre (0: clear)
    float ior;            // index of refraction, >= 1
    float metallic;       // [0, 1]; multiplies the texture's B channel
    float roughness;      // perceptual, [0, 1]; multiplies the texture's G channel; GGX alpha = roughness^2
    float transmission;   // [0, 1]
    float specular;       // [0, 1]: strength of the dielectric coat over the diffuse base (0: pure Lambert)
    uint albedoTexture;   // PN_NO_TEXTURE or an index into the texture table
    uint albedoWrap;      // sampler word: PN_WRAP_* for u | (PN_WRAP_* for v) << 8 | PN_SAMPLER_NEAREST
    uint metallicRoughnessTexture;  // linear; G = roughness, B = metallic (glTF)
    uint metallicRoughnessWrap;
    uint normalTexture;   // tangent-space normal map, linear
    uint normalWrap;
    uint emissionTexture; // sRGB, multiplies emission
    uint emissionWrap;
};

// Where one texture's texels are in the texel buffer, and its animation, 32 bytes. A texture of
// frameCount > 1 is frame `frame` of a cycle whose frames are the textures [index - frame,
// index - frame + frameCount); a lookup of it shows frame (floor(time / secondsPerFrame) + frame)
// mod frameCount of that cycle.
PN_STRUCT(TextureInfo) {
    uint firstTexel;
    uint width;
    uint height;
    uint flags;  // PN_TEXTURE_*
    uint frameCount;
    uint frame;
    float secondsPerFrame;
    uint pad0;
};

// One texel of the environment's alias table, 16 bytes. The table has one entry per texel of the
// equirectangular map (row-major, top row = +y), so entry i is also texel i.
PN_STRUCT(EnvAlias) {
    float threshold;  // keep texel i when u < threshold, else take the alias
    uint alias;       // index of the alias texel
    float pdf;        // solid-angle pdf of directions inside texel i (its pmf / its solid angle)
    float pad;
};

// One light the unified sampler can pick, 16 bytes. The first FrameUniforms.topLightCount
// entries are picked directly at every shading point (infinite lights, lights that move every
// frame); the rest are the leaves of the light BVH. The bit trail (bit d: the path took the
// second child at depth d) lets MIS find the probability of picking a light it hit.
PN_STRUCT(LightRef) {
    uint type;     // PN_LIGHTREF_*
    uint index;    // into the table of that type (see PN_LIGHTREF_*)
    uint trailLo;  // depths 0-31
    uint trailHi;  // depths 32-63
};

// The bounds of a top-level light that has a place (a moving point or spot light), 64 bytes, as
// pbrt-v4's LightBounds (Conty & Kulla 2018): where it is, how much it emits and in which
// directions. The light BVH itself is stored compactly (LightTreeNode).
PN_STRUCT(LightNode) {
    vec3 boundsMin;
    float phi;          // emitted power bound: radiance x area (irradiance at unit distance)
    vec3 boundsMax;
    float cosThetaO;    // normals (emission directions) lie within thetaO of axis
    vec3 axis;          // unit
    float cosThetaE;    // emission spreads at most thetaE beyond the normals (pi/2: Lambertian)
    uint childOrLight;
    uint twoSided;      // nonzero: emits on both sides of its normals
    float sinThetaO;    // precomputed for the importance bound
    float minDistance2; // half the bounds' diagonal: pbrt-v4's floor on the squared distance
};

// A node of the light BVH as the shaders walk it, 48 bytes: what the importance bound needs,
// precomputed (render/light_tree.h compactLightTree). The box becomes its bounding sphere (the
// bound only ever used the box's centre and half diagonal), the cone's sine is stored beside its
// cosine, and the two children of a node lie side by side. The root is record 0; an interior
// node's children are records childOrLight and childOrLight + 1.
//   childOrLight & PN_LIGHT_NODE_LEAF: a leaf holding LightRef (childOrLight & PN_LIGHT_NODE_INDEX)
//   childOrLight & PN_LIGHT_NODE_TWO_SIDED: emits on both sides of its normals
PN_STRUCT(LightTreeNode) {
    vec3 center;        // of the lights' bounding box
    float radius;       // half the box's diagonal
    vec3 axis;          // unit
    float phi;          // emitted power bound, as LightNode.phi
    float cosThetaO;
    float sinThetaO;
    float cosThetaE;
    uint childOrLight;
};

// A point, spot or directional light, 64 bytes. Delta lights: reached only by light sampling.
PN_STRUCT(PunctualLight) {
    vec3 position;
    uint type;            // PN_LIGHT_*
    vec3 intensity;       // colour * intensity: candela (point, spot) or lux (directional)
    float range;          // 0: unlimited; else glTF's smooth window to zero at this distance
    vec3 direction;       // unit, where the light travels (spot, directional)
    float cosOuter;       // spot: cosine of the outer cone angle
    float cosInner;       // spot: cosine of the inner cone angle
    float pad2;
    float coneOneMinusCos;  // directional: 1 - cos(angular radius); 0 is a delta light (a sun
                            // disk of radiance intensity / (pi sin^2 radius) otherwise)
    float pad1;
};

// A light sampled by the cone of directions its sphere subtends, 64 bytes: an emissive sphere
// of the scene (primitive = its slot in the triangle arrays, so BSDF-sampled hits find it and
// MIS applies) or a spot light with a radius (primitive = PN_NO_HIT: no geometry, reached by
// light sampling only).
PN_STRUCT(SphereLight) {
    vec3 center;
    float radius;
    vec3 radiance;        // leaving the sphere's outside, W/(m^2 sr) per channel
    float pad2;
    vec3 spotDirection;   // spot: unit, where the light travels
    float cosOuter;       // spot: cosine of the outer cone angle (-1 for a sphere: no cone)
    float cosInner;       // spot: cosine of the inner cone angle
    float pad3;
    uint primitive;       // slot in TriVerts / TriAttribs, or PN_NO_HIT for a spot light
    uint pad0;
};

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
    // Thin-lens camera (0 radius: pinhole) and analytic primitives.
    float lensRadius;      // metres
    float focusDistance;   // metres along cameraForward
    uint sphereCount;      // entries in the sphere buffer
    uint sphereLightCount; // entries in the emissive-sphere table
    // Environment light: an equirectangular map (envWidth x envHeight texels at
    // PN_BINDING_ENV_TEXELS), or the constant background when envWidth is 0.
    uint envWidth;         // 0: no map
    float envIntensity;    // multiplies the map or the background
    float envRotation;     // radians about +y (world direction = rotation * map direction)
    uint envHeight;
    uint misMode;          // PN_MIS_*: which estimators the integrator combines (tests compare them)
    uint debugMode;        // viewer debug views; 0: the image
    uint instanceCount;    // 0: one flat BVH rooted at node 0 (no instancing); else the Instance entries
    float time;            // seconds: the moment animated textures show
    // The unified light sampler.
    uint topLightCount;    // LightRef entries picked directly at every shading point
    float envLuminance;    // mean luminance of the environment over directions (intensity 1)
    uint lightRefCount;    // LightRef entries in all
    uint lightPickUniform; // nonzero: pick every light with the same probability (a test oracle)
    uint topRoot;          // with instanceCount > 0: the top-level BVH's root node
    uint lightGridOffset;  // word of the light grid in the light tree's buffer (0: none, walk the tree)
    float shadowRouletteShare;  // shadow-ray roulette below this share of the pixel's estimate (lib/path.glsl); 0: off
    float textureSaturation;    // of base-colour textures (shared/view_limits.h); 1: as they are
    float renderDistance;       // metres across the floor from the camera; nothing beyond is hit; 0: no limit
    uint flags;                 // PN_FRAME_*
    uint pad5;
    uint pad6;
};
// FrameUniforms.flags. NO_JITTER: camera rays go through pixel centres (no anti-aliasing; the
// random draws are made all the same, so the rest of each path's numbers do not change).
#define PN_FRAME_NO_JITTER 1u

// ---- viewer passes (temporal.comp, atrous.comp, tonemap.comp, gbuffer.comp, heatmap.comp) ----
#define PN_TONEMAP_REINHARD 0u
#define PN_TONEMAP_ACES 1u
#define PN_DEBUG_NONE 0u
#define PN_DEBUG_NORMALS 1u
#define PN_DEBUG_ALBEDO 2u
#define PN_DEBUG_DEPTH 3u
#define PN_DEBUG_MOTION 4u
#define PN_DEBUG_SAMPLES 5u
#define PN_DEBUG_HEAT_NODES 6u   // BVH nodes visited by the primary ray
#define PN_DEBUG_HEAT_TRIS 7u    // triangles tested by the primary ray
#define PN_DEBUG_BVH_BOXES 8u    // the image with the BVH's boxes at one depth outlined (boxes.comp)
#define PN_DEBUG_LEAF_DEPTH 9u   // depth of the BVH leaf holding the primary ray's hit (root: 0)
#define PN_DEBUG_LEAF_TRIS 10u   // primitives in the BVH leaf holding the primary ray's hit
// The fast preview (ViewSettings::preview, shown while the view moves): the primary hit's albedo
// times the cosine between its normal and the ray, as a raster preview with a headlight draws it.
#define PN_DEBUG_PREVIEW 11u
#define PN_MAX_OVERLAY_BOXES 4096u  // boxes the overlay draws at most (each pixel tests every one)
// The debug view's small window (picture-in-picture): 1/PN_DEBUG_INSET_DIVISOR of the image's
// width and height, PN_DEBUG_INSET_MARGIN pixels from its bottom right corner, in a one-pixel frame.
#define PN_DEBUG_INSET_DIVISOR 4u
#define PN_DEBUG_INSET_MARGIN 8u
#define PN_OVERLAY_COLOR 0xff00ffffu  // RGBA8 of an outlined pixel: opaque yellow
#define PN_TRACE_MASKED 1u       // PassPush.mode bit of trace.comp: read the active mask (adaptive sampling)
#define PN_TRACE_REPLACE 2u      // PassPush.mode bit of trace.comp and wave_finish.comp: store the pixel's sums
                                 // instead of adding them (a pass that samples every pixel: no clear before it)
// PassPush.mode bit of trace.comp and the wavefront: a pixel's samples in one pass share their camera
// ray (shared/pass_jitter.h), so the wavefront traces it once per pixel. For the viewer, whose
// many passes spread it over the pixel; set only for passes of more than one sample.
#define PN_TRACE_SHARED_CAMERA 4u
// PassPush.mode bit the wavefront sets for itself: bounce 0's extend and shade make each slot's
// camera path where they need it (startPath) instead of reading what a start step stored, and take
// slot i as queue entry i (every slot is live: not for masked passes, nor for a tail from the start).
#define PN_WAVE_CAMERA_IN_PLACE 8u
#define PN_WAVE_MAKES_CAMERA_PATHS(mode, bounce) (((mode) & PN_WAVE_CAMERA_IN_PLACE) != 0u && (bounce) == 0u)
// PassPush.mode bit of trace.comp and the wavefront: the pixel estimates buffer holds each pixel's
// value so far (the viewer's history); without it a pass that adds to the accumulation buffer
// estimates from its sums, and one that replaces them has no estimate (lib/trace_outputs.glsl).
#define PN_TRACE_PIXEL_ESTIMATES 16u
#define PN_GBUFFER_SUBPIXEL 1u    // PassPush.mode bit of gbuffer.comp: trace cell passIndex of a 4x4 grid in the pixel
// GBufferTexel.flags bit: the pixel bypasses the a-trous filter (its raw mean is shown) and is no
// tap for its neighbours: a surface the camera sees emit (its light is not illumination times
// albedo, and blurring it spreads its glow; Doom's unseen sector light does not count), a window
// onto the sky, a sprite (a card whose texture's cut-out edges no normal or depth guide sees).
// The sky bypasses too, as any pixel whose primary ray missed.
#define PN_GBUFFER_UNFILTERED 1u
#define PN_ATROUS_LAST 1u        // PassPush.mode bit: the last a-trous pass multiplies the albedo back
#define PN_ATROUS_DISPLAY 2u     // PassPush.mode bit: ... and tone-maps it into the display (no debug view over it)
// PassPush.mode bit: ... and shows the filter alone, not weighed against the running mean (atrous.comp's
// blendWithMean), which never converges at rest: for measurements and tests of what the blend keeps.
#define PN_ATROUS_FILTER_ONLY 4u
// The denoiser's per-pixel guide, written by temporal.comp: xyz = the shading normal, w = the
// linear depth (0: the primary ray missed). 16 bytes instead of a 48-byte GBufferTexel per tap
// keeps the 25-tap filter in cache; plain floats rather than an 8-byte octahedral normal, because
// decoding (a normalize) at every tap cost more than the bytes (18% of the filter on the H200).
#define PN_DENOISE_GUIDE_BYTES 16u

// What the primary ray saw at a pixel's centre, 48 bytes.
PN_STRUCT(GBufferTexel) {
    vec3 normal;     // shading normal, unit, facing the camera; zero where the ray missed
    float depth;     // linear depth (distance along cameraForward); 0 where the ray missed
    vec3 albedo;     // textured base colour at the hit, what the denoiser divides out
    uint surfaceId;  // material + 1 (0: miss); a change at a pixel means a different surface
    vec2 motion;     // pixels from here to where the same point was in the previous frame (camera and object motion)
    float prevDepth; // the point's linear depth in the previous frame's camera, where it was then (0: miss)
    uint flags;      // PN_GBUFFER_* bits
};

// Push constants of the box overlay (boxes.comp), 16 bytes.
PN_STRUCT(BoxOverlayPush) {
    uint boxCount;    // boxes in the overlay buffer, at most PN_MAX_OVERLAY_BOXES
    float lineWidth;  // pixels: a pixel centre this close to a projected box edge is outlined
    uint pad0;
    uint pad1;
};

// The temporal accumulation of one pixel, 32 bytes.
PN_STRUCT(HistoryTexel) {
    vec3 color;     // running mean of radiance
    float samples;  // N of the running mean (capped while the camera moves)
    float moment1;  // running mean of per-sample luminance
    float moment2;  // running mean of per-sample squared luminance (variance = m2 - m1^2)
    float meanVariance;  // variance of `color`'s luminance as an estimate (written for the denoiser; never read back)
    float pad1;
};

// Settings of the viewer's passes (uniform buffer), 128 bytes. The previous camera is what
// reprojection projects into: it plays the role of the previous view-projection matrix.
PN_STRUCT(ViewerUniforms) {
    vec3 prevCameraPosition;
    float prevTanHalfFovY;
    vec3 prevCameraRight;
    float prevAspect;
    vec3 prevCameraUp;
    uint historyValid;     // 0: no usable history (first frame, reset, lighting changed)
    vec3 prevCameraForward;
    uint cameraMoved;      // 0: exact running mean; else reproject, reject, clamp and blend
    float exposure;        // stops
    uint toneMapper;       // PN_TONEMAP_*
    uint debugMode;        // PN_DEBUG_*
    uint samplesPerFrame;  // paths per pixel the trace pass added this frame
    float clampSigma;      // history is clamped to the neighbourhood's mean +- clampSigma * sigma (0: off)
    float depthTolerance;  // relative depth difference above which history is disoccluded
    float normalTolerance; // cosine below which history is disoccluded
    float maxHistory;      // cap on N while moving: the blend weight never falls below 1/maxHistory
    float sigmaLuminance;  // a-trous edge stopping: luminance, in standard deviations
    float sigmaNormal;     // exponent on the normals' cosine
    float sigmaDepth;      // relative depth difference per pixel of step
    float heatMax;         // heat-map count shown as the hottest colour
    uint denoise;          // nonzero: the tonemap input is the denoiser's output
    float debugOpacity;    // the debug view blended over the image: 1 shows only the view, 0 only the image
    uint debugInset;       // nonzero: the debug view in a small window over the image (PN_DEBUG_INSET_*)
    uint gbufferReused;    // nonzero: both G-buffers hold this still view (last frame's guide stands too)
};

// Largest counts of a heat-map frame (for the legend), 16 bytes. heatmap.comp writes a pixel's
// own counts as a vec4 (nodes, triangles, leaf depth, leaf primitives; the last two 0 on a miss).
PN_STRUCT(HeatCounters) {
    uint maxNodes;
    uint maxTris;
    uint maxLeafDepth;
    uint maxLeafTris;
};

// Per-dispatch constants, 32 bytes.
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

// The wavefront pass's queue counts and the indirect dispatch sizes computed from them
// (wave_args.comp), 64 bytes.
PN_STRUCT(WaveControl) {
    uint rayCount[2];    // live paths in each queue (read at bounce b: rayCount[b & 1])
    uint shadowCount;    // shadow rays queued by the last shade pass
    uint shadowLive;     // the shadow count the pending shadow pass reads (shadowCount is refilled meanwhile)
    uint extendGroups[4];  // VkDispatchIndirectCommand (x, y, z) + pad, for extend and shade
    uint shadowGroups[4];  // VkDispatchIndirectCommand, for the shadow pass
    uint tailGroups[4];    // VkDispatchIndirectCommand, for the tail (the live paths to their end)
};

// Counters written by the trace pass: rays only when PassPush.countRays is set. The buffer holds
// PN_RAY_COUNTER_LANES of them, 128 bytes apart; each workgroup adds to one lane, so that the
// atomics of a frame's hundred thousand subgroups do not all queue on one address (on an H200 one
// address cost Cornell's 1080p frame 0.15 ms). The host sums the lanes (render/ray_counters.h).
#define PN_RAY_COUNTER_LANES 64u
PN_STRUCT(RayCounters) {
    uint closestRays;
    uint shadowRays;
    uint invalidSamples;  // NaN or infinite path samples (always counted; dropped from the image)
    // PN_FEATURE_FRAME_STATS only: primitives (triangles, spheres, sprites) tested by the walks,
    // closest-hit rays that hit something, shadow rays that found an occluder.
    uint primitivesTested;
    uint closestHits;
    uint shadowBlocked;
    uint pad[26];
};

// A ray for the test and benchmark kernels, 32 bytes.
PN_STRUCT(RayDesc) {
    vec3 origin;
    float tMax;
    vec3 direction;
    float pad;
};

// A hit from the test and benchmark kernels, 16 bytes.
PN_STRUCT(HitRecord) {
    float t;
    uint triangle;   // PN_NO_HIT when nothing was hit
    float u;
    float v;
};

// A primary hit kept by the ray benchmark for its shadow and bounce passes, 32 bytes.
PN_STRUCT(SurfacePoint) {
    vec3 position;
    uint valid;
    vec3 normal;
    float pad;
};

// One query of the BSDF test kernel, 32 bytes: the material is materials[0] of the test scene.
PN_STRUCT(BsdfTestQuery) {
    vec3 wo;        // local shading frame, z = the normal on wo's side
    uint entering;  // nonzero: wo is outside the material (glass refracts with eta = ior)
    vec3 wi;        // PN_BSDF_TEST_EVAL: the direction to evaluate
    uint pad;
};

// One result of the BSDF test kernel, 32 bytes.
PN_STRUCT(BsdfTestResult) {
    vec3 wi;        // sampled direction (PN_BSDF_TEST_SAMPLE)
    float pdf;      // solid-angle pdf (of the sampled direction, or of the query's wi)
    vec3 value;     // weight = f cos / pdf (sample), or f (eval)
    uint isDelta;   // the sample came from a delta lobe (its pdf is that lobe's probability)
};

#ifdef __cplusplus
// Layout checks: every offset the shader relies on. A failure here means a field moved.
static_assert(PN_LIGHT_GRID_FIRST_TABLE < PN_LIGHT_GRID_PREFIXES && PN_LIGHT_GRID_MAX_LEVELS < 15,
              "the light grid's header words come before its prefixes; an alias fits in 15 bits");
static_assert(PN_LIGHT_GRID_ALIAS_SHIFT == PN_LIGHT_GRID_MASS_BITS + 1 &&
                  PN_LIGHT_GRID_THRESHOLD_MASK == (1u << PN_LIGHT_GRID_ALIAS_SHIFT) - 1u,
              "an alias entry's threshold (up to a whole 2^16) fits below its alias");
static_assert(sizeof(BvhNode) == 32 && offsetof(BvhNode, firstOrRight) == 12 &&
              offsetof(BvhNode, boundsMax) == 16 && offsetof(BvhNode, triCount) == 28);
static_assert(sizeof(WideNode) == 80 && offsetof(WideNode, exponentsMask) == 12 && offsetof(WideNode, childBase) == 16 &&
              offsetof(WideNode, primBase) == 20 && offsetof(WideNode, meta) == 24 && offsetof(WideNode, loX) == 32 &&
              offsetof(WideNode, hiX) == 40 && offsetof(WideNode, loY) == 48 && offsetof(WideNode, loZ) == 64 &&
              offsetof(WideNode, hiZ) == 72);
static_assert(sizeof(TriVerts) == 48 && offsetof(TriVerts, flags) == 12 && offsetof(TriVerts, e1) == 16 &&
              offsetof(TriVerts, uvIndex) == 28 && offsetof(TriVerts, e2) == 32);
static_assert(sizeof(TriAttribs) == 24 && offsetof(TriAttribs, lightIndex) == 4 && offsetof(TriAttribs, area) == 8 &&
              offsetof(TriAttribs, n0) == 12 && offsetof(TriAttribs, n2) == 20);
static_assert(sizeof(TriUvs) == 24 && offsetof(TriUvs, uv1) == 8 && offsetof(TriUvs, uv2) == 16);
static_assert(sizeof(Material) == 96 && offsetof(Material, flags) == 12 &&
              offsetof(Material, emission) == 16 && offsetof(Material, alphaCutoff) == 28 &&
              offsetof(Material, absorption) == 32 && offsetof(Material, ior) == 44 &&
              offsetof(Material, metallic) == 48 && offsetof(Material, roughness) == 52 &&
              offsetof(Material, transmission) == 56 && offsetof(Material, specular) == 60 &&
              offsetof(Material, albedoTexture) == 64 && offsetof(Material, albedoWrap) == 68 &&
              offsetof(Material, metallicRoughnessTexture) == 72 && offsetof(Material, normalTexture) == 80 &&
              offsetof(Material, emissionTexture) == 88 && offsetof(Material, emissionWrap) == 92);
static_assert(sizeof(TextureInfo) == 32 && offsetof(TextureInfo, flags) == 12 && offsetof(TextureInfo, frameCount) == 16 &&
              offsetof(TextureInfo, frame) == 20 && offsetof(TextureInfo, secondsPerFrame) == 24);
static_assert(sizeof(LightRef) == 16 && offsetof(LightRef, index) == 4 && offsetof(LightRef, trailHi) == 12);
static_assert(sizeof(LightTreeNode) == 48 && offsetof(LightTreeNode, radius) == 12 && offsetof(LightTreeNode, axis) == 16 &&
              offsetof(LightTreeNode, phi) == 28 && offsetof(LightTreeNode, cosThetaO) == 32 &&
              offsetof(LightTreeNode, childOrLight) == 44);
static_assert(sizeof(LightNode) == 64 && offsetof(LightNode, phi) == 12 && offsetof(LightNode, boundsMax) == 16 &&
              offsetof(LightNode, cosThetaO) == 28 && offsetof(LightNode, axis) == 32 &&
              offsetof(LightNode, cosThetaE) == 44 && offsetof(LightNode, childOrLight) == 48 &&
              offsetof(LightNode, twoSided) == 52 && offsetof(LightNode, sinThetaO) == 56 &&
              offsetof(LightNode, minDistance2) == 60);
static_assert(sizeof(EnvAlias) == 16 && offsetof(EnvAlias, alias) == 4 && offsetof(EnvAlias, pdf) == 8);
static_assert(sizeof(Instance) == 112 && offsetof(Instance, worldToObject) == 48 && offsetof(Instance, rootNode) == 96 &&
              offsetof(Instance, firstPrimitive) == 100 && offsetof(Instance, primitiveCount) == 104 &&
              offsetof(Instance, id) == 108);
static_assert(sizeof(FrameUniforms) == 208 && offsetof(FrameUniforms, textureSaturation) == 188 &&
              offsetof(FrameUniforms, renderDistance) == 192 && offsetof(FrameUniforms, flags) == 196 && offsetof(FrameUniforms, topLightCount) == 160 &&
              offsetof(FrameUniforms, instanceCount) == 152 && offsetof(FrameUniforms, topRoot) == 176 &&
              offsetof(FrameUniforms, envLuminance) == 164 && offsetof(FrameUniforms, lightPickUniform) == 172 && offsetof(FrameUniforms, tanHalfFovY) == 12 &&
              offsetof(FrameUniforms, cameraRight) == 16 && offsetof(FrameUniforms, aspect) == 28 &&
              offsetof(FrameUniforms, cameraUp) == 32 && offsetof(FrameUniforms, width) == 44 &&
              offsetof(FrameUniforms, cameraForward) == 48 && offsetof(FrameUniforms, height) == 60 &&
              offsetof(FrameUniforms, maxBounces) == 64 && offsetof(FrameUniforms, samplesPerPass) == 92 &&
              offsetof(FrameUniforms, background) == 96 && offsetof(FrameUniforms, punctualCount) == 108 &&
              offsetof(FrameUniforms, lensRadius) == 112 && offsetof(FrameUniforms, sphereLightCount) == 124 &&
              offsetof(FrameUniforms, envWidth) == 128 && offsetof(FrameUniforms, envHeight) == 140 &&
              offsetof(FrameUniforms, misMode) == 144 && offsetof(FrameUniforms, debugMode) == 148 &&
              offsetof(FrameUniforms, time) == 156);
static_assert(sizeof(PunctualLight) == 64 && offsetof(PunctualLight, type) == 12 &&
              offsetof(PunctualLight, range) == 28 && offsetof(PunctualLight, direction) == 32 &&
              offsetof(PunctualLight, cosOuter) == 44 &&
              offsetof(PunctualLight, coneOneMinusCos) == 56);
static_assert(sizeof(SphereLight) == 64 && offsetof(SphereLight, radius) == 12 &&
              offsetof(SphereLight, radiance) == 16 &&
              offsetof(SphereLight, spotDirection) == 32 && offsetof(SphereLight, cosOuter) == 44 &&
              offsetof(SphereLight, cosInner) == 48 &&
              offsetof(SphereLight, primitive) == 56);
static_assert(sizeof(BvhPair) == 64 && offsetof(BvhPair, left) == 12 && offsetof(BvhPair, leafCount) == 28 &&
              offsetof(BvhPair, rightMin) == 32 && offsetof(BvhPair, right) == 44 && offsetof(BvhPair, rightMax) == 48);
static_assert(sizeof(PassPush) == 48 && offsetof(PassPush, countRays) == 12 && offsetof(PassPush, tileX) == 16 &&
              offsetof(PassPush, tileY) == 20 && offsetof(PassPush, tileWidth) == 24 && offsetof(PassPush, waveStride) == 32 &&
              offsetof(PassPush, waveBounce) == 36 && offsetof(PassPush, waveTailPaths) == 40);
static_assert(sizeof(WaveControl) == 64 && offsetof(WaveControl, shadowLive) == 12 &&
              offsetof(WaveControl, extendGroups) == 16 && offsetof(WaveControl, shadowGroups) == 32 &&
              offsetof(WaveControl, tailGroups) == 48);
static_assert(sizeof(RayCounters) == 128);
static_assert(sizeof(RayDesc) == 32 && offsetof(RayDesc, tMax) == 12 && offsetof(RayDesc, direction) == 16);
static_assert(sizeof(HitRecord) == 16 && offsetof(HitRecord, v) == 12);
static_assert(sizeof(BsdfTestQuery) == 32 && offsetof(BsdfTestQuery, entering) == 12 &&
              offsetof(BsdfTestQuery, wi) == 16);
static_assert(sizeof(BsdfTestResult) == 32 && offsetof(BsdfTestResult, pdf) == 12 &&
              offsetof(BsdfTestResult, value) == 16 && offsetof(BsdfTestResult, isDelta) == 28);
static_assert(sizeof(SurfacePoint) == 32 && offsetof(SurfacePoint, valid) == 12 &&
              offsetof(SurfacePoint, normal) == 16);
static_assert(sizeof(GBufferTexel) == 48 && offsetof(GBufferTexel, depth) == 12 &&
              offsetof(GBufferTexel, albedo) == 16 && offsetof(GBufferTexel, surfaceId) == 28 &&
              offsetof(GBufferTexel, motion) == 32 && offsetof(GBufferTexel, flags) == 44);
static_assert(sizeof(HistoryTexel) == 32 && offsetof(HistoryTexel, samples) == 12 &&
              offsetof(HistoryTexel, moment1) == 16 && offsetof(HistoryTexel, moment2) == 20 &&
              offsetof(HistoryTexel, meanVariance) == 24);
static_assert(sizeof(BoxOverlayPush) == 16 && offsetof(BoxOverlayPush, lineWidth) == 4);
static_assert(sizeof(ViewerUniforms) == 128 && offsetof(ViewerUniforms, prevTanHalfFovY) == 12 &&
              offsetof(ViewerUniforms, prevCameraRight) == 16 && offsetof(ViewerUniforms, prevAspect) == 28 &&
              offsetof(ViewerUniforms, prevCameraUp) == 32 && offsetof(ViewerUniforms, historyValid) == 44 &&
              offsetof(ViewerUniforms, prevCameraForward) == 48 && offsetof(ViewerUniforms, cameraMoved) == 60 &&
              offsetof(ViewerUniforms, exposure) == 64 && offsetof(ViewerUniforms, samplesPerFrame) == 76 &&
              offsetof(ViewerUniforms, clampSigma) == 80 && offsetof(ViewerUniforms, maxHistory) == 92 &&
              offsetof(ViewerUniforms, sigmaLuminance) == 96 && offsetof(ViewerUniforms, heatMax) == 108 &&
              offsetof(ViewerUniforms, denoise) == 112 && offsetof(ViewerUniforms, debugOpacity) == 116 &&
              offsetof(ViewerUniforms, debugInset) == 120);
static_assert(sizeof(HeatCounters) == 16 && offsetof(HeatCounters, maxLeafDepth) == 8 &&
              offsetof(HeatCounters, maxLeafTris) == 12);
}  // namespace penumbra::shader
#endif
#endif
