// Suzanne in the Cornell box: the scene of "Casually Pathtracing with WebGPU", Blender's monkey
// head in the middle of the published Cornell room (its two blocks removed), lit by the ceiling
// light. The model is read at run time from Debian's assimp-testmodels (scripts/setup.sh
// installs it); it is never committed, and the preset says so in one line when it is missing.
#include <filesystem>

#include "core/error.h"
#include "core/transform.h"
#include "scene/io/assimp_loader.h"
#include "scene/merge.h"
#include "scene/presets/mesh_builder.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

constexpr float kHeadWidth = 0.30f;           // metres, ear to ear: the box is 0.556 m wide
const Vec3 kHeadCentre{0.278f, 0.22f, 0.28f};  // the room's middle, a little below half height
// The file is Blender's, z up with the face toward -y; a quarter turn about x stands it in the
// room's y-up frame, facing +z, and half a turn about y then faces it to the published camera,
// which looks down +z from z = -0.8 m.
constexpr float kStandDegrees = -90.0f;
constexpr float kTurnDegrees = 180.0f;

}  // namespace

const char* suzanneModelPath() { return "/usr/share/assimp/models/BLEND/Suzanne_248.blend"; }

Scene makeSuzanne() {
    const std::filesystem::path path = suzanneModelPath();
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw Error("the suzanne scene needs " + path.string() +
                    " (Debian package assimp-testmodels; scripts/setup.sh installs it)");
    Scene head = loadAssimp(path);
    // One matte white, whatever the file's materials say, as the blog renders it.
    head.materials = {Material{"suzanne", Vec3{0.8f}}};
    head.textures.clear();
    for (Mesh& m : head.meshes) m.material = 0;

    Scene scene = makeCornellBox();
    scene.name = "suzanne";
    std::erase_if(scene.meshes, [](const Mesh& m) { return m.name == "short block" || m.name == "tall block"; });
    const Aabb box = head.bounds();
    const float scale = kHeadWidth / std::max(box.extent().x, 1e-6f);
    const Affine place = Affine::translation(kHeadCentre) * Affine::eulerDegrees({0, kTurnDegrees, 0}) *
                         Affine::eulerDegrees({kStandDegrees, 0, 0}) *
                         Affine::scaling(Vec3{scale}) * Affine::translation(-box.center());
    appendScene(scene, std::move(head), place);
    return scene;
}

}  // namespace penumbra
