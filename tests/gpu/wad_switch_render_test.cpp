// A Doom switch turned and a key picked up in a final render (render --walk's renderer,
// render/renderer.h): the materials updated in place (Renderer::setMaterial) give the image a
// renderer made afresh from the changed scene gives, bit for bit (glow off, which would weigh the
// light tree by the texture drawn at load), and the switch's pixels differ from before (SW2's
// picture is not SW1's). Freedoom E1M1, lavapipe.
#include <cmath>
#include <filesystem>

#include "../unit/io/io_test_util.h"
#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/doom/level.h"
#include "scene/presets/dungeon_textures.h"
#include "scene/doom/level_looks.h"
#include "scene/io/wad/units.h"
#include "scene/io/wad/wad_loader.h"

namespace penumbra::test {
namespace {

using WadSwitchRenderTest = GpuTest;

const char* const kFreedoom = freedoomWadPath();  // Debian package freedoom

ImageRgb renderOnce(Renderer& r) {
    r.render();
    return r.image();
}

TEST_F(WadSwitchRenderTest, InPlaceUpdateEqualsAFreshRenderer) {
    PENUMBRA_REQUIRE_ASSET(kFreedoom);
    // Glowing textures off: with SW1 and SW2 glowing, the light tree of a fresh renderer weighs
    // the switch by SW2's mean glow, the updated one still by SW1's (InteractiveRenderer::
    // setMaterial keeps the light tables): equally right, not the same random choices.
    WadOptions noGlow;
    noGlow.glow = 0;
    Scene scene = loadWad(kFreedoom, "E1M1", noGlow);
    doom::Level level = *scene.doomLevel;
    // The camera 0.8 m in front of the first switch on a wall that stays.
    const doom::SwitchMaterial* turn = nullptr;
    for (const doom::SwitchMaterial& s : level.switchMaterials())
        for (const Mesh& m : scene.meshes)
            if (!turn && m.material == s.material && m.positions.size() >= 4) {
                const Vec3 centre = 0.25f * (m.positions[0] + m.positions[1] + m.positions[2] + m.positions[3]);
                scene.camera.position = centre + 0.8f * m.normals[0];
                scene.camera.lookAt = centre;
                turn = &s;
            }
    ASSERT_NE(turn, nullptr);
    const RenderSettings settings = testSettings(32, 24, 2, 2);
    Renderer inPlace(*ctx, scene, settings);
    const ImageRgb before = renderOnce(inPlace);

    ASSERT_TRUE(level.trigger(turn->line));
    const auto [kx, ky] = level.keyPositions().at(0);
    level.touchThings({kx, ky, 0});
    const std::vector<std::uint32_t> changed = doom::applyLooks(level, scene.materials);
    ASSERT_EQ(changed.size(), 2u) << "the switch's material and the key's";
    for (std::uint32_t m : changed) inPlace.setMaterial(m, scene.materials[m]);
    inPlace.restart(scene.camera);
    const ImageRgb after = renderOnce(inPlace);

    Renderer fresh(*ctx, scene, settings);
    const ImageRgb expected = renderOnce(fresh);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < after.pixels.size(); ++i) {
        EXPECT_EQ(after.pixels[i], expected.pixels[i]) << "pixel " << i;
        differ += length(after.pixels[i] - before.pixels[i]) > 1e-3f;
    }
    EXPECT_GT(differ, 4u) << "the switch turned in the image";
}

}  // namespace
}  // namespace penumbra::test
