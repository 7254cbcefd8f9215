#include "scene/objects.h"

#include "core/error.h"

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

std::string instanceName(const Scene& scene, std::uint32_t instance) {
    PN_CHECK(instance < scene.instances.size());
    const std::uint32_t prototype = scene.instances[instance].prototype;
    const std::string name = prototype < scene.prototypes.size() ? scene.prototypes[prototype].name : "";
    return "instance " + std::to_string(instance) + (name.empty() ? "" : " (" + name + ")");
}

void moveInstance(Scene& scene, std::uint32_t instance, Vec3 offset, float yawDegrees) {
    PN_CHECK(instance < scene.instances.size());
    // A turn about the object's own origin, then a move of that origin (editedTransform's form).
    Affine edit = Affine::eulerDegrees({0, yawDegrees, 0});
    for (int i = 0; i < 3; ++i) edit.m[i][3] = offset[i];
    Affine& t = scene.instances[instance].transform;
    t = editedTransform(edit, t);
    // An animated instance keeps the edit, so its animation does not undo it on the next frame.
    for (InstanceAnimation& a : scene.instanceAnimations)
        if (a.instance == instance) a.userEdit = composeEdits(edit, a.userEdit);
}

}  // namespace penumbra
