#include "render/scene_objects.h"

#include <cmath>

#include "bvh/traverse_cpu.h"
#include "bvh/two_level.h"
#include "core/error.h"
#include "render/frame_uniforms.h"

namespace penumbra {

std::uint32_t sphereObject(const Scene& scene, std::size_t sphere) {
    return static_cast<std::uint32_t>(scene.meshes.size() + sphere);
}

bool isObject(const Scene& scene, std::uint32_t object) {
    return object != kNoObject && object < scene.meshes.size() + scene.spheres.size();
}

std::string objectName(const Scene& scene, std::uint32_t object) {
    PN_CHECK(isObject(scene, object));
    if (object < scene.meshes.size()) {
        const std::string& name = scene.meshes[object].name;
        return name.empty() ? "mesh " + std::to_string(object) : "mesh '" + name + "'";
    }
    return "sphere " + std::to_string(object - scene.meshes.size());
}

std::uint32_t objectMaterial(const Scene& scene, std::uint32_t object) {
    PN_CHECK(isObject(scene, object));
    if (object < scene.meshes.size()) return scene.meshes[object].material;
    return scene.spheres[object - scene.meshes.size()].material;
}

void translateObject(Scene& scene, std::uint32_t object, Vec3 offset) {
    PN_CHECK(isObject(scene, object));
    if (object < scene.meshes.size()) {
        for (Vec3& p : scene.meshes[object].positions) p = p + offset;
    } else {
        Sphere& s = scene.spheres[object - scene.meshes.size()];
        s.center = s.center + offset;
    }
}

Pick pickPixel(const SceneArrays& arrays, const Camera& camera, std::uint32_t width, std::uint32_t height, float x,
               float y) {
    RenderSettings rs;
    rs.width = width;
    rs.height = height;
    const shader::FrameUniforms f = makeFrameUniforms(camera, Vec3{0}, rs, 0, 0, 0);
    // cameraRayDirection in shaders/lib/camera.glsl at the pixel's centre.
    const float px = std::floor(x) + 0.5f, py = std::floor(y) + 0.5f;
    const float ndcX = 2.0f * px / float(width) - 1.0f, ndcY = 1.0f - 2.0f * py / float(height);
    const Vec3 direction = normalize(f.cameraForward + f.cameraRight * (ndcX * f.aspect * f.tanHalfFovY) +
                                     f.cameraUp * (ndcY * f.tanHalfFovY));
    Ray ray{f.cameraPosition, direction};
    const bvh::Hit hit = arrays.instances.empty()
                             ? bvh::closestHit(arrays.nodes, arrays.triVerts, ray)
                             : bvh::closestHit(bvh::TwoLevelView{arrays.nodes, arrays.triVerts, arrays.instances,
                                                                 arrays.topRoot},
                                               ray);
    Pick pick;
    if (hit.triangle == PN_NO_HIT) return pick;
    pick.primitive = hit.triangle;
    pick.material = arrays.triAttribs[hit.triangle].materialId;
    pick.object = hit.triangle < arrays.primitiveObject.size() ? arrays.primitiveObject[hit.triangle] : kNoObject;
    pick.depth = hit.t * dot(direction, f.cameraForward);
    return pick;
}

}  // namespace penumbra
