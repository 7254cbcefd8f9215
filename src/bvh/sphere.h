// Analytic spheres as BVH primitives. A sphere occupies a TriVerts slot flagged PN_TRI_SPHERE
// (v0 = centre, e1.x = radius), so triangles and spheres share one BVH and one leaf range, and
// traversal branches on the flag only.
#pragma once

#include "core/aabb.h"
#include "core/vec.h"
#include "shared/types.h"

namespace penumbra::bvh {

Aabb sphereBounds(Vec3 center, float radius);

shader::TriVerts toSphereVerts(Vec3 center, float radius);

inline bool isSphere(const shader::TriVerts& slot) { return (slot.flags & PN_TRI_SPHERE) != 0; }

// The nearest root with t in (0, tMax) of |o + t d - c| = r, in the numerically stable form
// (Ray Tracing Gems ch. 7; pbrt-v4): the discriminant is formed from the distance of the centre
// to the ray's line, not from b^2 - 4ac, and the root nearer zero is c / q, not (-b + sqrt) / 2a.
// A ray that starts inside the sphere finds the exit point. shaders/lib/intersect.glsl is the
// same arithmetic in the same order.
bool intersectSphere(const shader::TriVerts& slot, const Ray& ray, float tMax, float& t);

}  // namespace penumbra::bvh
