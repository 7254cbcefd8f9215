// Geometry: the Cornell box data published by the Cornell Program of Computer Graphics
// (millimetres, converted to metres here). Reflectances are the usual RGB reductions of the
// measured spectra; the light's radiance is the customary (17, 12, 4).
#include "scene/presets/mesh_builder.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

constexpr float kMm = 0.001f;
Vec3 mm(float x, float y, float z) { return Vec3{x, y, z} * kMm; }

// The published quads are listed in arbitrary winding; walls are diffuse on both sides, so only
// the light's winding matters (its front face must point down, into the room).
Mesh quadMesh(const char* name, std::uint32_t material, std::initializer_list<Vec3> corners) {
    Mesh mesh;
    mesh.name = name;
    mesh.material = material;
    const Vec3* c = corners.begin();
    for (std::size_t i = 0; i + 3 < corners.size(); i += 4) addQuad(mesh, c[i], c[i + 1], c[i + 2], c[i + 3]);
    return mesh;
}

}  // namespace

Scene makeCornellBox() {
    Scene scene;
    scene.name = "cornell";
    const Vec3 whiteAlbedo{0.725f, 0.71f, 0.68f};
    std::uint32_t white = addMaterial(scene, "white", whiteAlbedo);
    std::uint32_t red = addMaterial(scene, "red", {0.63f, 0.065f, 0.05f});
    std::uint32_t green = addMaterial(scene, "green", {0.14f, 0.45f, 0.091f});
    std::uint32_t light = addMaterial(scene, "light", {0.78f, 0.78f, 0.78f}, {17.0f, 12.0f, 4.0f});

    scene.meshes.push_back(quadMesh("floor", white, {mm(552.8f, 0, 0), mm(0, 0, 0), mm(0, 0, 559.2f), mm(549.6f, 0, 559.2f)}));
    scene.meshes.push_back(quadMesh("ceiling", white, {mm(556, 548.8f, 0), mm(556, 548.8f, 559.2f), mm(0, 548.8f, 559.2f), mm(0, 548.8f, 0)}));
    scene.meshes.push_back(quadMesh("back wall", white, {mm(549.6f, 0, 559.2f), mm(0, 0, 559.2f), mm(0, 548.8f, 559.2f), mm(556, 548.8f, 559.2f)}));
    scene.meshes.push_back(quadMesh("right wall", green, {mm(0, 0, 559.2f), mm(0, 0, 0), mm(0, 548.8f, 0), mm(0, 548.8f, 559.2f)}));
    scene.meshes.push_back(quadMesh("left wall", red, {mm(552.8f, 0, 0), mm(549.6f, 0, 559.2f), mm(556, 548.8f, 559.2f), mm(556, 548.8f, 0)}));
    // The light sits 0.1 mm below the ceiling so the two surfaces never tie in depth.
    scene.meshes.push_back(quadMesh("light", light, {mm(343, 548.7f, 227), mm(343, 548.7f, 332), mm(213, 548.7f, 332), mm(213, 548.7f, 227)}));
    scene.meshes.push_back(quadMesh("short block", white, {
        mm(130, 165, 65), mm(82, 165, 225), mm(240, 165, 272), mm(290, 165, 114),
        mm(290, 0, 114), mm(290, 165, 114), mm(240, 165, 272), mm(240, 0, 272),
        mm(130, 0, 65), mm(130, 165, 65), mm(290, 165, 114), mm(290, 0, 114),
        mm(82, 0, 225), mm(82, 165, 225), mm(130, 165, 65), mm(130, 0, 65),
        mm(240, 0, 272), mm(240, 165, 272), mm(82, 165, 225), mm(82, 0, 225)}));
    scene.meshes.push_back(quadMesh("tall block", white, {
        mm(423, 330, 247), mm(265, 330, 296), mm(314, 330, 456), mm(472, 330, 406),
        mm(423, 0, 247), mm(423, 330, 247), mm(472, 330, 406), mm(472, 0, 406),
        mm(472, 0, 406), mm(472, 330, 406), mm(314, 330, 456), mm(314, 0, 456),
        mm(314, 0, 456), mm(314, 330, 456), mm(265, 330, 296), mm(265, 0, 296),
        mm(265, 0, 296), mm(265, 330, 296), mm(423, 330, 247), mm(423, 0, 247)}));

    // The published camera: at (278, 273, -800) mm looking down +z, 35 mm lens on a 25 mm film,
    // a vertical field of view of 2 atan(12.5 / 35) = 39.31 degrees.
    scene.camera.position = mm(278, 273, -800);
    scene.camera.lookAt = mm(278, 273, 0);
    scene.camera.up = {0, 1, 0};
    scene.camera.fovYDegrees = 39.3077f;
    return scene;
}

}  // namespace penumbra
