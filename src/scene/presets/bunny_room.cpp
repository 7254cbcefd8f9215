// The bunny room: the scene of the real-time path tracer that renders the Stanford bunny at 1080p
// (mirror walls, a glass sphere, a semi-specular floor, diffuse walls, a ceiling light and point
// lights). The bunny comes from Debian's glmark2-data when it is installed; otherwise a faceted
// stand-in of the same size takes its place, so the preset never needs a file.
#include <cmath>
#include <filesystem>

#include "core/log.h"
#include "core/transform.h"
#include "scene/io/obj.h"
#include "scene/merge.h"
#include "scene/presets/mesh_builder.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

const char* const kBunnyPath = "/usr/share/glmark2/models/bunny.obj";
constexpr float kHalfWidth = 2.0f;  // the room is 4 x 2.6 x 4 m
constexpr float kHeight = 2.6f;
constexpr float kBunnyHeight = 0.75f;
const Vec3 kBunnyFoot{-0.55f, 0.0f, -0.2f};  // where the bunny's feet touch the floor

// An icosahedron of unit circumradius: the stand-in when the bunny is not installed.
Mesh icosahedron() {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    Mesh m;
    m.name = "bunny stand-in";
    for (Vec3 v : {Vec3{-1, t, 0}, Vec3{1, t, 0}, Vec3{-1, -t, 0}, Vec3{1, -t, 0}, Vec3{0, -1, t}, Vec3{0, 1, t},
                   Vec3{0, -1, -t}, Vec3{0, 1, -t}, Vec3{t, 0, -1}, Vec3{t, 0, 1}, Vec3{-t, 0, -1}, Vec3{-t, 0, 1}})
        m.positions.push_back(normalize(v));
    m.indices = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
                 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
    return m;
}

// The bunny (or its stand-in) as a scene of its own, before placing.
Scene bunnyOrStandIn() {
    if (std::filesystem::exists(kBunnyPath)) {
        try {
            return loadObj(kBunnyPath);
        } catch (const std::exception& e) {
            std::string message = "bunny-room: ";
            message.append(e.what()).append("; using a stand-in");
            logWarning(message);
        }
    }
    Scene s;
    s.name = "stand-in";
    s.materials.push_back({"bunny-material", Vec3{0.8f}});
    s.meshes.push_back(icosahedron());
    return s;
}

// Scales and moves `part` so that it stands kBunnyHeight tall with its feet at kBunnyFoot.
Affine placeOnFloor(const Scene& part) {
    const Aabb box = part.bounds();
    const float scale = kBunnyHeight / std::max(box.extent().y, 1e-6f);
    const Vec3 base{0.5f * (box.lo.x + box.hi.x), box.lo.y, 0.5f * (box.lo.z + box.hi.z)};
    return Affine::translation(kBunnyFoot) * Affine::eulerDegrees({0, 30, 0}) * Affine::scaling(Vec3{scale}) *
           Affine::translation(-base);
}

}  // namespace

Scene makeBunnyRoom() {
    Scene scene;
    scene.name = "bunny-room";
    const std::uint32_t white = addMaterial(scene, "white wall", Vec3{0.75f});
    const std::uint32_t blue = addMaterial(scene, "blue wall", {0.15f, 0.25f, 0.55f});
    std::uint32_t mirror = addMaterial(scene, "mirror", Vec3{0.95f});
    scene.materials[mirror].metallic = 1.0f;
    scene.materials[mirror].roughness = 0.0f;
    std::uint32_t floor = addMaterial(scene, "semi-specular floor", {0.55f, 0.42f, 0.3f});
    scene.materials[floor].specular = 1.0f;
    scene.materials[floor].roughness = 0.3f;
    std::uint32_t glass = addMaterial(scene, "glass", Vec3{1.0f});
    scene.materials[glass].transmission = 1.0f;
    scene.materials[glass].roughness = 0.0f;
    scene.materials[glass].specular = 1.0f;
    scene.materials[glass].ior = 1.5f;
    const std::uint32_t panel = addMaterial(scene, "ceiling light", Vec3{0}, Vec3{9.0f, 8.5f, 7.5f});

    const float w = kHalfWidth, h = kHeight;
    auto wall = [&](const char* name, std::uint32_t material, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
        addQuadMesh(scene, name, material, a, b, c, d);
    };
    // Every wall faces into the room.
    wall("floor", floor, {-w, 0, -w}, {-w, 0, w}, {w, 0, w}, {w, 0, -w});
    wall("ceiling", white, {-w, h, -w}, {w, h, -w}, {w, h, w}, {-w, h, w});
    wall("back mirror", mirror, {-w, 0, -w}, {w, 0, -w}, {w, h, -w}, {-w, h, -w});
    wall("right mirror", mirror, {w, 0, -w}, {w, 0, w}, {w, h, w}, {w, h, -w});
    wall("left wall", blue, {-w, 0, w}, {-w, 0, -w}, {-w, h, -w}, {-w, h, w});
    wall("front wall", white, {w, 0, w}, {-w, 0, w}, {-w, h, w}, {w, h, w});
    const float p = 0.45f, y = h - 0.01f;
    wall("ceiling light", panel, {-p, y, -p}, {p, y, -p}, {p, y, p}, {-p, y, p});

    scene.spheres.push_back({{0.75f, 0.45f, -0.35f}, 0.45f, glass});

    // Two small warm and cool bulbs with radii, for soft shadows.
    Light warm;
    warm.name = "warm bulb";
    warm.position = {-1.4f, 1.9f, 1.2f};
    warm.color = {1.0f, 0.8f, 0.55f};
    warm.intensity = 3.0f;
    warm.radius = 0.06f;
    Light cool = warm;
    cool.name = "cool bulb";
    cool.position = {1.3f, 1.6f, 1.3f};
    cool.color = {0.6f, 0.75f, 1.0f};
    scene.lights = {warm, cool};

    Scene bunny = bunnyOrStandIn();
    const Affine place = placeOnFloor(bunny);
    appendScene(scene, std::move(bunny), place);

    scene.camera.position = {-0.2f, 1.25f, 1.85f};
    scene.camera.lookAt = {0.0f, 0.5f, -0.6f};
    scene.camera.up = {0, 1, 0};
    scene.camera.fovYDegrees = 55.0f;
    return scene;
}

}  // namespace penumbra
