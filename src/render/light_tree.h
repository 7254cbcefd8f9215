// The light BVH: a binary tree over bounded lights (emissive triangles and spheres, point and
// spot lights) whose nodes bound where the lights below are, how much they emit and in which
// directions, so a shading point can descend it choosing children by their estimated
// contribution (Conty Estevez & Kulla 2018, "Importance sampling of many lights with adaptive
// tree splitting"; pbrt-v4's BVHLightSampler). Built on the CPU once per scene.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/aabb.h"
#include "shared/types.h"

namespace penumbra {

// Where a set of lights is and how it emits. Normals lie within thetaO of axis, and light
// leaves at most thetaE beyond a normal (pi/2 for a Lambertian emitter).
struct LightBounds {
    Aabb bounds;
    float phi = 0;           // power bound: radiance x area, or intensity (irradiance at 1 m)
    Vec3 axis{0, 0, 1};      // unit
    float cosThetaO = 1;     // cos of the normals' spread about axis (-1: every direction)
    float cosThetaE = 0;     // cos of the emission spread beyond a normal
    bool twoSided = false;   // emits on both sides of its normals
};

// The smallest bounds holding both (a with phi 0 is the empty set).
LightBounds unionOf(const LightBounds& a, const LightBounds& b);

// A light at a point emitting in every direction (a point light), or in a cone (a spot light:
// full strength inside cosInner, none beyond cosOuter).
LightBounds pointLightBounds(Vec3 position, float intensity);
LightBounds spotLightBounds(Vec3 position, Vec3 direction, float intensity, float cosInner, float cosOuter);

// The node written for a set of lights: interior (childOrLight = second child) or leaf.
shader::LightNode toLightNode(const LightBounds& b, std::uint32_t childOrLight);

struct LightTree {
    // Depth-first; the root is nodes[0]; an interior node's first child follows it. Child and
    // leaf indices are relative to nodes[0] plus nodeBase (see buildLightTree).
    std::vector<shader::LightNode> nodes;
    std::vector<std::uint64_t> trails;  // per input light: bit d set where the path took the second child
};

// Builds the tree over lights[i] (each with phi > 0); leaf i refers to LightRef firstRef + i, and
// node indices stored in the nodes are offset by nodeBase (where nodes[0] lands in the buffer).
// Splits minimise pbrt-v4's surface-area-orientation cost over 12 bins per axis.
LightTree buildLightTree(std::span<const LightBounds> lights, std::uint32_t firstRef, std::uint32_t nodeBase);

// The tree (built with nodeBase 0) as the shaders walk it (shared/types.h, LightTreeNode): the
// root at record 0, each interior node's children side by side; same child order, so the trails
// still lead to every light. Empty for an empty tree.
std::vector<shader::LightTreeNode> compactLightTree(const LightTree& tree);

// How deep a compact tree's leaves lie, counting the root as depth 1 as bvh::treeDepth does: the
// levels a shading point's walk visits.
struct LightTreeDepth {
    std::uint32_t max = 0;
    double mean = 0;  // over leaves
};
LightTreeDepth lightTreeDepth(std::span<const shader::LightTreeNode> records);

}  // namespace penumbra
