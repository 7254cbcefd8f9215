// The triangle as the BVH builder sees it, and its conversion to the GPU's hot layout.
#pragma once

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

// The cold per-triangle data shading reads (normals, uvs, material, area; not a light: lightIndex
// is PN_NO_LIGHT until the light list claims it), in the space of t's positions.
shader::TriAttribs toTriAttribs(const SceneTriangle& t);

// Positions only: the BVH needs nothing else from the scene.
std::vector<Triangle> trianglesOf(std::span<const SceneTriangle> sceneTriangles);

}  // namespace penumbra::bvh
