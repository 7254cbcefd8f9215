#include "render/object_boxes.h"

#include <map>

#include "bvh/sphere.h"
#include "bvh/sprite.h"
#include "render/scene_objects.h"

namespace penumbra {

namespace {

Aabb nodeBox(const shader::BvhNode& n) {
    Aabb box;
    box.grow(n.boundsMin);
    box.grow(n.boundsMax);
    return box;
}

// Each primitive's box: its own for triangles and spheres, its leaf's for sprites (flat tree).
Aabb primitiveBox(const shader::TriVerts& p, const Aabb& leaf) {
    Aabb box;
    if (bvh::isSprite(p)) return leaf;
    if (bvh::isSphere(p)) {
        const Vec3 r{p.e1.x};
        box.grow(p.v0 - r);
        box.grow(p.v0 + r);
        return box;
    }
    box.grow(p.v0);
    box.grow(p.v0 + p.e1);
    box.grow(p.v0 + p.e2);
    return box;
}

shader::ObjectBox toObjectBox(const Aabb& box, std::uint32_t first, std::uint32_t count, std::uint32_t instance) {
    shader::ObjectBox out{};
    out.boundsMin = box.lo;
    out.boundsMax = box.hi;
    out.first = first;
    out.count = count;
    out.instance = instance;
    return out;
}

void flatObjectBoxes(SceneArrays& a) {
    std::vector<Aabb> leafOf(a.triVerts.size());
    for (const shader::BvhNode& n : a.nodes)
        for (std::uint32_t i = n.firstOrRight; n.triCount > 0 && i < n.firstOrRight + n.triCount; ++i)
            leafOf.at(i) = nodeBox(n);
    // Objects in their scene order, then the primitives of none.
    std::map<std::uint32_t, std::vector<std::uint32_t>> members;
    for (std::uint32_t i = 0; i < a.triVerts.size(); ++i)
        members[i < a.primitiveObject.size() ? a.primitiveObject[i] : kNoObject].push_back(i);
    for (const auto& [object, prims] : members) {
        Aabb box;
        for (std::uint32_t i : prims) box.grow(primitiveBox(a.triVerts[i], leafOf[i]));
        a.objectBoxes.push_back(toObjectBox(box, std::uint32_t(a.objectPrims.size()), std::uint32_t(prims.size()), PN_NO_HIT));
        a.objectPrims.insert(a.objectPrims.end(), prims.begin(), prims.end());
    }
}

// One box per instance: its top-level leaf's world box, in instance order.
void instanceObjectBoxes(SceneArrays& a) {
    std::vector<Aabb> worldBox(a.instances.size());
    for (std::size_t n = a.topRoot; n < a.nodes.size(); ++n)
        if (a.nodes[n].triCount > 0) worldBox.at(a.nodes[n].firstOrRight) = nodeBox(a.nodes[n]);
    for (std::uint32_t k = 0; k < a.instances.size(); ++k) {
        const shader::Instance& inst = a.instances[k];
        a.objectBoxes.push_back(toObjectBox(worldBox[k], inst.firstPrimitive, inst.primitiveCount, k));
    }
}

}  // namespace

void buildObjectBoxes(SceneArrays& a) {
    a.objectBoxes.clear();
    a.objectPrims.clear();
    if (a.instances.empty())
        flatObjectBoxes(a);
    else
        instanceObjectBoxes(a);
}

}  // namespace penumbra
