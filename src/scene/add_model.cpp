#include "scene/add_model.h"

#include <cmath>
#include <utility>

#include "core/error.h"
#include "scene/instances.h"
#include "scene/merge.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

constexpr float kViewShare = 1.0f / 1.5f;  // of the view's height the model's bounding sphere spans

}  // namespace

AddedModel addModelInFront(Scene& scene, Scene model, const Camera& camera, float maxDistance) {
    bakeAllInstances(model);
    Aabb box;
    for (const Mesh& m : model.meshes)
        for (const Vec3& p : m.positions) box.grow(p);
    if (box.empty() || model.triangleCount() == 0)
        throw Error("'" + model.name + "' has no triangles to add");
    model.lights.clear();
    model.spheres.clear();
    model.sphereGroups.clear();
    model.sprites.clear();
    // appendScene renumbers materials and their textures; meshes land in `holder`, recentred.
    Scene holder;
    holder.materials = std::move(scene.materials);
    holder.textures = std::move(scene.textures);
    const std::string name = model.name.empty() ? "model" : model.name;
    appendScene(holder, std::move(model), Affine::translation(-box.center()));
    scene.materials = std::move(holder.materials);
    scene.textures = std::move(holder.textures);
    scene.prototypes.push_back({name, std::move(holder.meshes)});

    const float radius = std::max(0.5f * length(box.extent()), 1e-6f);
    const float tanHalf = std::tan(degreesToRadians(camera.fovYDegrees * 0.5f));
    float distance = radius / (tanHalf * kViewShare);
    float scale = 1.0f;
    if (maxDistance > 0 && distance > maxDistance) {  // shrink it to fit the room ahead
        scale = maxDistance / distance;
        distance = maxDistance;
    }
    const Vec3 forward = normalize(camera.lookAt - camera.position);
    AddedModel added{static_cast<std::uint32_t>(scene.prototypes.size() - 1),
                     static_cast<std::uint32_t>(scene.instances.size())};
    scene.instances.push_back(
        {added.prototype, Affine::translation(camera.position + forward * distance) * Affine::scaling(Vec3{scale})});
    return added;
}

}  // namespace penumbra
