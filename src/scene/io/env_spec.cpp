#include "scene/io/env_spec.h"

#include <cmath>

#include "core/error.h"
#include "scene/io/env_load.h"

namespace penumbra {

void applyEnvironment(Scene& scene, const EnvironmentSpec& spec) {
    Environment& env = scene.environment;
    if (spec.sky || spec.file == "sky") {
        Sky sky = makeSky(spec.sky.value_or(SkyParams{}));
        env.map = std::move(sky.map);
        env.sun = sky.sun;
    } else if (!spec.file.empty()) {
        env.map = loadEnvironmentMap(spec.file);
        env.sun.reset();
    }
    if (spec.intensity) {
        if (!(*spec.intensity >= 0 && *spec.intensity <= 1e9f))
            throw UsageError("environment intensity must be between 0 and 1e9");
        env.intensity = *spec.intensity;
    }
    if (spec.rotationDegrees) {
        if (!(std::abs(*spec.rotationDegrees) <= 3600.0f))
            throw UsageError("environment rotation must be between -3600 and 3600 degrees");
        env.rotationDegrees = *spec.rotationDegrees;
    }
}

}  // namespace penumbra
