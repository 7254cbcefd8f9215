// The material sweep: rows of spheres under a procedural daylight sky, one parameter changing
// along each row, so a glance shows what roughness, metalness and the coat do:
//   front row:  red plastic (diffuse base + dielectric coat), roughness 0 -> 1
//   middle row: gold, roughness 0 -> 1
//   back row:   metallic 0 -> 1 at roughness 0.3
// and, at the back, a clear glass sphere and a perfect mirror sphere.
#include "scene/io/env_sky.h"
#include "scene/presets/mesh_builder.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

constexpr int kPerRow = 5;
constexpr float kRadius = 0.2f;
constexpr float kSpacing = 0.5f;

std::uint32_t addPbr(Scene& scene, std::string name, Vec3 base, float metallic, float roughness) {
    std::uint32_t id = addMaterial(scene, std::move(name), base);
    scene.materials[id].metallic = metallic;
    scene.materials[id].roughness = roughness;
    scene.materials[id].specular = 1.0f;
    return id;
}

}  // namespace

Scene makeMaterialSpheres() {
    Scene scene;
    scene.name = "materials";
    const Vec3 red{0.7f, 0.08f, 0.06f};
    const Vec3 gold{1.0f, 0.77f, 0.34f};  // gold's F0 (sRGB-ish linear values)
    for (int i = 0; i < kPerRow; ++i) {
        const float t = float(i) / float(kPerRow - 1);
        const float x = (float(i) - 0.5f * float(kPerRow - 1)) * kSpacing;
        const std::string suffix = std::to_string(i);
        scene.spheres.push_back({{x, kRadius, 0.5f}, kRadius, addPbr(scene, "plastic " + suffix, red, 0.0f, t)});
        scene.spheres.push_back({{x, kRadius, 0.0f}, kRadius, addPbr(scene, "gold " + suffix, gold, 1.0f, t)});
        scene.spheres.push_back({{x, kRadius, -0.5f}, kRadius, addPbr(scene, "metalness " + suffix, gold, t, 0.3f)});
    }
    std::uint32_t glass = addPbr(scene, "glass", Vec3{1.0f}, 0.0f, 0.0f);
    scene.materials[glass].transmission = 1.0f;
    scene.materials[glass].ior = 1.5f;
    const std::uint32_t mirror = addPbr(scene, "mirror", Vec3{0.97f}, 1.0f, 0.0f);
    scene.spheres.push_back({{-0.45f, 0.35f, -1.15f}, 0.35f, glass});
    scene.spheres.push_back({{0.45f, 0.35f, -1.15f}, 0.35f, mirror});

    const std::uint32_t ground = addMaterial(scene, "ground", Vec3{0.45f});
    Mesh floor;
    floor.name = "ground";
    floor.material = ground;
    addQuad(floor, {-20, 0, -20}, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20});
    scene.meshes.push_back(floor);

    SkyParams params;
    params.sunElevationDegrees = 35.0f;
    params.sunAzimuthDegrees = 140.0f;
    params.sunRadiusDegrees = 1.0f;  // a little softer than the real sun's 0.27
    Sky sky = makeSky(params);
    scene.environment.map = std::move(sky.map);
    scene.environment.sun = sky.sun;

    scene.camera.position = {0.0f, 1.1f, 2.3f};
    scene.camera.lookAt = {0.0f, 0.15f, -0.2f};
    scene.camera.up = {0, 1, 0};
    scene.camera.fovYDegrees = 40.0f;
    return scene;
}

}  // namespace penumbra
