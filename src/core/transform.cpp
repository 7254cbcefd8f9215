#include "core/transform.h"
#include "shared/constants.h"

#include <cmath>

namespace penumbra {

float Affine::determinant() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

Vec3 Affine::normal(Vec3 n) const {
    // The cofactor matrix C is det * inverse transpose; its scale does not matter after
    // normalising, but its sign does, so multiply by the determinant's sign. Its rows are the
    // cross products of the rows of the linear part, so C n is their dot products with n (not a
    // sum of rows weighted by n's components: that would be C^T n, the inverse without the
    // transpose, which turns normals the wrong way under a rotation).
    Vec3 r0{m[0][0], m[0][1], m[0][2]}, r1{m[1][0], m[1][1], m[1][2]}, r2{m[2][0], m[2][1], m[2][2]};
    Vec3 c0 = cross(r1, r2), c1 = cross(r2, r0), c2 = cross(r0, r1);
    Vec3 out{dot(c0, n), dot(c1, n), dot(c2, n)};
    return normalize(determinant() < 0 ? -out : out);
}

Affine Affine::inverse() const {
    // The inverse of the linear part is the transposed cofactor matrix over the determinant; the
    // translation is then undone by -inverse * t.
    Vec3 r0{m[0][0], m[0][1], m[0][2]}, r1{m[1][0], m[1][1], m[1][2]}, r2{m[2][0], m[2][1], m[2][2]};
    Vec3 c0 = cross(r1, r2), c1 = cross(r2, r0), c2 = cross(r0, r1);
    const float invDet = 1.0f / determinant();
    Affine inv;
    for (int i = 0; i < 3; ++i) {
        inv.m[i][0] = c0[i] * invDet;
        inv.m[i][1] = c1[i] * invDet;
        inv.m[i][2] = c2[i] * invDet;
    }
    const Vec3 t{m[0][3], m[1][3], m[2][3]};
    const Vec3 back = inv.vector(t);
    inv.m[0][3] = -back.x;
    inv.m[1][3] = -back.y;
    inv.m[2][3] = -back.z;
    return inv;
}

Affine Affine::translation(Vec3 t) {
    Affine a;
    a.m[0][3] = t.x;
    a.m[1][3] = t.y;
    a.m[2][3] = t.z;
    return a;
}

Affine Affine::scaling(Vec3 s) {
    Affine a;
    a.m[0][0] = s.x;
    a.m[1][1] = s.y;
    a.m[2][2] = s.z;
    return a;
}

Affine Affine::eulerDegrees(Vec3 d) {
    const float k = degreesToRadians(1.0f);
    auto rot = [](int axis, float radians) {
        Affine a;
        float c = std::cos(radians), s = std::sin(radians);
        int i = (axis + 1) % 3, j = (axis + 2) % 3;
        a.m[i][i] = c;
        a.m[i][j] = -s;
        a.m[j][i] = s;
        a.m[j][j] = c;
        return a;
    };
    return rot(2, d.z * k) * rot(1, d.y * k) * rot(0, d.x * k);
}

Affine operator*(const Affine& a, const Affine& b) {
    Affine r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) {
            float v = (j == 3) ? a.m[i][3] : 0.0f;
            for (int k = 0; k < 3; ++k) v += a.m[i][k] * b.m[k][j];
            r.m[i][j] = v;
        }
    return r;
}

}  // namespace penumbra
