// A room built to show what a BVH does (look at it with `penumbra view bvh-lesson` and the heat
// map debug view): on one side a few cubes far apart, which the SAH separates into cheap, mostly
// empty boxes; on the other a dense cluster of small cubes, where rays test many nodes; and a
// slab laid diagonally across the room, whose axis-aligned bounds are mostly empty space and so
// overlap everything near them; and, as the WebGPU renderer's BVH lesson has them, boxes nested
// inside each other (two open boxes and a cube, whose bounds nest as the BVH's own boxes do) and
// a checkered floor grid of tiles at two heights (many flat boxes side by side).
#include <cmath>

#include "scene/presets/mesh_builder.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

// An axis-aligned (before rotating by `yawRadians` about +y) box, every face wound outward.
void addBox(Mesh& mesh, Vec3 centre, Vec3 half, float yawRadians = 0.0f) {
    const float c = std::cos(yawRadians), s = std::sin(yawRadians);
    Vec3 p[8];
    for (int i = 0; i < 8; ++i) {
        Vec3 local{(i & 1) == ((i >> 1) & 1) ? -half.x : half.x, (i & 2) ? half.y : -half.y, (i & 4) ? half.z : -half.z};
        p[i] = centre + Vec3{c * local.x + s * local.z, local.y, -s * local.x + c * local.z};
    }
    // Corner order as in the furnace preset: 0..3 at -z counter-clockwise seen from +z, 4..7 at +z.
    addQuad(mesh, p[3], p[2], p[1], p[0]);  // -z
    addQuad(mesh, p[6], p[7], p[4], p[5]);  // +z
    addQuad(mesh, p[7], p[3], p[0], p[4]);  // -x
    addQuad(mesh, p[2], p[6], p[5], p[1]);  // +x
    addQuad(mesh, p[0], p[1], p[5], p[4]);  // -y
    addQuad(mesh, p[7], p[6], p[2], p[3]);  // +y
}

// addBox without its -z face: an open box one can look into from -z.
void addOpenBox(Mesh& mesh, Vec3 centre, Vec3 half) {
    addBox(mesh, centre, half);
    mesh.positions.erase(mesh.positions.begin(), mesh.positions.begin() + 4);  // the -z quad comes first
    mesh.indices.erase(mesh.indices.begin(), mesh.indices.begin() + 6);
    for (std::uint32_t& i : mesh.indices) i -= 4;
}

// Nested boxes, all centred on `centre`, open toward the camera (-z): an outer and a middle open
// box and a solid cube inside them.
void addNestedBoxes(Scene& scene, Vec3 centre, const std::uint32_t (&materials)[3]) {
    const char* names[3] = {"nested box outer", "nested box middle", "nested box inner"};
    const float halves[3] = {0.9f, 0.55f, 0.25f};
    for (int k = 0; k < 3; ++k) {
        Mesh box{.name = names[k], .material = materials[k]};
        if (k < 2) addOpenBox(box, centre, Vec3{halves[k]});
        else addBox(box, centre, Vec3{halves[k]});
        scene.meshes.push_back(std::move(box));
    }
}

// A 4 x 4 checkerboard of floor tiles from `corner` (least x and z), the light and dark squares
// at two heights just above the floor (as the WebGPU renderer's grid alternates its elevations).
void addFloorGrid(Scene& scene, Vec3 corner, std::uint32_t lightMat, std::uint32_t darkMat) {
    constexpr float kTileX = 0.75f, kTileZ = 0.5f, kLow = 0.005f, kHigh = 0.03f;
    Mesh light{.name = "floor grid light", .material = lightMat}, dark{.name = "floor grid dark", .material = darkMat};
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) {
            const bool even = (row + col) % 2 == 0;
            const float x0 = corner.x + kTileX * float(col), z0 = corner.z + kTileZ * float(row);
            const float y = corner.y + (even ? kLow : kHigh);
            addQuad(even ? light : dark, {x0, y, z0 + kTileZ}, {x0 + kTileX, y, z0 + kTileZ}, {x0 + kTileX, y, z0},
                    {x0, y, z0});
        }
    scene.meshes.push_back(std::move(light));
    scene.meshes.push_back(std::move(dark));
}

}  // namespace

Scene makeBvhLesson() {
    Scene scene;
    scene.name = "bvh-lesson";
    std::uint32_t walls = addMaterial(scene, "walls", {0.75f, 0.75f, 0.72f});
    std::uint32_t floor = addMaterial(scene, "floor", {0.45f, 0.42f, 0.40f});
    std::uint32_t sparse = addMaterial(scene, "separate cubes", {0.15f, 0.3f, 0.7f});
    std::uint32_t dense = addMaterial(scene, "cluster", {0.8f, 0.45f, 0.1f});
    std::uint32_t slab = addMaterial(scene, "diagonal slab", {0.2f, 0.6f, 0.25f});
    std::uint32_t light = addMaterial(scene, "light", Vec3{0.8f}, {8.0f, 7.5f, 6.5f});

    // The room: 10 m square, 3 m high, walls wound to face inward.
    const float r = 5.0f, h = 3.0f;
    Mesh room{.name = "room", .material = walls};
    addQuad(room, {-r, 0, -r}, {r, 0, -r}, {r, h, -r}, {-r, h, -r});
    addQuad(room, {r, 0, r}, {-r, 0, r}, {-r, h, r}, {r, h, r});
    addQuad(room, {-r, 0, r}, {-r, 0, -r}, {-r, h, -r}, {-r, h, r});
    addQuad(room, {r, 0, -r}, {r, 0, r}, {r, h, r}, {r, h, -r});
    addQuad(room, {-r, h, -r}, {r, h, -r}, {r, h, r}, {-r, h, r});
    scene.meshes.push_back(std::move(room));
    Mesh ground{.name = "floor", .material = floor};
    addQuad(ground, {-r, 0, r}, {r, 0, r}, {r, 0, -r}, {-r, 0, -r});
    scene.meshes.push_back(std::move(ground));
    // A 2 m square ceiling light, 1 cm below the ceiling, facing down.
    Mesh lamp{.name = "light", .material = light};
    addQuad(lamp, {-1, h - 0.01f, -1}, {1, h - 0.01f, -1}, {1, h - 0.01f, 1}, {-1, h - 0.01f, 1});
    scene.meshes.push_back(std::move(lamp));

    // -x side, behind the slab: five cubes metres apart.
    Mesh separate{.name = "separate cubes", .material = sparse};
    for (Vec3 at : {Vec3{-4.0f, 0.3f, 0.0f}, Vec3{-3.5f, 0.3f, 3.0f}, Vec3{-2.0f, 0.3f, 1.5f}, Vec3{-4.0f, 0.3f, -3.0f},
                    Vec3{-1.5f, 0.3f, 3.8f}})
        addBox(separate, at, Vec3{0.3f});
    scene.meshes.push_back(std::move(separate));

    // +x side, in front of the slab: 6 x 6 x 3 small cubes 5 cm apart.
    Mesh cluster{.name = "cluster", .material = dense};
    for (int y = 0; y < 3; ++y)
        for (int z = 0; z < 6; ++z)
            for (int x = 0; x < 6; ++x)
                addBox(cluster, Vec3{2.5f + 0.25f * x, 0.1f + 0.25f * y, 0.5f + 0.25f * z}, Vec3{0.1f});
    scene.meshes.push_back(std::move(cluster));

    // Across the room on the diagonal z = x: 8 m long, 1.2 m high, 15 cm thick.
    Mesh diagonal{.name = "diagonal slab", .material = slab};
    addBox(diagonal, Vec3{0.0f, 0.6f, 0.0f}, Vec3{4.0f, 0.6f, 0.075f}, -0.7853982f);
    scene.meshes.push_back(std::move(diagonal));

    // Behind the slab, clear of it and of the separate cubes: the nested boxes, hovering 10 cm up.
    const std::uint32_t nested[3] = {addMaterial(scene, "outer box", {0.85f, 0.75f, 0.1f}),
                                     addMaterial(scene, "middle box", {0.1f, 0.7f, 0.7f}),
                                     addMaterial(scene, "inner cube", {0.8f, 0.15f, 0.1f})};
    addNestedBoxes(scene, Vec3{0.0f, 1.0f, 3.0f}, nested);
    // In front of the slab, near the camera, in the corner the cluster leaves free: the floor grid.
    addFloorGrid(scene, Vec3{0.5f, 0.0f, -4.5f}, addMaterial(scene, "light tiles", Vec3{0.8f}),
                 addMaterial(scene, "dark tiles", Vec3{0.3f}));

    // From above the middle of one wall, looking over the slab at both sides.
    scene.camera.position = {0.0f, 2.8f, -4.8f};
    scene.camera.lookAt = {0.0f, 0.2f, 0.8f};
    scene.camera.fovYDegrees = 65.0f;
    return scene;
}

}  // namespace penumbra
