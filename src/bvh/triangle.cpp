#include "bvh/triangle.h"

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
    a.uv0 = t.uv[0];
    a.uv1 = t.uv[1];
    a.uv2 = t.uv[2];
    a.materialId = t.material;
    a.lightIndex = PN_NO_LIGHT;
    a.area = 0.5f * length(cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
    return a;
}

std::vector<Triangle> trianglesOf(std::span<const SceneTriangle> sceneTriangles) {
    std::vector<Triangle> out;
    out.reserve(sceneTriangles.size());
    for (const SceneTriangle& t : sceneTriangles) out.push_back({t.p[0], t.p[1], t.p[2]});
    return out;
}

}  // namespace penumbra::bvh
