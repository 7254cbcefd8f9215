// Every light the integrator can sample, as the unified light sampler (shaders/lib/
// light_sampler.glsl) sees them: LightRef entries, top-level ones first (the environment,
// directional lights, lights that move every frame), then the leaves of the light BVH over
// every bounded light (emissive triangles and spheres, point and spot lights).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "render/light_tree.h"
#include "scene/scene.h"
#include "shared/types.h"

namespace penumbra {

struct EmissiveTriangle {
    std::uint32_t slot;  // primitive slot (leaf order)
    Vec3 p[3];
    float radiance;      // luminance of the emission, textures averaged
};

struct LightListInput {
    std::vector<EmissiveTriangle> triangles;
    std::span<const shader::SphereLight> spheres;
    std::span<const shader::PunctualLight> punctual;
    std::vector<bool> punctualMoves;  // per punctual light: moved every frame (kept out of the tree)
    bool environment = false;         // the environment is light-sampled
};

struct LightList {
    std::vector<shader::LightRef> refs;
    // nodes[k]: the bounds of top-level entry k (unused for infinite lights).
    std::vector<shader::LightNode> nodes;
    // The light BVH over the rest, compact (compactLightTree); empty when there is none.
    std::vector<shader::LightTreeNode> tree;
    std::uint32_t topCount = 0;
    // LightRef of each emissive primitive (triangle or sphere), for TriAttribs::lightIndex.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> primitiveLights;  // (slot, ref)
};

LightList buildLightList(const LightListInput& input);

// The bounds of a point or spot light as the light BVH and the top-level list use them.
LightBounds punctualBounds(const shader::PunctualLight& light);

// Mean linear luminance of a texture's texels (sRGB decoded when it is colour data).
float meanLuminance(const Texture& texture);
// The same for textures[index], averaged over its animation's frames when it has them.
float meanLuminanceOverFrames(const std::vector<Texture>& textures, std::size_t index);

// The top-level entry that refers to punctual light `index`, if any (the viewer moves the torch).
std::optional<std::uint32_t> topEntryOfPunctual(std::span<const shader::LightRef> refs, std::uint32_t topCount,
                                                std::uint32_t index);

}  // namespace penumbra
