#include "scene/light_edit.h"

#include <algorithm>

#include "core/error.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

constexpr float kMinSphereRadius = 1e-4f;  // metres: a sphere must keep a size
constexpr float kMaxSpotDegrees = 90.0f;

Vec3 nonNegative(Vec3 v) { return Vec3{std::max(v.x, 0.0f), std::max(v.y, 0.0f), std::max(v.z, 0.0f)}; }

}  // namespace

std::vector<EditableLight> editableLights(const Scene& scene) {
    std::vector<EditableLight> out;
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        if (!scene.lights[i].moves) out.push_back({EditableLight::Kind::Light, static_cast<std::uint32_t>(i)});
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        if (maxComponent(scene.materials[scene.spheres[i].material].emission) > 0)
            out.push_back({EditableLight::Kind::EmissiveSphere, static_cast<std::uint32_t>(i)});
    return out;
}

std::string lightName(const Scene& scene, EditableLight light) {
    if (light.kind == EditableLight::Kind::EmissiveSphere) {
        PN_CHECK(light.index < scene.spheres.size());
        return "'" + scene.materials[scene.spheres[light.index].material].name + "' sphere " +
               std::to_string(light.index);
    }
    PN_CHECK(light.index < scene.lights.size());
    const Light& l = scene.lights[light.index];
    const char* kind = l.type == LightType::Directional ? "directional light"
                       : l.type == LightType::Spot      ? (l.radius > 0 ? "spot sphere light" : "spot light")
                       : l.radius > 0                   ? "sphere light"
                                                        : "point light";
    return std::string(kind) + " " + (l.name.empty() ? std::to_string(light.index) : "'" + l.name + "'");
}

LightParams lightParams(const Scene& scene, EditableLight light) {
    LightParams p;
    if (light.kind == EditableLight::Kind::EmissiveSphere) {
        const Sphere& s = scene.spheres[light.index];
        const Vec3 emission = scene.materials[s.material].emission;
        p.position = s.center;
        p.radius = s.radius;
        p.intensity = maxComponent(emission);
        p.color = p.intensity > 0 ? emission / p.intensity : Vec3{1};
        return p;
    }
    const Light& l = scene.lights[light.index];
    p.position = l.position;
    p.color = l.color;
    p.intensity = l.intensity;
    p.hasPosition = l.type != LightType::Directional;
    p.radius = p.hasPosition ? l.radius : l.angularRadius;
    p.isSpot = l.type == LightType::Spot;
    p.spotDegrees = p.isSpot ? radiansToDegrees(l.outerConeRadians) : 0.0f;
    return p;
}

void setLightParams(Scene& scene, EditableLight light, const LightParams& p) {
    const Vec3 color = nonNegative(p.color);
    const float intensity = std::max(p.intensity, 0.0f);
    if (light.kind == EditableLight::Kind::EmissiveSphere) {
        PN_CHECK(light.index < scene.spheres.size());
        Sphere& s = scene.spheres[light.index];
        s.center = p.position;
        s.radius = std::max(p.radius, kMinSphereRadius);
        scene.materials[s.material].emission = color * intensity;
        return;
    }
    PN_CHECK(light.index < scene.lights.size());
    Light& l = scene.lights[light.index];
    l.color = color;
    l.intensity = intensity;
    if (l.type == LightType::Directional) {
        l.angularRadius = std::clamp(p.radius, 0.0f, kMaxAngularRadius);
        return;
    }
    l.position = p.position;
    l.radius = std::max(p.radius, 0.0f);
    if (l.type == LightType::Spot) {
        // The inner cone keeps its share of the outer one, so the soft edge scales with the cone.
        const float share = l.outerConeRadians > 0 ? l.innerConeRadians / l.outerConeRadians : 0.0f;
        l.outerConeRadians = degreesToRadians(std::clamp(p.spotDegrees, 0.1f, kMaxSpotDegrees));
        l.innerConeRadians = std::clamp(share, 0.0f, 1.0f) * l.outerConeRadians;
    }
}

}  // namespace penumbra
