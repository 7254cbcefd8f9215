// Affine transforms (3x4, row-major): enough for placing assets; no projective part needed.
#pragma once

#include <cmath>
#include <limits>

#include "core/aabb.h"
#include "core/vec.h"

namespace penumbra {

struct Affine {
    float m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

    Vec3 point(Vec3 p) const {
        return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
                m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
                m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
    }
    Vec3 vector(Vec3 v) const {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    float determinant() const;
    // Normals transform by the inverse transpose of the linear part (then renormalise).
    Vec3 normal(Vec3 n) const;
    // The inverse transform (the linear part must be invertible: determinant() != 0).
    Affine inverse() const;

    static Affine translation(Vec3 t);
    static Affine scaling(Vec3 s);
    // Rotations about x, then y, then z (degrees), as in the JSON scene format.
    static Affine eulerDegrees(Vec3 degrees);
};

// The box around `box` after `transform` (its eight corners transformed); empty stays empty.
// Inline: a top-level rebuild calls it for every instance, every frame.
inline Aabb transformBounds(const Aabb& box, const Affine& transform) {
    Aabb out;
    if (box.empty()) return out;
    // Arvo's method (Graphics Gems, 1990): the centre goes through the transform, the half extent
    // through the absolute values of its linear part; in exact arithmetic the box around the
    // eight transformed corners, at a third of the work. Padded by the rounding error of a sum of
    // such terms (relative to their magnitudes, since they may cancel), so it never comes out
    // smaller than the corners' box as float arithmetic computes them.
    const Vec3 c = (box.lo + box.hi) * 0.5f, e = (box.hi - box.lo) * 0.5f;
    const Vec3 reach{std::abs(c.x) + e.x, std::abs(c.y) + e.y, std::abs(c.z) + e.z};
    const Vec3 centre = transform.point(c);
    Vec3 extent;
    for (int i = 0; i < 3; ++i) {
        const float* row = transform.m[i];
        const float half = std::abs(row[0]) * e.x + std::abs(row[1]) * e.y + std::abs(row[2]) * e.z;
        const float magnitude =
            std::abs(row[0]) * reach.x + std::abs(row[1]) * reach.y + std::abs(row[2]) * reach.z + std::abs(row[3]);
        extent[i] = half + magnitude * (8.0f * std::numeric_limits<float>::epsilon());
    }
    out.lo = centre - extent;
    out.hi = centre + extent;
    return out;
}

// a * b: apply b first, then a.
Affine operator*(const Affine& a, const Affine& b);

}  // namespace penumbra
