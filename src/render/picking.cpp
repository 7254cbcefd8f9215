#include "render/picking.h"

#include <cmath>

#include "bvh/traverse_cpu.h"
#include "bvh/two_level.h"
#include "core/error.h"
#include "render/frame_uniforms.h"
#include "shared/camera.h"

namespace penumbra {

Vec3 pixelRayDirection(const Camera& camera, std::uint32_t width, std::uint32_t height, float x, float y) {
    RenderSettings rs;
    rs.width = width;
    rs.height = height;
    return shader::cameraRayDirection(makeFrameUniforms(camera, Vec3{0}, rs, 0, 0, 0), Vec2{x, y});
}

Pick pickPixel(const SceneArrays& arrays, const Camera& camera, std::uint32_t width, std::uint32_t height, float x,
               float y) {
    RenderSettings rs;
    rs.width = width;
    rs.height = height;
    const shader::FrameUniforms f = makeFrameUniforms(camera, Vec3{0}, rs, 0, 0, 0);
    // The ray through the pixel's centre, as the G-buffer traces it.
    const Vec3 direction = pixelRayDirection(camera, width, height, std::floor(x) + 0.5f, std::floor(y) + 0.5f);
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
    if (hit.instance < arrays.instances.size()) pick.instance = arrays.instances[hit.instance].id;  // PN_NO_HIT: the world
    return pick;
}

}  // namespace penumbra
