// Four-wide float vectors for the BVH builder's inner loops, through the GCC/Clang vector
// extension: one code path that becomes SSE on x86-64 and NEON on ARM, with no intrinsics.
// Boxes use lanes x, y, z; lane w is kept at 0 wherever arithmetic touches it.
#pragma once

#include <cstdint>
#include <limits>

#include "core/aabb.h"
#include "core/vec.h"

namespace penumbra::bvh::simd {

using F4 = float __attribute__((vector_size(16)));
using I4 = std::int32_t __attribute__((vector_size(16)));

inline F4 splat(float s) { return F4{s, s, s, s}; }
inline F4 vec(Vec3 v) { return F4{v.x, v.y, v.z, 0.0f}; }
inline Vec3 vec3(F4 v) { return {v[0], v[1], v[2]}; }

// a < b ? a : b lane by lane: exactly std::min(b, a)'s choice, and one minps/maxps instruction.
inline F4 vmin(F4 a, F4 b) { return a < b ? a : b; }
inline F4 vmax(F4 a, F4 b) { return a > b ? a : b; }

// Lane w cleared, leaving x, y, z untouched (the builder keeps a primitive's index in lane w).
inline F4 xyz(F4 v) {
    const I4 mask{-1, -1, -1, 0};
    return F4(I4(v) & mask);
}

inline constexpr float kInf = std::numeric_limits<float>::infinity();
inline constexpr F4 kPosInf{kInf, kInf, kInf, kInf};
inline constexpr F4 kNegInf{-kInf, -kInf, -kInf, -kInf};

// A box in two vectors; starts empty (lo = +inf, hi = -inf).
struct Box4 {
    F4 lo = kPosInf, hi = kNegInf;

    void grow(F4 l, F4 h) {
        lo = vmin(lo, l);
        hi = vmax(hi, h);
    }
    void grow(const Box4& b) { grow(b.lo, b.hi); }
    void grow(F4 p) { grow(p, p); }
    bool empty() const { return lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]; }
    // The same arithmetic, in the same order, as Aabb::halfArea (0 when empty).
    float halfArea() const {
        if (empty()) return 0.0f;
        F4 e = hi - lo;
        return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
    }
    Aabb aabb() const { return {vec3(lo), vec3(hi)}; }
};

}  // namespace penumbra::bvh::simd
