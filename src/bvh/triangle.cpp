#include "bvh/triangle.h"

#include "scene/scene.h"

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

std::vector<Triangle> trianglesOf(std::span<const SceneTriangle> sceneTriangles) {
    std::vector<Triangle> out;
    out.reserve(sceneTriangles.size());
    for (const SceneTriangle& t : sceneTriangles) out.push_back({t.p[0], t.p[1], t.p[2]});
    return out;
}

}  // namespace penumbra::bvh
