// The triangle as the BVH builder sees it, and its conversion to the GPU's hot layout.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/aabb.h"
#include "core/vec.h"
#include "shared/types.h"

namespace penumbra {
struct SceneTriangle;
}

namespace penumbra::bvh {

struct Triangle {
    Vec3 v0, v1, v2;
};

Aabb bounds(const Triangle& tri);

// Edges are precomputed so that traversal on either side of the bus does no subtraction per test.
shader::TriVerts toTriVerts(const Triangle& tri);

// The cold per-triangle data shading reads (normals, material, area; not a light: lightIndex
// is PN_NO_LIGHT until the light list claims it), in the space of t's positions.
shader::TriAttribs toTriAttribs(const SceneTriangle& t);

// The TriVerts::uvIndex of t's texture coordinates: 0 (the shared all-zero entry, added if uvs is
// empty) when they are all zero, as for every triangle of a mesh without UVs, else a new entry
// appended to uvs.
std::uint32_t appendTriUvs(const SceneTriangle& t, std::vector<shader::TriUvs>& uvs);

// Positions only: the BVH needs nothing else from the scene.
std::vector<Triangle> trianglesOf(std::span<const SceneTriangle> sceneTriangles);

}  // namespace penumbra::bvh
