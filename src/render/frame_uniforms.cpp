#include "render/frame_uniforms.h"
#include "render/walks.h"
#include "shared/constants.h"

#include <cmath>

namespace penumbra {

shader::FrameUniforms makeFrameUniforms(const Camera& camera, Vec3 background, const RenderSettings& settings,
                                        std::uint32_t lightNodeCount, std::uint32_t triCount,
                                        std::uint32_t nodeCount) {
    validateCamera(camera);
    shader::FrameUniforms f{};
    Vec3 forward = normalize(camera.lookAt - camera.position);
    // Right-handed: with +y up and looking down +z, +x is on the left of the image.
    Vec3 right = normalize(cross(forward, camera.up));
    Vec3 up = cross(right, forward);
    f.cameraPosition = camera.position;
    f.cameraForward = forward;
    f.cameraRight = right;
    f.cameraUp = up;
    f.tanHalfFovY = std::tan(degreesToRadians(camera.fovYDegrees * 0.5f));
    f.aspect = float(settings.width) / float(settings.height);
    f.width = settings.width;
    f.height = settings.height;
    f.maxBounces = settings.maxBounces;
    f.rouletteStart = settings.rouletteStart;
    f.shadowRouletteShare = settings.shadowRouletteShare;
    f.textureSaturation = settings.textureSaturation;
    f.renderDistance = settings.renderDistance;
    f.flags = settings.pixelJitter ? 0u : PN_FRAME_NO_JITTER;
    f.lightNodeCount = lightNodeCount;
    f.triCount = triCount;
    f.nodeCount = nodeCount;
    f.accel = walkInfo(settings.accel).shaderId;
    f.seed = settings.seed;
    f.samplesPerPass = settings.samplesPerPass;
    f.background = background;
    // Thin lens: the camera ray starts on a disk of this radius and aims at the plane this far
    // along cameraForward (0 radius: a pinhole, and the shader draws no lens sample).
    f.lensRadius = camera.apertureRadius;
    f.focusDistance = effectiveFocusDistance(camera);
    f.envWidth = 0;
    f.envHeight = 0;
    f.envIntensity = 1.0f;
    f.lightPickUniform = settings.uniformLightPick ? 1u : 0u;
    f.time = settings.time;
    f.misMode = settings.mis == MisMode::LightOnly  ? PN_MIS_LIGHT_ONLY
                : settings.mis == MisMode::BsdfOnly ? PN_MIS_BSDF_ONLY
                                                    : PN_MIS_BOTH;
    return f;
}

shader::FrameUniforms makeSceneFrameUniforms(const Camera& camera, Vec3 background, const Environment& env,
                                             const RenderSettings& settings, const GpuScene& scene) {
    shader::FrameUniforms f =
        makeFrameUniforms(camera, background, settings, scene.lightNodeCount, scene.triCount, scene.nodeCount);
    f.topLightCount = scene.topLightCount;
    f.envLuminance = scene.envLuminance;
    f.lightRefCount = scene.lightRefCount;
    f.punctualCount = scene.punctualCount;
    f.sphereLightCount = scene.sphereLightCount;
    f.instanceCount = scene.instanceCount;
    f.topRoot = scene.topRoot;
    f.lightGridOffset = scene.lightGridOffset;
    if (f.accel == PN_ACCEL_WIDE && scene.wideNodeCount == 0) f.accel = PN_ACCEL_BVH;  // two-level scenes
    setEnvironmentUniforms(f, env, scene.envWidth, scene.envHeight);
    return f;
}

void setEnvironmentUniforms(shader::FrameUniforms& frame, const Environment& env, std::uint32_t width,
                            std::uint32_t height) {
    frame.envWidth = width;
    frame.envHeight = height;
    frame.envIntensity = env.intensity;
    frame.envRotation = degreesToRadians(env.rotationDegrees);
}

void setPreviousCamera(shader::ViewerUniforms& viewer, const shader::FrameUniforms& previous) {
    viewer.prevCameraPosition = previous.cameraPosition;
    viewer.prevTanHalfFovY = previous.tanHalfFovY;
    viewer.prevCameraRight = previous.cameraRight;
    viewer.prevAspect = previous.aspect;
    viewer.prevCameraUp = previous.cameraUp;
    viewer.prevCameraForward = previous.cameraForward;
}

}  // namespace penumbra
