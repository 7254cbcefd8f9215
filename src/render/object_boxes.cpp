#include "render/object_boxes.h"

#include <map>

#include "bvh/sphere.h"
#include "bvh/sprite.h"
#include "render/picking.h"

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

shader::ObjectBox toObjectBox(const Aabb& box, std::uint32_t first, std::uint32_t count, std::uint32_t instance,
                              bool listed) {
    shader::ObjectBox out{};
    out.boundsMin = box.lo;
    out.boundsMax = box.hi;
    out.first = first;
    out.count = count;
    out.instance = instance;
    out.listed = listed ? 1u : 0u;
    return out;
}

// The box of each leaf's primitives, for the sprites among them (the bottom levels' leaves only:
// top-level leaves hold instances).
std::vector<Aabb> leafBoxes(const SceneArrays& a) {
    std::vector<Aabb> leafOf(a.triVerts.size());
    const std::size_t end = a.instances.empty() ? a.nodes.size() : a.bottomNodeCount;
    for (std::size_t k = 0; k < end; ++k) {
        const shader::BvhNode& n = a.nodes[k];
        for (std::uint32_t i = n.firstOrRight; n.triCount > 0 && i < n.firstOrRight + n.triCount; ++i) leafOf.at(i) = nodeBox(n);
    }
    return leafOf;
}

// Slots [first, end), in world space, grouped by scene object (in scene order; the primitives of
// none last), one listed box each reporting `instance`.
void addListedBoxes(SceneArrays& a, const std::vector<Aabb>& leafOf, std::uint32_t first, std::uint32_t end,
                    std::uint32_t instance) {
    std::map<std::uint32_t, std::vector<std::uint32_t>> members;
    for (std::uint32_t i = first; i < end; ++i)
        members[i < a.primitiveObject.size() ? a.primitiveObject[i] : kNoObject].push_back(i);
    for (const auto& [object, prims] : members) {
        Aabb box;
        for (std::uint32_t i : prims) box.grow(primitiveBox(a.triVerts[i], leafOf[i]));
        a.objectBoxes.push_back(
            toObjectBox(box, std::uint32_t(a.objectPrims.size()), std::uint32_t(prims.size()), instance, true));
        a.objectPrims.insert(a.objectPrims.end(), prims.begin(), prims.end());
    }
}

// Two levels: the world's own geometry (the identity instance of no scene instance) is split by
// object like a flat scene; every scene instance is one box, its top-level leaf's, walked in its
// space (exact for an identity placement too). Deciding by the world rather than by the identity
// keeps the number of boxes and slots when an instance moves from or to where it was modelled
// (a Doom door at rest), so a move overwrites the boxes in place.
void instanceObjectBoxes(SceneArrays& a, const std::vector<Aabb>& leafOf) {
    std::vector<Aabb> worldBox(a.instances.size());
    for (std::size_t n = a.topRoot; n < a.nodes.size(); ++n)
        if (a.nodes[n].triCount > 0) worldBox.at(a.nodes[n].firstOrRight) = nodeBox(a.nodes[n]);
    for (std::uint32_t k = 0; k < a.instances.size(); ++k) {
        const shader::Instance& inst = a.instances[k];
        if (inst.id == PN_NO_HIT)
            addListedBoxes(a, leafOf, inst.firstPrimitive, inst.firstPrimitive + inst.primitiveCount, k);
        else
            a.objectBoxes.push_back(toObjectBox(worldBox[k], inst.firstPrimitive, inst.primitiveCount, k, false));
    }
}

}  // namespace

void buildObjectBoxes(SceneArrays& a) {
    a.objectBoxes.clear();
    a.objectPrims.clear();
    const std::vector<Aabb> leafOf = leafBoxes(a);
    if (a.instances.empty())
        addListedBoxes(a, leafOf, 0, std::uint32_t(a.triVerts.size()), PN_NO_HIT);
    else
        instanceObjectBoxes(a, leafOf);
}

}  // namespace penumbra
