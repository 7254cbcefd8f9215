#include "render/sphere_lights.h"
#include "shared/constants.h"

#include <cmath>

namespace penumbra {
namespace {


// Radiance of a sphere of radius r whose intensity is `intensity` in every direction: a sphere
// seen from afar is a disk of area pi r^2.
Vec3 radianceForIntensity(const Light& l) {
    return l.color * (l.intensity / float(kPi * double(l.radius) * double(l.radius)));
}

}  // namespace

bool isSphereLight(const Light& light) {
    return light.radius > 0 && (light.type == LightType::Point || light.type == LightType::Spot);
}

RenderSpheres renderSpheres(const Scene& scene) {
    RenderSpheres out;
    out.spheres = scene.spheres;
    for (const Light& l : scene.lights) {
        if (!isSphereLight(l) || l.type != LightType::Point) continue;
        Material m;
        m.name = l.name.empty() ? "point light" : l.name;
        m.albedo = Vec3{0};
        m.emission = radianceForIntensity(l);
        if (!isFinite(m.emission) || !isFinite(l.position) || !std::isfinite(l.radius)) continue;
        out.spheres.push_back({l.position, l.radius, std::uint32_t(scene.materials.size() + out.extraMaterials.size())});
        out.extraMaterials.push_back(m);
    }
    return out;
}

std::vector<shader::SphereLight> buildSphereLightTable(const Scene& scene, const RenderSpheres& spheres,
                                                       std::span<const Material> materials,
                                                       std::span<const std::uint32_t> slots) {
    std::vector<shader::SphereLight> table;
    for (std::size_t i = 0; i < spheres.spheres.size(); ++i) {
        const Sphere& s = spheres.spheres[i];
        const Material& m = materials[s.material];
        if (!m.isEmissive()) continue;
        shader::SphereLight l{};
        l.center = s.center;
        l.radius = s.radius;
        l.radiance = m.emission;
        l.cosOuter = -1.0f;
        l.cosInner = -1.0f;
        l.spotDirection = Vec3{0, -1, 0};
        l.primitive = slots[i];
        table.push_back(l);
    }
    for (const Light& light : scene.lights) {
        if (!isSphereLight(light) || light.type != LightType::Spot) continue;
        shader::SphereLight l{};
        l.center = light.position;
        l.radius = light.radius;
        l.radiance = radianceForIntensity(light);
        l.spotDirection = normalize(light.direction);
        l.cosOuter = std::cos(light.outerConeRadians);
        l.cosInner = std::cos(light.innerConeRadians);
        l.primitive = PN_NO_HIT;
        if (!(luminance(l.radiance) > 0) || !isFinite(l.radiance) || !isFinite(l.center) || !isFinite(l.spotDirection))
            continue;
        table.push_back(l);
    }
    return table;
}

}  // namespace penumbra
