#include "render/instance_arrays.h"

#include <algorithm>
#include <chrono>
#include <cstring>

#include "bvh/triangle.h"
#include "bvh/two_level.h"
#include "core/error.h"
#include "render/rest_tree.h"
#include "render/walks.h"
#include "scene/objects.h"

namespace penumbra {
namespace {

struct BottomLevel {
    std::uint32_t root = PN_NO_HIT;
    std::uint32_t firstPrimitive = 0, primitiveCount = 0;
    Aabb bounds;
};

// One prototype's triangles in object space, with its BVH, appended to the arrays.
BottomLevel appendPrototype(const Prototype& prototype, SceneArrays& out, const bvh::BuildOptions& options) {
    std::vector<SceneTriangle> tris;
    for (const Mesh& m : prototype.meshes) appendTriangles(m, tris);
    BottomLevel level;
    if (tris.empty()) return level;
    const std::vector<bvh::Triangle> geometry = bvh::trianglesOf(tris);
    const bvh::Bvh tree = bvh::buildTriangles(geometry, options);
    if (out.triVerts.size() + tris.size() >= PN_NO_HIT) throw Error("the scene's instanced meshes have too many triangles");
    level.firstPrimitive = static_cast<std::uint32_t>(out.triVerts.size());
    level.primitiveCount = static_cast<std::uint32_t>(tris.size());
    level.root = bvh::appendBottomLevel(out.nodes, tree, level.firstPrimitive);
    level.bounds.grow(tree.nodes[0].boundsMin);
    level.bounds.grow(tree.nodes[0].boundsMax);
    for (std::uint32_t original : tree.primOrder) {
        const SceneTriangle& t = tris[original];
        out.triVerts.push_back(bvh::toTriVerts(geometry[original]));
        out.triVerts.back().uvIndex = bvh::appendTriUvs(t, out.triUvs);
        // Object space; never a light: emissive prototypes are baked into the world (scene/instances.h).
        shader::TriAttribs a = bvh::toTriAttribs(t);
        out.triAttribs.push_back(a);
        out.primitiveObject.push_back(kNoObject);
    }
    return level;
}

}  // namespace

void appendInstanceLevels(const Scene& scene, SceneArrays& out, const bvh::BuildOptions& options) {
    if (scene.instances.empty()) return;
    const auto start = std::chrono::steady_clock::now();
    out.instances.clear();
    out.instanceBounds.clear();
    if (!out.nodes.empty()) {
        // The world's own primitives: an identity instance over the flat BVH at node 0.
        out.instances.push_back(bvh::makeInstance(Affine{}, 0, 0, static_cast<std::uint32_t>(out.triVerts.size()), PN_NO_HIT));
        Aabb world;
        world.grow(out.nodes[0].boundsMin);
        world.grow(out.nodes[0].boundsMax);
        out.instanceBounds.push_back(world);
    }
    std::vector<BottomLevel> levels(scene.prototypes.size());
    std::vector<bool> built(scene.prototypes.size(), false);
    for (std::size_t k = 0; k < scene.instances.size(); ++k) {
        const Instance& inst = scene.instances[k];
        if (!built[inst.prototype]) {
            levels[inst.prototype] = appendPrototype(scene.prototypes[inst.prototype], out, options);
            built[inst.prototype] = true;
        }
        const BottomLevel& level = levels[inst.prototype];
        if (level.root == PN_NO_HIT) continue;  // a prototype without triangles places nothing
        out.instances.push_back(bvh::makeInstance(inst.transform, level.root, level.firstPrimitive, level.primitiveCount,
                                                  static_cast<std::uint32_t>(k)));
        out.instanceBounds.push_back(level.bounds);
    }
    appendRestTree(out);
    out.bottomNodeCount = static_cast<std::uint32_t>(out.nodes.size());
    out.uniqueMeshes = static_cast<std::uint32_t>(std::count(built.begin(), built.end(), true));
    rebuildTopLevel(out);
    out.buildMilliseconds +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void rebuildTopLevel(SceneArrays& arrays) {
    PN_CHECK(arrays.instanceBounds.size() == arrays.instances.size() && arrays.bottomNodeCount <= arrays.nodes.size());
    bvh::replaceTopLevel(arrays.nodes, arrays.bottomNodeCount, arrays.instances, arrays.instanceBounds,
                         arrays.topLevelScratch);
    arrays.topRoot = arrays.bottomNodeCount;
    refreshTopLevelRecords(arrays);
}

bool moveInstances(SceneArrays& arrays, const Scene& scene) {
    bool changed = false;
    for (shader::Instance& i : arrays.instances) {
        if (i.id == PN_NO_HIT || i.id >= scene.instances.size()) continue;  // the world
        const shader::Instance moved =
            bvh::makeInstance(scene.instances[i.id].transform, i.rootNode, i.firstPrimitive, i.primitiveCount, i.id);
        if (std::memcmp(&moved, &i, sizeof(moved)) == 0) continue;
        i = moved;
        changed = true;
    }
    if (changed) rebuildTopLevel(arrays);  // the same node count: one leaf per instance
    return changed;
}

void setInstanceTransform(SceneArrays& arrays, std::uint32_t index, const Affine& objectToWorld) {
    PN_CHECK(index < arrays.instances.size());
    shader::Instance& inst = arrays.instances[index];
    inst = bvh::makeInstance(objectToWorld, inst.rootNode, inst.firstPrimitive, inst.primitiveCount, inst.id);
    rebuildTopLevel(arrays);
}

}  // namespace penumbra
