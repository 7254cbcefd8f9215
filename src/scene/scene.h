// The scene model: plain data, no GPU types. Loaders and presets produce it; bvh/ and render/
// consume it. Lights are emissive materials on triangles (area lights).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/aabb.h"
#include "core/vec.h"

namespace penumbra {

struct Material {
    std::string name;
    Vec3 albedo{0.8f};  // diffuse reflectance per channel, [0, 1]
    Vec3 emission{0};   // radiance leaving the front face (counter-clockwise winding), >= 0

    bool isEmissive() const { return maxComponent(emission) > 0.0f; }
};

// An indexed triangle mesh with one material. normals and uvs are either empty or one per
// position; missing normals mean flat shading.
struct Mesh {
    std::string name;
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<Vec2> uvs;
    std::vector<std::uint32_t> indices;  // three per triangle
    std::uint32_t material = 0;

    std::size_t triangleCount() const { return indices.size() / 3; }
};

struct Camera {
    Vec3 position{0, 0, 1};
    Vec3 lookAt{0, 0, 0};
    Vec3 up{0, 1, 0};
    float fovYDegrees = 40.0f;  // vertical field of view
};

struct Scene {
    std::string name;
    std::vector<Material> materials;
    std::vector<Mesh> meshes;
    Camera camera;

    std::size_t triangleCount() const;
    Aabb bounds() const;
    // Throws Error naming the mesh and the problem (index out of range, non-finite vertex,
    // bad material id, ...). Loaders call it before handing a scene on.
    void validate() const;
};

// One triangle with everything the renderer needs, in world space.
struct SceneTriangle {
    Vec3 p[3];
    Vec3 n[3];  // shading normals (the geometric normal when the mesh has none)
    Vec2 uv[3];
    std::uint32_t material = 0;
};

// All triangles of the scene in mesh order.
std::vector<SceneTriangle> flattenTriangles(const Scene& scene);

// Checks a camera and throws a UsageError naming the problem (look-at equal to the position,
// up parallel to the view direction, field of view outside (0, 180)).
void validateCamera(const Camera& camera);

}  // namespace penumbra
