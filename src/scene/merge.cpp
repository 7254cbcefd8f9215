#include "scene/merge.h"

#include <utility>

namespace penumbra {

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
    for (Light& l : part.lights) {
        l.position = transform.point(l.position);
        l.direction = normalize(transform.vector(l.direction));
        into.lights.push_back(std::move(l));
    }
}

}  // namespace penumbra
