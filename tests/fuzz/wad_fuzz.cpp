// libFuzzer target for the WAD loader: any input must load or throw penumbra::Error; a level
// that loads must also take a few walking steps from its player start.
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>

#include "core/error.h"
#include "scene/io/wad/units.h"
#include "scene/io/wad/wad_loader.h"
#include "scene/walk/walk_physics.h"

namespace {

void walkAround(const penumbra::Scene& scene) {
    using namespace penumbra;
    if (!scene.walkMap) return;
    const Vec3 eye = wad::sceneToMap(scene.camera.position);
    std::optional<walk::WalkState> s = walk::placePlayer(*scene.walkMap, eye.x, eye.y, eye.z - walk::kEyeHeight);
    for (int i = 0; s && i < 8; ++i)
        s = walk::stepWalk(*scene.walkMap, *s, walk::kRunSpeed * std::cos(i), walk::kRunSpeed * std::sin(i), 0.1);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view bytes(reinterpret_cast<const char*>(data), size);
    try {
        penumbra::wadMapNames(bytes);
        penumbra::Scene scene = penumbra::loadWadFromMemory(bytes, "", "fuzz.wad");
        walkAround(scene);
    } catch (const penumbra::Error&) {
    }
    return 0;
}
