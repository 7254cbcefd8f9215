#include "scene/animation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace penumbra {
namespace {

struct PathValue {
    Vec3 position, lookAt;
    float fov;
};

PathValue valueOf(const CameraKey& k) { return {k.position, k.lookAt, k.fovYDegrees}; }

PathValue lerp(const PathValue& a, const PathValue& b, float t) {
    return {a.position + (b.position - a.position) * t, a.lookAt + (b.lookAt - a.lookAt) * t,
            a.fov + (b.fov - a.fov) * t};
}

// d value / d time at key i: central difference, one-sided at the ends.
PathValue tangentAt(const std::vector<CameraKey>& keys, std::size_t i) {
    const std::size_t lo = i == 0 ? 0 : i - 1;
    const std::size_t hi = std::min(i + 1, keys.size() - 1);
    const float dt = float(keys[hi].time - keys[lo].time);
    const PathValue a = valueOf(keys[lo]), b = valueOf(keys[hi]);
    return {(b.position - a.position) / dt, (b.lookAt - a.lookAt) / dt, (b.fov - a.fov) / dt};
}

// Cubic Hermite between keys i and i+1 at s in [0, 1] of the segment.
PathValue hermite(const std::vector<CameraKey>& keys, std::size_t i, float s) {
    const float h = float(keys[i + 1].time - keys[i].time);
    const float s2 = s * s, s3 = s2 * s;
    const float h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    const PathValue p0 = valueOf(keys[i]), p1 = valueOf(keys[i + 1]);
    const PathValue m0 = tangentAt(keys, i), m1 = tangentAt(keys, i + 1);
    auto mix = [&](Vec3 a, Vec3 ta, Vec3 b, Vec3 tb) { return a * h00 + ta * (h10 * h) + b * h01 + tb * (h11 * h); };
    return {mix(p0.position, m0.position, p1.position, m1.position), mix(p0.lookAt, m0.lookAt, p1.lookAt, m1.lookAt),
            p0.fov * h00 + m0.fov * (h10 * h) + p1.fov * h01 + m1.fov * (h11 * h)};
}

}  // namespace

Camera cameraOnPath(const CameraPath& path, const Camera& base, double seconds) {
    Camera camera = base;
    const auto& keys = path.keys;
    if (keys.empty()) return camera;
    PathValue v;
    if (!(seconds > keys.front().time)) {
        v = valueOf(keys.front());
    } else if (seconds >= keys.back().time) {
        v = valueOf(keys.back());
    } else {
        // The segment [keys[i].time, keys[i+1].time) that holds `seconds`.
        const auto after = std::upper_bound(keys.begin(), keys.end(), seconds,
                                            [](double t, const CameraKey& k) { return t < k.time; });
        const std::size_t i = std::size_t(after - keys.begin()) - 1;
        const float s = float((seconds - keys[i].time) / (keys[i + 1].time - keys[i].time));
        v = path.interpolation == PathInterpolation::Linear ? lerp(valueOf(keys[i]), valueOf(keys[i + 1]), s)
                                                            : hermite(keys, i, s);
    }
    camera.position = v.position;
    camera.lookAt = v.lookAt;
    // A cubic can overshoot between keys; the field of view stays in the range cameras allow.
    camera.fovYDegrees = std::clamp(v.fov, 0.01f, 179.99f);
    return camera;
}

void validateCameraPath(const CameraPath& path) {
    for (std::size_t i = 0; i < path.keys.size(); ++i) {
        const CameraKey& k = path.keys[i];
        const std::string where = "camera_path key " + std::to_string(i) + ": ";
        if (!std::isfinite(k.time) || !isFinite(k.position) || !isFinite(k.lookAt))
            throw Error(where + "time, position and look_at must be finite numbers");
        if (i > 0 && !(k.time > path.keys[i - 1].time))
            throw Error(where + "time " + std::to_string(k.time) + " is not after the previous key's " +
                        std::to_string(path.keys[i - 1].time) + "; keys must be in increasing time");
        if (length(k.lookAt - k.position) == 0.0f) throw Error(where + "look_at equals position");
        if (!(k.fovYDegrees > 0 && k.fovYDegrees < 180)) throw Error(where + "fov must be in (0, 180) degrees");
    }
}

bool isAnimated(const Scene& scene) { return !scene.cameraPath.keys.empty() || animatesGeometry(scene); }

bool animatesGeometry(const Scene& scene) { return !scene.instanceAnimations.empty(); }

void applyInstanceAnimations(Scene& scene, double seconds) {
    for (const InstanceAnimation& a : scene.instanceAnimations)
        if (a.instance < scene.instances.size())
            scene.instances[a.instance].transform = editedTransform(a.userEdit, chainTransform(a.chain, seconds));
}

void applySceneTime(Scene& scene, double seconds) {
    // Animated nodes (glTF animations) and scene-file motions move their instances.
    applyInstanceAnimations(scene, seconds);
    if (scene.cameraPath.keys.empty()) return;
    const Camera before = scene.camera;
    scene.camera = cameraOnPath(scene.cameraPath, scene.camera, seconds);
    validateCamera(scene.camera);
    // The torch (attachTorch) is carried with the camera: it moves by as much as the eye.
    const Vec3 moved = scene.camera.position - before.position;
    for (Light& light : scene.lights)
        if (light.moves) light.position = light.position + moved;
}

Scene sceneAtTime(const Scene& scene, double seconds) {
    Scene copy = scene;
    applySceneTime(copy, seconds);
    return copy;
}

}  // namespace penumbra
