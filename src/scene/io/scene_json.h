// Penumbra's own scene file (.json): assets with transforms, camera, lights, material overrides
// and render settings. Documented in docs/SCENES.md.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "scene/scene.h"

namespace penumbra {

// Render settings a scene file may carry; unset fields keep the command line's values.
struct SceneFileSettings {
    std::optional<std::uint32_t> samplesPerPixel, maxBounces, width, height;
    std::optional<float> exposure;
};

Scene loadSceneJson(const std::filesystem::path& path, SceneFileSettings* settings = nullptr);
Scene loadSceneJsonFromText(std::string_view text, const std::filesystem::path& baseDir, const std::string& name,
                            SceneFileSettings* settings = nullptr);

// Writes a scene as JSON that loadSceneJson reads back to the same scene (meshes inline).
std::string sceneToJson(const Scene& scene);

}  // namespace penumbra
