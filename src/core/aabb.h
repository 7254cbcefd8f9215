// Axis-aligned bounding box and ray types shared by the BVH builder and the CPU traversal.
#pragma once

#include <limits>

#include "core/vec.h"

namespace penumbra {

struct Aabb {
    Vec3 lo{std::numeric_limits<float>::infinity()};
    Vec3 hi{-std::numeric_limits<float>::infinity()};

    void grow(Vec3 p) {
        lo = min(lo, p);
        hi = max(hi, p);
    }
    void grow(const Aabb& b) {
        lo = min(lo, b.lo);
        hi = max(hi, b.hi);
    }
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    Vec3 extent() const { return hi - lo; }
    Vec3 center() const { return (lo + hi) * 0.5f; }
    // Half the surface area: the SAH only needs areas up to a common factor.
    float halfArea() const {
        if (empty()) return 0.0f;
        Vec3 e = extent();
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
    float area() const { return 2.0f * halfArea(); }
};

struct Ray {
    Vec3 origin;
    Vec3 direction;  // need not be unit length; t is measured in units of it
    float tMax = std::numeric_limits<float>::infinity();
};

}  // namespace penumbra
