#include "scene/instances.h"

#include <utility>

namespace penumbra {

Mesh transformedMesh(Mesh mesh, const Affine& transform) {
    for (Vec3& p : mesh.positions) p = transform.point(p);
    for (Vec3& n : mesh.normals) n = transform.normal(n);
    if (transform.determinant() < 0)
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    return mesh;
}

std::size_t prototypeTriangleCount(const Prototype& prototype) {
    std::size_t n = 0;
    for (const Mesh& m : prototype.meshes) n += m.triangleCount();
    return n;
}

std::size_t instancedTriangleCount(const Scene& scene) {
    std::size_t n = 0;
    for (const Instance& i : scene.instances)
        if (i.prototype < scene.prototypes.size()) n += prototypeTriangleCount(scene.prototypes[i.prototype]);
    return n;
}

bool prototypeIsEmissive(const Scene& scene, const Prototype& prototype) {
    for (const Mesh& m : prototype.meshes)
        if (m.material < scene.materials.size() && scene.materials[m.material].isEmissive() &&
            scene.materials[m.material].lightSampled)
            return true;
    return false;
}

void appendBakedInstance(Scene& scene, std::size_t instance) {
    const Instance placed = scene.instances.at(instance);
    for (const Mesh& m : scene.prototypes.at(placed.prototype).meshes)
        scene.meshes.push_back(transformedMesh(m, placed.transform));
}

void bakeAllInstances(Scene& scene) {
    for (std::size_t i = 0; i < scene.instances.size(); ++i) appendBakedInstance(scene, i);
    scene.instances.clear();
    scene.prototypes.clear();
    scene.instanceAnimations.clear();  // baked where they stand now
}

std::size_t bakeEmissiveInstances(Scene& scene, std::vector<std::uint32_t>* keptFrom) {
    if (keptFrom) keptFrom->clear();
    std::vector<Instance> kept;
    std::vector<std::uint32_t> newIndex(scene.instances.size(), UINT32_MAX);
    std::size_t baked = 0;
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        if (inst.prototype < scene.prototypes.size() && prototypeIsEmissive(scene, scene.prototypes[inst.prototype])) {
            appendBakedInstance(scene, i);  // an animated emitter stays where it is now
            ++baked;
        } else {
            newIndex[i] = static_cast<std::uint32_t>(kept.size());
            kept.push_back(inst);
            if (keptFrom) keptFrom->push_back(static_cast<std::uint32_t>(i));
        }
    }
    scene.instances = std::move(kept);
    std::vector<InstanceAnimation> animations;
    for (InstanceAnimation& a : scene.instanceAnimations)
        if (a.instance < newIndex.size() && newIndex[a.instance] != UINT32_MAX) {
            a.instance = newIndex[a.instance];
            animations.push_back(std::move(a));
        }
    scene.instanceAnimations = std::move(animations);
    return baked;
}

void instanceWorldMeshes(Scene& scene) {
    Prototype world{"world", {}};
    std::vector<Mesh> kept;
    for (Mesh& m : scene.meshes) {
        const bool emissive = m.material < scene.materials.size() && scene.materials[m.material].isEmissive();
        (emissive ? kept : world.meshes).push_back(std::move(m));
    }
    scene.meshes = std::move(kept);
    if (world.meshes.empty()) return;
    scene.instances.push_back({static_cast<std::uint32_t>(scene.prototypes.size()), Affine{}});
    scene.prototypes.push_back(std::move(world));
}

}  // namespace penumbra
