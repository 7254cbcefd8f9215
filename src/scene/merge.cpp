#include "scene/merge.h"

#include <cmath>
#include <utility>

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
    const bool mirrored = transform.determinant() < 0;
    for (Mesh& mesh : part.meshes) {
        for (Vec3& p : mesh.positions) p = transform.point(p);
        for (Vec3& n : mesh.normals) n = transform.normal(n);
        if (mirrored)
            for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
        mesh.material += materialBase;
        into.meshes.push_back(std::move(mesh));
    }
    // A sphere stays a sphere: its radius scales by the transform's mean scale factor (exact for
    // uniform scaling; non-uniform scaling of a sphere would make an ellipsoid).
    const float radiusScale = meanScale(transform);
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
