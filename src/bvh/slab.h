// The CPU slab test shared by the binary and wide reference traversals.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "bvh/traverse_cpu.h"
#include "core/aabb.h"

namespace penumbra::bvh {

// Per-ray slab-test setup. A zero direction component gives an infinite inverse; the near and
// far planes are chosen by the sign bit (so -0 counts as negative), which keeps every product
// either a signed infinity (origin outside the slab on that side: the box is missed, or the
// axis does not limit t) or NaN (origin exactly on a face). NaN is then dropped by the argument
// order of std::max/std::min below, i.e. an axis-parallel ray through a face counts as inside
// that slab, which is what a closed box needs for triangles lying in the face.
struct SlabRay {
    Vec3 origin, invDir;
    bool negative[3];

    explicit SlabRay(const Ray& ray) : origin(ray.origin) {
        for (int a = 0; a < 3; ++a) {
            invDir[a] = 1.0f / ray.direction[a];
            negative[a] = std::signbit(ray.direction[a]);
        }
    }

    // Entry distance of the box clipped to [0, tMax], or +inf when the ray misses it.
    float enter(Vec3 lo, Vec3 hi, float tMax) const {
        float entry = 0.0f, exit = tMax;
        for (int a = 0; a < 3; ++a) {
            float tNear = ((negative[a] ? hi[a] : lo[a]) - origin[a]) * invDir[a];
            float tFar = ((negative[a] ? lo[a] : hi[a]) - origin[a]) * invDir[a];
            entry = std::max(entry, tNear);  // (entry < NaN) is false: keeps entry
            exit = std::min(exit, tFar);     // (NaN < exit) is false: keeps exit
        }
        return entry <= exit * kSlabExitScale ? entry : std::numeric_limits<float>::infinity();
    }
};

}  // namespace penumbra::bvh
