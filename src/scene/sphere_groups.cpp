#include "scene/sphere_groups.h"

#include "core/error.h"

namespace penumbra {

std::optional<std::uint32_t> sphereGroupOf(const Scene& scene, std::size_t sphere) {
    for (std::size_t g = 0; g < scene.sphereGroups.size(); ++g)
        for (std::uint32_t i : scene.sphereGroups[g].spheres)
            if (i == sphere) return static_cast<std::uint32_t>(g);
    return std::nullopt;
}

std::string sphereGroupName(const Scene& scene, std::uint32_t group) {
    PN_CHECK(group < scene.sphereGroups.size());
    const SphereGroup& g = scene.sphereGroups[group];
    return "group '" + g.name + "' (" + std::to_string(g.spheres.size()) + " spheres)";
}

Vec3 sphereGroupPivot(const Scene& scene, std::uint32_t group) {
    PN_CHECK(group < scene.sphereGroups.size());
    const SphereGroup& g = scene.sphereGroups[group];
    if (g.spheres.empty()) return Vec3{0};
    Vec3 sum{0};
    for (std::uint32_t i : g.spheres) sum += scene.spheres[i].center;
    return sum / float(g.spheres.size());
}

void moveSphereGroup(Scene& scene, std::uint32_t group, Vec3 offset) {
    PN_CHECK(group < scene.sphereGroups.size());
    for (std::uint32_t i : scene.sphereGroups[group].spheres) scene.spheres[i].center += offset;
}

void turnSphereGroup(Scene& scene, std::uint32_t group, const Affine& rotation) {
    const Vec3 pivot = sphereGroupPivot(scene, group);
    for (std::uint32_t i : scene.sphereGroups[group].spheres) {
        Vec3& c = scene.spheres[i].center;
        c = pivot + rotation.vector(c - pivot);
    }
}

}  // namespace penumbra
