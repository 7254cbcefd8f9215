// A UV sphere with smooth (radial) vertex normals, for tests that need shading normals that are
// not the faces' own: coarse enough that interpolated and geometric normals differ visibly.
#pragma once

#include <cmath>
#include <cstdint>

#include "scene/scene.h"
#include "shared/constants.h"

namespace penumbra::test {

// rings >= 2 bands from pole to pole, segments >= 3 around +y; faces wind counter-clockwise seen
// from outside, so the front faces and the normals point outward.
inline Mesh smoothSphere(Vec3 center, float radius, int rings, int segments,
                         std::uint32_t material) {
    Mesh m;
    m.name = "smooth sphere";
    m.material = material;
    for (int i = 0; i <= rings; ++i) {
        const float theta = kPiF * float(i) / float(rings);
        for (int j = 0; j <= segments; ++j) {
            const float phi = 2 * kPiF * float(j) / float(segments);
            const Vec3 n{std::sin(theta) * std::cos(phi), std::cos(theta),
                         -std::sin(theta) * std::sin(phi)};
            m.positions.push_back(center + n * radius);
            m.normals.push_back(n);
            m.uvs.push_back({float(j) / float(segments), float(i) / float(rings)});
        }
    }
    const auto at = [&](int i, int j) { return std::uint32_t(i * (segments + 1) + j); };
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            if (i > 0) m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
            if (i + 1 < rings)
                m.indices.insert(m.indices.end(), {at(i, j + 1), at(i + 1, j), at(i + 1, j + 1)});
        }
    return m;
}

}  // namespace penumbra::test
