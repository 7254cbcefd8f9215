// What a user asks of the environment (a file, the procedural sky, intensity, rotation), from the
// command line or a scene file, and applying it to a scene.
#pragma once

#include <optional>
#include <string>

#include "scene/io/env_sky.h"
#include "scene/scene.h"

namespace penumbra {

struct EnvironmentSpec {
    std::string file;              // a .hdr or .exr map, "sky" for the procedural sky, or empty
    std::optional<SkyParams> sky;  // sky parameters (implies the sky)
    std::optional<float> intensity;
    std::optional<float> rotationDegrees;

    bool empty() const { return file.empty() && !sky && !intensity && !rotationDegrees; }
};

// Replaces the scene's map (and sun) when the spec names one, then sets intensity and rotation
// when given. Throws Error for unreadable maps, UsageError for out-of-range numbers.
void applyEnvironment(Scene& scene, const EnvironmentSpec& spec);

}  // namespace penumbra
