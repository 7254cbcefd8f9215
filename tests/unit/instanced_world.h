// A small world with instances, for the two-level tests: the room of the GPU test worlds without
// its spheres, and one smooth-sphere prototype placed several times (rotated, squashed, mirrored).
#pragma once

#include "scene/instances.h"
#include "scene/presets/mesh_builder.h"
#include "scene/scene.h"
#include "smooth_sphere.h"

namespace penumbra::test {

// Placement k of the sphere prototype (k = 0..4 differ in every way an affine map can).
inline Affine spherePlacement(int k) {
    const Vec3 at[] = {{-0.5f, 0.5f, -0.5f}, {0.7f, 0.35f, 0.2f}, {0.0f, 1.0f, -1.2f}, {-1.2f, 0.3f, 0.8f},
                       {1.2f, 0.9f, -0.9f}};
    const Vec3 scale[] = {{0.5f, 0.5f, 0.5f}, {0.35f, 0.25f, 0.4f}, {-0.3f, 0.3f, 0.3f}, {0.2f, 0.45f, 0.2f},
                          {0.3f, 0.3f, -0.25f}};
    const Vec3 turn[] = {{0, 0, 0}, {20, 40, -10}, {0, 75, 0}, {-30, 10, 60}, {45, -20, 5}};
    return Affine::translation(at[k % 5]) * Affine::eulerDegrees(turn[k % 5]) * Affine::scaling(scale[k % 5]);
}

// instances: how many placements of the sphere (spherePlacement(k) for k < 5, then more spread
// out); rings and segments: its tessellation.
inline Scene instancedRoom(int instances = 5, int rings = 6, int segments = 9) {
    Scene s;
    s.name = "instanced room";
    const std::uint32_t floor = addMaterial(s, "floor", Vec3{0.6f});
    const std::uint32_t red = addMaterial(s, "red", {0.7f, 0.2f, 0.15f});
    const std::uint32_t metal = addMaterial(s, "metal", {0.95f, 0.8f, 0.5f});
    s.materials[metal].metallic = 1.0f;
    s.materials[metal].roughness = 0.35f;
    const std::uint32_t panel = addMaterial(s, "panel", Vec3{0}, {5.0f, 5.0f, 4.5f});
    auto quad = [&](const char* name, std::uint32_t material, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
        addQuadMesh(s, name, material, a, b, c, d);
    };
    quad("floor", floor, {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2});
    quad("back", red, {-2, 0, -2}, {2, 0, -2}, {2, 2.5f, -2}, {-2, 2.5f, -2});
    quad("panel", panel, {-0.9f, 2.2f, -0.3f}, {-0.3f, 2.2f, -0.3f}, {-0.3f, 2.2f, 0.3f}, {-0.9f, 2.2f, 0.3f});
    s.prototypes.push_back({"sphere", {smoothSphere(Vec3{0}, 1.0f, rings, segments, metal)}});
    for (int k = 0; k < instances; ++k) {
        Affine t = spherePlacement(k);
        if (k >= 5) t = Affine::translation({0.3f * float(k / 5), 0.0f, -0.2f * float(k / 5)}) * t;
        s.instances.push_back({0, t});
    }
    s.background = Vec3{0.15f};
    s.camera.position = {0.4f, 1.2f, 3.6f};
    s.camera.lookAt = {-0.1f, 0.5f, 0.0f};
    s.camera.fovYDegrees = 45.0f;
    return s;
}

// The same world with every instance baked into world meshes (what duplicating the mesh gives).
inline Scene baked(Scene s) {
    bakeAllInstances(s);
    return s;
}

}  // namespace penumbra::test
