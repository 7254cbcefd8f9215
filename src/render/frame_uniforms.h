// Turns a scene camera and render settings into the shaders' per-frame constants.
#pragma once

#include "render/gpu_scene.h"
#include "render/settings.h"
#include "scene/scene.h"
#include "shared/types.h"

namespace penumbra {

// background: radiance of rays that leave the scene (Scene::background).
shader::FrameUniforms makeFrameUniforms(const Camera& camera, Vec3 background, const RenderSettings& settings,
                                        std::uint32_t lightNodeCount, std::uint32_t triCount,
                                        std::uint32_t nodeCount);

// The environment's fields: map size (0: the constant background), intensity, rotation.
void setEnvironmentUniforms(shader::FrameUniforms& frame, const Environment& env, std::uint32_t width,
                            std::uint32_t height);

// The frame for rendering `scene` as uploaded: makeFrameUniforms plus every count the GPU scene
// holds (lights, punctual lights, spheres, sphere lights) and its environment. The map itself is
// not read: only env's intensity and rotation.
shader::FrameUniforms makeSceneFrameUniforms(const Camera& camera, Vec3 background, const Environment& env,
                                             const RenderSettings& settings, const GpuScene& scene);

// The viewer passes reproject through the previous frame's camera: copies it from that frame.
void setPreviousCamera(shader::ViewerUniforms& viewer, const shader::FrameUniforms& previous);

}  // namespace penumbra
