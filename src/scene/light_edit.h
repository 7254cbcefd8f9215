// The lights a viewer user edits with sliders (docs/VIEWER.md, "Lights"): each of the scene's
// punctual lights (point and spot lights, sphere lights when they have a radius, directional
// lights) except one that moves with the camera (the torch has its own section), and each sphere
// whose material emits (a lamp like the caffeine scene's). Scene data only: the caller rebuilds
// the GPU scene, since the light tables weigh lights by power.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace penumbra {

struct EditableLight {
    enum class Kind { Light, EmissiveSphere } kind = Kind::Light;
    std::uint32_t index = 0;  // into Scene::lights or Scene::spheres
};

// The sliders' values. An emissive sphere's colour and intensity split its material's emission:
// colour = emission / intensity with intensity its largest channel.
struct LightParams {
    Vec3 position{0};
    Vec3 color{1};
    float intensity = 1;    // candela, lux (directional) or the emission's largest channel
    float radius = 0;       // metres; a directional light's angular radius in radians
    float spotDegrees = 0;  // a spot light's outer cone half-angle; 0 for the others
    bool hasPosition = true;
    bool isSpot = false;
};

std::vector<EditableLight> editableLights(const Scene& scene);
std::string lightName(const Scene& scene, EditableLight light);  // "sphere light 'warm bulb'", "lamp sphere 24"
LightParams lightParams(const Scene& scene, EditableLight light);
// Writes the values back, clamped to what the renderer accepts (radius >= 0, colour and intensity
// >= 0, a spot's angle in (0, 90] degrees, its inner cone keeping its share of it). An emissive sphere's
// radius stays above zero; its emission goes to its material, which its other users share.
void setLightParams(Scene& scene, EditableLight light, const LightParams& params);

}  // namespace penumbra
