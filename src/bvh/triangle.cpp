#include "bvh/triangle.h"

#include "core/error.h"
#include "scene/scene.h"
#include "shared/unit_vector.h"

namespace penumbra::bvh {

Aabb bounds(const Triangle& tri) {
    Aabb box;
    box.grow(tri.v0);
    box.grow(tri.v1);
    box.grow(tri.v2);
    return box;
}

shader::TriVerts toTriVerts(const Triangle& tri) {
    shader::TriVerts out{};
    out.v0 = tri.v0;
    out.e1 = tri.v1 - tri.v0;
    out.e2 = tri.v2 - tri.v0;
    return out;
}

shader::TriAttribs toTriAttribs(const SceneTriangle& t) {
    shader::TriAttribs a{};
    a.n0 = shader::packUnitVector(t.n[0]);
    a.n1 = shader::packUnitVector(t.n[1]);
    a.n2 = shader::packUnitVector(t.n[2]);
    a.materialId = t.material;
    a.lightIndex = PN_NO_LIGHT;
    a.area = 0.5f * length(cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
    return a;
}

std::uint32_t appendTriUvs(const SceneTriangle& t, std::vector<shader::TriUvs>& uvs) {
    if (uvs.empty()) uvs.emplace_back();
    bool allZero = true;
    for (const Vec2& uv : t.uv) allZero = allZero && uv.x == 0.0f && uv.y == 0.0f;
    if (allZero) return 0;
    PN_CHECK(uvs.size() < PN_NO_HIT);  // at most one entry per primitive, and primitives are fewer
    uvs.push_back({t.uv[0], t.uv[1], t.uv[2]});
    return static_cast<std::uint32_t>(uvs.size() - 1);
}

std::vector<Triangle> trianglesOf(std::span<const SceneTriangle> sceneTriangles) {
    std::vector<Triangle> out;
    out.reserve(sceneTriangles.size());
    for (const SceneTriangle& t : sceneTriangles) out.push_back({t.p[0], t.p[1], t.p[2]});
    return out;
}

}  // namespace penumbra::bvh
