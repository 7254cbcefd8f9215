#include "scene/scene.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "scene/environment.h"

namespace penumbra {

std::size_t Scene::triangleCount() const {
    std::size_t n = 0;
    for (const Mesh& m : meshes) n += m.triangleCount();
    return n;
}

Aabb Scene::bounds() const {
    Aabb box;
    for (const Mesh& m : meshes)
        for (Vec3 p : m.positions) box.grow(p);
    for (const Sphere& s : spheres) {
        box.grow(s.center - Vec3{s.radius});
        box.grow(s.center + Vec3{s.radius});
    }
    for (const Sprite& s : sprites) box.grow(spriteBounds(s));
    for (const Instance& i : instances) {
        if (i.prototype >= prototypes.size()) continue;
        Aabb local;
        for (const Mesh& m : prototypes[i.prototype].meshes)
            for (Vec3 p : m.positions) local.grow(p);
        box.grow(transformBounds(local, i.transform));
    }
    return box;
}

Aabb spriteBounds(const Sprite& s) {
    // The card turns about its axis, so it sweeps a vertical cylinder.
    const float r = std::max(std::abs(s.left), std::abs(s.right));
    Aabb box;
    box.grow(s.position + Vec3{-r, s.bottom, -r});
    box.grow(s.position + Vec3{r, s.top, r});
    return box;
}

namespace {

// Each texture's pixels match its size, and an animated texture's frames are all in the scene.
void validateTextures(const std::vector<Texture>& textures) {
    for (std::size_t i = 0; i < textures.size(); ++i) {
        const Texture& tex = textures[i];
        if (tex.width <= 0 || tex.height <= 0 ||
            tex.rgba.size() != std::size_t(tex.width) * std::size_t(tex.height) * 4)
            throw Error("texture '" + tex.name + "' has inconsistent size or pixel data");
        const TextureAnimation& a = tex.animation;
        if (a.frames == 1 && a.frame == 0) continue;
        // The shader moves between the cycle's frames by index: they must all exist.
        if (a.frames < 1 || a.frame < 0 || a.frame >= a.frames || std::size_t(a.frame) > i ||
            i - std::size_t(a.frame) + std::size_t(a.frames) > textures.size() || !(a.secondsPerFrame > 0) ||
            !std::isfinite(a.secondsPerFrame))
            throw Error("texture '" + tex.name + "' is frame " + std::to_string(a.frame) + " of " +
                        std::to_string(a.frames) + " of an animation whose frames are not all in the scene");
    }
}

void validateMaterials(const Scene& scene) {
    for (const Material& mat : scene.materials) {
        for (const TextureRef* ref : {&mat.albedoTexture, &mat.emissionTexture, &mat.normalTexture,
                                      &mat.metallicRoughnessTexture})
            if (ref->texture >= static_cast<int>(scene.textures.size()))
                throw Error("material '" + mat.name + "' uses texture " + std::to_string(ref->texture) +
                            ", which does not exist");
        if (!isFinite(mat.albedo) || minComponent(mat.albedo) < 0 || maxComponent(mat.albedo) > 1)
            throw Error("material '" + mat.name + "': albedo must be finite and within [0, 1]");
        if (!isFinite(mat.emission) || minComponent(mat.emission) < 0)
            throw Error("material '" + mat.name + "': emission must be finite and >= 0");
    }
}

void validateMesh(const Mesh& m, std::size_t materialCount, const std::string& where) {
    if (m.indices.size() % 3 != 0)
        throw Error(where + ": index count " + std::to_string(m.indices.size()) + " is not a multiple of 3");
    if (m.material >= materialCount)
        throw Error(where + ": material " + std::to_string(m.material) + " does not exist");
    if (!m.normals.empty() && m.normals.size() != m.positions.size())
        throw Error(where + ": normal count differs from position count");
    if (!m.uvs.empty() && m.uvs.size() != m.positions.size())
        throw Error(where + ": uv count differs from position count");
    for (std::uint32_t i : m.indices)
        if (i >= m.positions.size())
            throw Error(where + ": index " + std::to_string(i) + " is past the " +
                        std::to_string(m.positions.size()) + " vertices");
    for (Vec3 p : m.positions)
        if (!isFinite(p)) throw Error(where + ": a vertex position is not finite");
}

// Instances place prototypes that exist with finite, invertible transforms; their animations move
// instances that exist, along valid tracks.
void validateInstances(const Scene& scene) {
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& instance = scene.instances[i];
        const std::string where = "instance " + std::to_string(i) + " in scene '" + scene.name + "'";
        if (instance.prototype >= scene.prototypes.size())
            throw Error(where + ": it places prototype " + std::to_string(instance.prototype) +
                        ", which does not exist");
        for (const auto& row : instance.transform.m)
            for (float v : row)
                if (!std::isfinite(v)) throw Error(where + ": its transform is not finite");
        const float det = instance.transform.determinant();
        if (!(std::abs(det) > 1e-12f) || !std::isfinite(1.0f / det))
            throw Error(where + ": its transform flattens it (determinant 0); give it a nonzero scale");
    }
    for (std::size_t i = 0; i < scene.instanceAnimations.size(); ++i) {
        const InstanceAnimation& a = scene.instanceAnimations[i];
        const std::string where = "animation " + std::to_string(i) + " in scene '" + scene.name + "'";
        if (a.instance >= scene.instances.size()) throw Error(where + ": it moves an instance that does not exist");
        for (const NodeMotion& m : a.chain) {
            if (m.scripted) validateMotion(*m.scripted, where);
            for (const Track* t : {&m.translationTrack, &m.rotationTrack, &m.scaleTrack}) validateTrack(*t, where);
        }
    }
}

void validateSpheres(const Scene& scene) {
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        const std::string where = "sphere " + std::to_string(i) + " in scene '" + scene.name + "'";
        if (!isFinite(s.center)) throw Error(where + ": centre is not finite");
        if (!(s.radius > 0) || !std::isfinite(s.radius)) throw Error(where + ": radius must be a finite number > 0");
        if (s.material >= scene.materials.size())
            throw Error(where + ": material " + std::to_string(s.material) + " does not exist");
    }
    std::vector<bool> grouped(scene.spheres.size(), false);
    for (const SphereGroup& g : scene.sphereGroups)
        for (std::uint32_t i : g.spheres) {
            const std::string where = "sphere group '" + g.name + "' in scene '" + scene.name + "'";
            if (i >= scene.spheres.size()) throw Error(where + ": sphere " + std::to_string(i) + " does not exist");
            if (grouped[i]) throw Error(where + ": sphere " + std::to_string(i) + " is already in a group");
            grouped[i] = true;
        }
}

void validateSprites(const Scene& scene) {
    for (std::size_t i = 0; i < scene.sprites.size(); ++i) {
        const Sprite& s = scene.sprites[i];
        const std::string where = "sprite " + std::to_string(i) + " in scene '" + scene.name + "'";
        const float extents[] = {s.left, s.right, s.bottom, s.top};
        if (!isFinite(s.position) || !isFinite(s.facing)) throw Error(where + ": position or facing is not finite");
        for (float e : extents)
            if (!std::isfinite(e) || std::abs(e) > 1e6f) throw Error(where + ": an extent is not a finite size");
        if (!(s.left < s.right) || !(s.bottom < s.top)) throw Error(where + ": its card has no area");
        if (s.rotations != 1 && s.rotations != 8) throw Error(where + ": it must have 1 or 8 views");
        if (s.material >= scene.materials.size())
            throw Error(where + ": material " + std::to_string(s.material) + " does not exist");
    }
}

}  // namespace

void Scene::validate() const {
    if (materials.empty()) throw Error("scene '" + name + "' has no materials");
    validateTextures(textures);
    validateMaterials(*this);
    for (const Mesh& m : meshes) validateMesh(m, materials.size(), "mesh '" + m.name + "' in scene '" + name + "'");
    for (const Prototype& p : prototypes)
        for (const Mesh& m : p.meshes)
            validateMesh(m, materials.size(), "mesh '" + m.name + "' of instanced '" + p.name + "'");
    validateInstances(*this);
    validateSpheres(*this);
    validateSprites(*this);
    for (const Light& l : lights)
        if (!(l.angularRadius >= 0 && l.angularRadius <= kMaxAngularRadius))
            throw Error("light '" + l.name + "': angular radius must be within [0, 45] degrees");
    validateEnvironment(environment);
}

void attachTorch(Scene& scene) {
    if (!scene.torch.enabled || !(scene.torch.intensity > 0)) return;
    Light torch;
    torch.name = "torch";
    // 15 cm below the eye: the shadows it casts are visible, as with a torch held at the chest.
    Vec3 up = normalize(scene.camera.up);
    torch.position = scene.camera.position - up * 0.15f;
    torch.color = scene.torch.color;
    torch.intensity = scene.torch.intensity;
    torch.range = scene.torch.range;
    torch.moves = true;
    scene.lights.push_back(torch);
}

std::size_t sceneBytes(const Scene& scene) {
    std::size_t bytes = sizeof(Scene) + scene.materials.size() * sizeof(Material) + scene.lights.size() * sizeof(Light) +
                        scene.spheres.size() * sizeof(Sphere) + scene.sprites.size() * sizeof(Sprite);
    auto meshBytes = [](const Mesh& m) {
        return sizeof(Mesh) + m.positions.capacity() * sizeof(Vec3) + m.normals.capacity() * sizeof(Vec3) +
               m.uvs.capacity() * sizeof(Vec2) + m.indices.capacity() * sizeof(std::uint32_t);
    };
    for (const Mesh& m : scene.meshes) bytes += meshBytes(m);
    for (const Prototype& p : scene.prototypes)
        for (const Mesh& m : p.meshes) bytes += meshBytes(m);
    bytes += scene.instances.size() * sizeof(Instance);
    for (const Texture& t : scene.textures) bytes += sizeof(Texture) + t.rgba.capacity();
    if (scene.environment.map) bytes += scene.environment.map->radiance.capacity() * sizeof(Vec3);
    return bytes;
}

std::vector<SceneTriangle> flattenTriangles(const Scene& scene) {
    std::vector<SceneTriangle> out;
    out.reserve(scene.triangleCount());
    for (const Mesh& m : scene.meshes) appendTriangles(m, out);
    return out;
}

void appendTriangles(const Mesh& m, std::vector<SceneTriangle>& out) {
    {
        for (std::size_t t = 0; t < m.triangleCount(); ++t) {
            SceneTriangle tri;
            tri.material = m.material;
            for (int k = 0; k < 3; ++k) tri.p[k] = m.positions[m.indices[3 * t + k]];
            Vec3 geometric = normalize(cross(tri.p[1] - tri.p[0], tri.p[2] - tri.p[0]));
            for (int k = 0; k < 3; ++k) {
                std::uint32_t i = m.indices[3 * t + k];
                Vec3 n = m.normals.empty() ? geometric : normalize(m.normals[i]);
                // A zero or broken normal falls back to the face's own.
                tri.n[k] = (isFinite(n) && dot(n, n) > 0.5f) ? n : geometric;
                tri.uv[k] = m.uvs.empty() ? Vec2{} : m.uvs[i];
            }
            out.push_back(tri);
        }
    }
}

void validateCamera(const Camera& camera) {
    Vec3 forward = camera.lookAt - camera.position;
    if (!isFinite(camera.position) || !isFinite(camera.lookAt) || !isFinite(camera.up))
        throw UsageError("camera position, look-at and up must be finite numbers");
    if (length(forward) <= 0)
        throw UsageError("camera look-at point equals its position; give --look-at a different point");
    if (length(cross(normalize(forward), normalize(camera.up))) < 1e-4f)
        throw UsageError("camera up vector is zero or parallel to the view direction; pass another --up");
    if (!(camera.fovYDegrees > 0 && camera.fovYDegrees < 180))
        throw UsageError("field of view must be between 0 and 180 degrees (got " +
                         std::to_string(camera.fovYDegrees) + "); pass e.g. --fov 40");
    if (!(camera.apertureRadius >= 0) || !std::isfinite(camera.apertureRadius))
        throw UsageError("aperture radius must be a finite number >= 0 metres (0: pinhole); pass e.g. --aperture 0.01");
    if (!(camera.focusDistance >= 0) || !std::isfinite(camera.focusDistance))
        throw UsageError("focus distance must be a finite number > 0 metres; pass e.g. --focus-distance 2");
}

float effectiveFocusDistance(const Camera& camera) {
    return camera.focusDistance > 0 ? camera.focusDistance : length(camera.lookAt - camera.position);
}

}  // namespace penumbra
