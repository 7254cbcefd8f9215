// Lights as the shaders sample them: the unified sampler's LightRefs, the light BVH, the light
// grid's header, punctual and sphere lights, the environment's alias table.
// Valid GLSL and C++ (see types.h); each struct's size and offsets are checked beside it.
#ifndef PENUMBRA_SHADER_LIGHTS_H
#define PENUMBRA_SHADER_LIGHTS_H

#include "shared/prelude.h"

#ifdef __cplusplus
namespace penumbra::shader {
#endif

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
// walk's importance levels. It is a run of words after the tree's records in the same buffer, from
// FrameUniforms.lightGridOffset: a LightGridHeader; at PN_LIGHT_GRID_PREFIXES the cluster of every
// trail prefix of L bits (2^L words), then each cluster's PN_LIGHT_GRID_CLUSTER_WORDS words and
// the clusters' light entries; the header names where the later sections start. Every word
// offset is from the grid's first word.
//   clusters' words:  node word, level, first light entry, lights (0: walk below the cluster)
//   light entries:    per cluster an alias table over its lights by power (what the walk below
//                     it would choose), one entry per light: (threshold | alias << 17, LightRef)
//   firstMass:        per LightRef its mass in its cluster's table
//   firstTree:        per cell (x fastest) and bin, the tree root's bound over the cell and bin
//                     (a float: the tree's weight against the top-level lights)
//   firstTable:       per cell and bin, one alias entry per cluster: (threshold | alias << 17, mass)
// The header, 64 bytes. lightGridOffset is a multiple of its 16 words, so that GLSL reads it as an
// element of a LightGridHeader array over the same buffer (lib/light_sampler.glsl).
PN_STRUCT(LightGridHeader) {
    vec3 origin;            // the grid's lower corner
    float inverseCellSize;  // 1 / the edge of its cubic cells
    uint cellsX;            // cells along x, y and z
    uint cellsY;
    uint cellsZ;
    uint clusterCount;      // clusters the tables pick among
    uint levels;            // L, the tree level of the clusters
    uint firstTable;        // word of the first cell and bin's alias table
    uint firstMass;         // word of the first LightRef's mass
    uint firstTree;         // word of the first cell and bin's tree weight
    uint pad[4];
};
#ifdef __cplusplus
static_assert(sizeof(LightGridHeader) == 64 && offsetof(LightGridHeader, inverseCellSize) == 12 &&
              offsetof(LightGridHeader, cellsX) == 16 && offsetof(LightGridHeader, clusterCount) == 28 &&
              offsetof(LightGridHeader, levels) == 32 && offsetof(LightGridHeader, firstTable) == 36 &&
              offsetof(LightGridHeader, firstMass) == 40 && offsetof(LightGridHeader, firstTree) == 44);
#endif
#define PN_LIGHT_GRID_PREFIXES 16u         // word of the prefix -> cluster map: right after the header
#define PN_LIGHT_GRID_CLUSTER_WORDS 4u     // per cluster: node word, level, first light entry, lights (0: walk below)
#define PN_LIGHT_GRID_MAX_LEVELS 8u        // at most 256 clusters
#define PN_LIGHT_GRID_BINS 6u              // shading normals by their largest component: +x, -x, +y, -y, +z, -z
#define PN_LIGHT_GRID_MASS_BITS 16u        // an entry's threshold is out of 2^16; a table's masses sum to 2^16 x clusters
#define PN_LIGHT_GRID_ALIAS_SHIFT 17u      // an alias entry's word: threshold (0 to 2^16, 17 bits) | alias << 17
#define PN_LIGHT_GRID_THRESHOLD_MASK 0x1ffffu
#ifdef __cplusplus
static_assert(sizeof(LightGridHeader) == 4 * PN_LIGHT_GRID_PREFIXES && PN_LIGHT_GRID_MAX_LEVELS < 15,
              "the light grid's prefixes follow its header; an alias fits in 15 bits");
static_assert(PN_LIGHT_GRID_ALIAS_SHIFT == PN_LIGHT_GRID_MASS_BITS + 1 &&
                  PN_LIGHT_GRID_THRESHOLD_MASK == (1u << PN_LIGHT_GRID_ALIAS_SHIFT) - 1u,
              "an alias entry's threshold (up to a whole 2^16) fits below its alias");
#endif
#define PN_LIGHT_NODE_LEAF 0x80000000u       // LightNode / LightTreeNode.childOrLight: a leaf
#define PN_LIGHT_NODE_TWO_SIDED 0x40000000u  // LightTreeNode.childOrLight: emits both ways
#define PN_LIGHT_NODE_INDEX 0x3fffffffu      // LightTreeNode.childOrLight: the child record or the LightRef

// One texel of the environment's alias table, 16 bytes. The table has one entry per texel of the
// equirectangular map (row-major, top row = +y), so entry i is also texel i.
PN_STRUCT(EnvAlias) {
    float threshold;  // keep texel i when u < threshold, else take the alias
    uint alias;       // index of the alias texel
    float pdf;        // solid-angle pdf of directions inside texel i (its pmf / its solid angle)
    float pad;
};
#ifdef __cplusplus
static_assert(sizeof(EnvAlias) == 16 && offsetof(EnvAlias, alias) == 4 && offsetof(EnvAlias, pdf) == 8);
#endif

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
#ifdef __cplusplus
static_assert(sizeof(LightRef) == 16 && offsetof(LightRef, index) == 4 && offsetof(LightRef, trailHi) == 12);
#endif

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
#ifdef __cplusplus
static_assert(sizeof(LightNode) == 64 && offsetof(LightNode, phi) == 12 && offsetof(LightNode, boundsMax) == 16 &&
              offsetof(LightNode, cosThetaO) == 28 && offsetof(LightNode, axis) == 32 &&
              offsetof(LightNode, cosThetaE) == 44 && offsetof(LightNode, childOrLight) == 48 &&
              offsetof(LightNode, twoSided) == 52 && offsetof(LightNode, sinThetaO) == 56 &&
              offsetof(LightNode, minDistance2) == 60);
#endif

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
#ifdef __cplusplus
static_assert(sizeof(LightTreeNode) == 48 && offsetof(LightTreeNode, radius) == 12 && offsetof(LightTreeNode, axis) == 16 &&
              offsetof(LightTreeNode, phi) == 28 && offsetof(LightTreeNode, cosThetaO) == 32 &&
              offsetof(LightTreeNode, childOrLight) == 44);
#endif

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
#ifdef __cplusplus
static_assert(sizeof(PunctualLight) == 64 && offsetof(PunctualLight, type) == 12 &&
              offsetof(PunctualLight, range) == 28 && offsetof(PunctualLight, direction) == 32 &&
              offsetof(PunctualLight, cosOuter) == 44 &&
              offsetof(PunctualLight, coneOneMinusCos) == 56);
#endif

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
#ifdef __cplusplus
static_assert(sizeof(SphereLight) == 64 && offsetof(SphereLight, radius) == 12 &&
              offsetof(SphereLight, radiance) == 16 &&
              offsetof(SphereLight, spotDirection) == 32 && offsetof(SphereLight, cosOuter) == 44 &&
              offsetof(SphereLight, cosInner) == 48 &&
              offsetof(SphereLight, primitive) == 56);
#endif

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
