// Affine transforms (3x4, row-major): enough for placing assets; no projective part needed.
#pragma once

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
Aabb transformBounds(const Aabb& box, const Affine& transform);

// a * b: apply b first, then a.
Affine operator*(const Affine& a, const Affine& b);

}  // namespace penumbra
