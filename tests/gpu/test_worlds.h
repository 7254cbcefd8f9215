// Small test worlds for invariance tests: a floor and two walls, smooth-shaded spheres (shading
// normals that are not the faces' own), and lights of every kind.
#pragma once

#include "../unit/smooth_sphere.h"
#include "scene/presets/mesh_builder.h"
#include "scene/scene.h"

namespace penumbra::test {

// A floor, a red back wall and a green left wall, a glossy metal sphere and a diffuse one with
// smooth normals, seen through a thin lens; no lights.
inline Scene room() {
    Scene s;
    s.name = "room";
    const std::uint32_t floor = addMaterial(s, "floor", Vec3{0.6f});
    const std::uint32_t red = addMaterial(s, "red", {0.7f, 0.2f, 0.15f});
    const std::uint32_t green = addMaterial(s, "green", {0.2f, 0.6f, 0.25f});
    const std::uint32_t metal = addMaterial(s, "metal", {0.95f, 0.8f, 0.5f});
    s.materials[metal].metallic = 1.0f;
    s.materials[metal].roughness = 0.35f;
    const std::uint32_t blue = addMaterial(s, "blue", {0.2f, 0.35f, 0.8f});
    auto quad = [&](const char* name, std::uint32_t material, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
        addQuadMesh(s, name, material, a, b, c, d);
    };
    quad("floor", floor, {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2});
    quad("back", red, {-2, 0, -2}, {2, 0, -2}, {2, 2.5f, -2}, {-2, 2.5f, -2});
    quad("left", green, {-2, 0, 2}, {-2, 0, -2}, {-2, 2.5f, -2}, {-2, 2.5f, 2});
    s.meshes.push_back(smoothSphere({-0.5f, 0.5f, -0.5f}, 0.5f, 6, 9, metal));
    s.meshes.push_back(smoothSphere({0.7f, 0.35f, 0.2f}, 0.35f, 5, 7, blue));
    s.camera.position = {0.4f, 1.2f, 3.6f};
    s.camera.lookAt = {-0.1f, 0.5f, 0.0f};
    s.camera.fovYDegrees = 45.0f;
    s.camera.apertureRadius = 0.015f;
    s.camera.focusDistance = 3.5f;
    return s;
}

// Lit by what keeps its look under any similarity transform: emitters (radiance), a directional
// light (illuminance) and a uniform sky. The panel emits downward only, toward the spheres.
inline Scene areaLitWorld() {
    Scene s = room();
    const std::uint32_t panel = addMaterial(s, "panel", Vec3{0}, {5.0f, 5.0f, 4.5f});
    const std::uint32_t lamp = addMaterial(s, "lamp", Vec3{0}, {8.0f, 6.0f, 3.0f});
    Mesh m;
    m.name = "panel";
    m.material = panel;
    addQuad(m, {-0.9f, 1.8f, -0.3f}, {-0.3f, 1.8f, -0.3f}, {-0.3f, 1.8f, 0.3f},
            {-0.9f, 1.8f, 0.3f});
    s.meshes.push_back(std::move(m));
    s.spheres.push_back({{0.9f, 1.4f, -1.0f}, 0.12f, lamp});
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = normalize(Vec3{0.4f, -1.0f, -0.5f});
    sun.color = {1.0f, 0.95f, 0.9f};
    sun.intensity = 2.0f;
    s.lights.push_back(sun);
    s.background = Vec3{0.15f};
    return s;
}

// Point (delta and with a radius) and spot lights: their candela do not scale with the world, so
// this one is only moved rigidly.
inline Scene punctuallyLitWorld() {
    Scene s = room();
    Light point;
    point.position = {0.8f, 1.6f, 1.0f};
    point.color = {1.0f, 0.85f, 0.7f};
    point.intensity = 1.5f;
    Light bulb = point;
    bulb.position = {-1.2f, 1.4f, 0.8f};
    bulb.color = {0.7f, 0.8f, 1.0f};
    bulb.radius = 0.15f;
    Light spot = point;
    spot.type = LightType::Spot;
    spot.position = {0.2f, 2.2f, 0.5f};
    spot.direction = normalize(Vec3{0.0f, -1.0f, -0.3f});
    spot.intensity = 3.0f;
    s.lights = {point, bulb, spot};
    s.background = Vec3{0.05f};
    return s;
}

}  // namespace penumbra::test
