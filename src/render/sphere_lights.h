// Spheres as the renderer sees them, and the table that light sampling picks sphere lights from.
#pragma once

#include <span>
#include <vector>

#include "scene/scene.h"
#include "shared/types.h"

namespace penumbra {

// Point and spot lights with a radius are sphere lights, not punctual ones.
bool isSphereLight(const Light& light);

// The scene's spheres, plus one emissive sphere per point light with a radius: radiance
// I / (pi r^2), so that from afar it has the point light's intensity I. Their materials
// (black, emissive) are numbered after the scene's.
struct RenderSpheres {
    std::vector<Sphere> spheres;
    std::vector<Material> extraMaterials;
};
RenderSpheres renderSpheres(const Scene& scene);

// One entry per emissive sphere (slots[i] = sphere i's slot in the primitive arrays) and per spot
// light with a radius (the light sampler picks among them, render/light_list.h). materials: the
// scene's followed by the extra ones.
std::vector<shader::SphereLight> buildSphereLightTable(const Scene& scene, const RenderSpheres& spheres,
                                                       std::span<const Material> materials,
                                                       std::span<const std::uint32_t> slots);

}  // namespace penumbra
