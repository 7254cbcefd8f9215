// Helpers for presets that are made of flat quads.
#pragma once

#include "scene/scene.h"

namespace penumbra {

// Adds the quad a-b-c-d (in order around its edge) to `mesh` as two triangles. The front face,
// the side that emits, is the one from which a, b, c appear counter-clockwise.
inline void addQuad(Mesh& mesh, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
    auto base = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c, d});
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

// Adds a mesh of its own, named `name`, holding the quad a-b-c-d (as addQuad) in `material`.
inline void addQuadMesh(Scene& scene, std::string name, std::uint32_t material, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
    Mesh m;
    m.name = std::move(name);
    m.material = material;
    addQuad(m, a, b, c, d);
    scene.meshes.push_back(std::move(m));
}

inline std::uint32_t addMaterial(Scene& scene, std::string name, Vec3 albedo, Vec3 emission = {}) {
    scene.materials.push_back({std::move(name), albedo, emission});
    return static_cast<std::uint32_t>(scene.materials.size() - 1);
}

}  // namespace penumbra
