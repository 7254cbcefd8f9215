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

// A room whose movers lie where the map put them, like a Doom map's doors and lifts at rest: a
// door (a slab across the doorway of a wall) and a lift (a raised platform), each a prototype
// modelled in world space and placed once by the identity. doorRaised(up): a placement raised by
// `up` (the identity for 0, as a door back at rest).
inline Affine doorRaised(float up) { return up == 0.0f ? Affine{} : Affine::translation({0.0f, up, 0.0f}); }

inline Scene moversAtRest() {
    Scene s;
    s.name = "movers at rest";
    const std::uint32_t floor = addMaterial(s, "floor", Vec3{0.6f});
    const std::uint32_t wall = addMaterial(s, "wall", {0.7f, 0.2f, 0.15f});
    const std::uint32_t door = addMaterial(s, "door", {0.3f, 0.5f, 0.8f});
    const std::uint32_t panel = addMaterial(s, "panel", Vec3{0}, {5.0f, 5.0f, 4.5f});
    addQuadMesh(s, "floor", floor, {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2});
    addQuadMesh(s, "wall left", wall, {-2, 0, -1}, {-0.5f, 0, -1}, {-0.5f, 2.5f, -1}, {-2, 2.5f, -1});
    addQuadMesh(s, "wall right", wall, {0.5f, 0, -1}, {2, 0, -1}, {2, 2.5f, -1}, {0.5f, 2.5f, -1});
    addQuadMesh(s, "panel", panel, {-0.9f, 2.2f, -0.3f}, {-0.3f, 2.2f, -0.3f}, {-0.3f, 2.2f, 0.3f}, {-0.9f, 2.2f, 0.3f});
    Mesh slab;
    slab.name = "door";
    slab.material = door;
    addQuad(slab, {-0.5f, 0, -0.95f}, {0.5f, 0, -0.95f}, {0.5f, 1.8f, -0.95f}, {-0.5f, 1.8f, -0.95f});
    addQuad(slab, {0.5f, 0, -1.05f}, {-0.5f, 0, -1.05f}, {-0.5f, 1.8f, -1.05f}, {0.5f, 1.8f, -1.05f});
    Mesh lift;
    lift.name = "lift";
    lift.material = floor;
    addQuad(lift, {0.8f, 0.3f, 0.2f}, {0.8f, 0.3f, 1.2f}, {1.8f, 0.3f, 1.2f}, {1.8f, 0.3f, 0.2f});
    addQuad(lift, {0.8f, 0.0f, 1.2f}, {1.8f, 0.0f, 1.2f}, {1.8f, 0.3f, 1.2f}, {0.8f, 0.3f, 1.2f});
    s.prototypes.push_back({"door", {slab}});
    s.prototypes.push_back({"lift", {lift}});
    s.instances.push_back({0, Affine{}});
    s.instances.push_back({1, Affine{}});
    s.background = Vec3{0.15f};
    s.camera.position = {0.4f, 1.2f, 3.6f};
    s.camera.lookAt = {-0.1f, 0.5f, 0.0f};
    s.camera.fovYDegrees = 50.0f;
    return s;
}

// The same world with every instance baked into world meshes (what duplicating the mesh gives).
inline Scene baked(Scene s) {
    bakeAllInstances(s);
    return s;
}

}  // namespace penumbra::test
