#include "scene/merge.h"

#include <cmath>
#include <utility>

#include "scene/instances.h"

namespace penumbra {

float meanScale(const Affine& transform) { return std::cbrt(std::abs(transform.determinant())); }

Camera transformCamera(const Camera& camera, const Affine& transform) {
    Camera c = camera;
    c.position = transform.point(camera.position);
    c.lookAt = transform.point(camera.lookAt);
    c.up = normalize(transform.vector(camera.up));
    c.apertureRadius *= meanScale(transform);
    c.focusDistance *= meanScale(transform);
    return c;
}

void appendScene(Scene& into, Scene part, const Affine& transform) {
    const auto materialBase = static_cast<std::uint32_t>(into.materials.size());
    const auto textureBase = static_cast<int>(into.textures.size());
    for (Texture& t : part.textures) into.textures.push_back(std::move(t));
    for (Material& m : part.materials) {
        for (TextureRef* ref : {&m.albedoTexture, &m.emissionTexture, &m.normalTexture, &m.metallicRoughnessTexture})
            if (ref->present()) ref->texture += textureBase;
        into.materials.push_back(std::move(m));
    }
    for (Mesh& mesh : part.meshes) {
        mesh.material += materialBase;
        into.meshes.push_back(transformedMesh(std::move(mesh), transform));
    }
    // Instances stay instances: the part's transform goes in front of theirs.
    const auto prototypeBase = static_cast<std::uint32_t>(into.prototypes.size());
    for (Prototype& p : part.prototypes) {
        for (Mesh& mesh : p.meshes) mesh.material += materialBase;
        into.prototypes.push_back(std::move(p));
    }
    const auto instanceBase = static_cast<std::uint32_t>(into.instances.size());
    for (const Instance& i : part.instances) into.instances.push_back({prototypeBase + i.prototype, transform * i.transform});
    // Animated instances keep moving, placed by the part's transform (a fixed node above their chain).
    for (InstanceAnimation& a : part.instanceAnimations) {
        a.instance += instanceBase;
        NodeMotion placement;
        placement.fixed = transform;
        a.chain.insert(a.chain.begin(), placement);
        into.instanceAnimations.push_back(std::move(a));
    }
    // A sphere stays a sphere: its radius scales by the transform's mean scale factor (exact for
    // uniform scaling; non-uniform scaling of a sphere would make an ellipsoid).
    const float radiusScale = meanScale(transform);
    const auto sphereBase = static_cast<std::uint32_t>(into.spheres.size());
    for (SphereGroup& g : part.sphereGroups) {
        for (std::uint32_t& i : g.spheres) i += sphereBase;
        into.sphereGroups.push_back(std::move(g));
    }
    for (Sphere& s : part.spheres) {
        s.center = transform.point(s.center);
        s.radius *= radiusScale;
        s.material += materialBase;
        into.spheres.push_back(s);
    }
    // Sprites stay upright cards: their axis point moves, their size scales like a sphere's and
    // their facing turns with the transform's horizontal part.
    for (Sprite& s : part.sprites) {
        s.position = transform.point(s.position);
        for (float* e : {&s.left, &s.right, &s.bottom, &s.top}) *e *= radiusScale;
        Vec3 facing = transform.vector(s.facing);
        facing.y = 0;
        s.facing = dot(facing, facing) > 0 ? normalize(facing) : Vec3{1, 0, 0};
        s.material += materialBase;
        into.sprites.push_back(s);
    }
    for (Light& l : part.lights) {
        l.position = transform.point(l.position);
        l.direction = normalize(transform.vector(l.direction));
        l.radius *= radiusScale;
        into.lights.push_back(std::move(l));
    }
}

}  // namespace penumbra
