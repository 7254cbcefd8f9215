// Turns a scene camera and render settings into the shaders' per-frame constants.
#pragma once

#include "render/settings.h"
#include "scene/scene.h"
#include "shared/types.h"

namespace penumbra {

// background: radiance of rays that leave the scene (Scene::background).
shader::FrameUniforms makeFrameUniforms(const Camera& camera, Vec3 background, const RenderSettings& settings,
                                        std::uint32_t lightCount, std::uint32_t triCount,
                                        std::uint32_t nodeCount);

// The environment's fields: map size (0: the constant background), intensity, rotation.
void setEnvironmentUniforms(shader::FrameUniforms& frame, const Environment& env, std::uint32_t width,
                            std::uint32_t height);

}  // namespace penumbra
