// A Doom switch that turns and a key that vanishes, on the GPU (issue 40; scene/doom/
// level_looks.h): Freedoom E1M1 seen in the viewer's renderer. Used, the switch's wall keeps its
// surface but shows its other texture (SW1 -> SW2) in the G-buffer's albedo, sent up in place
// (InteractiveRenderer::setMaterial, no scene reload), and a repeatable one shows the first again
// after 35 tics; picked up, a key's sprite is drawn nowhere.
#include <cmath>
#include <filesystem>

#include "../unit/io/io_test_util.h"
#include "gpu_fixture.h"
#include "render/interactive_renderer.h"
#include "scene/doom/level.h"
#include "scene/presets/dungeon_textures.h"
#include "scene/doom/level_looks.h"
#include "scene/doom/line_specials.h"
#include "scene/io/wad/units.h"
#include "scene/io/wad/wad_loader.h"
#include "shared/constants.h"

namespace penumbra::test {
namespace {

using ViewerSwitchKeyTest = GpuTest;

constexpr std::uint32_t kW = 32, kH = 24;
const char* const kFreedoom = freedoomWadPath();  // Debian package freedoom

class Viewer {
public:
    Viewer(const gpu::Context& ctx, Scene& scene) : ctx_(ctx), scene_(scene), renderer_(ctx, scene, false) {
        renderer_.resize(kW, kH);
        vs_.maxBounces = 1;
        vs_.denoise = false;
    }
    std::vector<shader::GBufferTexel> frame() {
        renderer_.commands().run([&](VkCommandBuffer cmd) { renderer_.record(cmd, scene_.camera, vs_); });
        renderer_.finishFrame();
        return gpu::downloadBuffer<shader::GBufferTexel>(ctx_, renderer_.commands(), renderer_.gbuffer(), kW * kH);
    }
    // The level's looks into the scene's materials, and those changed up to the GPU.
    std::size_t apply(const doom::Level& level) {
        const std::vector<std::uint32_t> changed = doom::applyLooks(level, scene_.materials);
        for (std::uint32_t m : changed) renderer_.setMaterial(m, scene_.materials[m]);
        return changed.size();
    }

private:
    const gpu::Context& ctx_;
    Scene& scene_;
    InteractiveRenderer renderer_;
    ViewSettings vs_;
};

Scene freedoomE1M1() { return loadWad(kFreedoom, "E1M1"); }

// The first world mesh drawn with `material`: its first quad's centre and facing.
bool meshFacing(const Scene& scene, std::uint32_t material, Vec3& centre, Vec3& facing) {
    for (const Mesh& m : scene.meshes) {
        if (m.material != material || m.positions.size() < 4) continue;
        centre = 0.25f * (m.positions[0] + m.positions[1] + m.positions[2] + m.positions[3]);
        facing = m.normals[0];
        return true;
    }
    return false;
}

float albedoDistance(const shader::GBufferTexel& a, const shader::GBufferTexel& b) {
    return std::abs(a.albedo.x - b.albedo.x) + std::abs(a.albedo.y - b.albedo.y) + std::abs(a.albedo.z - b.albedo.z);
}

TEST_F(ViewerSwitchKeyTest, UsedSwitchShowsItsOtherTextureAndTurnsBack) {
    PENUMBRA_REQUIRE_ASSET(kFreedoom);
    Scene scene = freedoomE1M1();
    doom::Level level = *scene.doomLevel;
    const doom::SwitchMaterial* turn = nullptr;
    Vec3 centre, facing;
    // A repeatable one if the map has one on a wall that stays (then it turns back too).
    for (const bool wantRepeat : {true, false})
        for (const doom::SwitchMaterial& s : level.switchMaterials())
            if (!turn && doom::lineSpecial(level.lines()[s.line].special).value().repeat == wantRepeat &&
                meshFacing(scene, s.material, centre, facing))
                turn = &s;
    ASSERT_NE(turn, nullptr) << "a switch on a wall that stays";
    scene.camera.position = centre + 0.8f * facing;  // 26 map units in front of the switch
    scene.camera.lookAt = centre;
    Viewer viewer(*ctx, scene);
    const std::uint32_t surface = turn->material + 1;
    std::vector<shader::GBufferTexel> before = viewer.frame();
    std::uint32_t switchPixels = 0;
    for (const shader::GBufferTexel& g : before) switchPixels += g.surfaceId == surface;
    ASSERT_GT(switchPixels, kW * kH / 4) << "the switch fills much of the view";

    const bool repeatable = doom::lineSpecial(level.lines()[turn->line].special).value().repeat;
    RecordProperty("switch_line", int(turn->line));
    RecordProperty("repeatable", repeatable ? 1 : 0);
    ASSERT_TRUE(level.trigger(turn->line));
    ASSERT_TRUE(level.switchFlipped(turn->line));
    EXPECT_EQ(viewer.apply(level), 1u);
    const std::vector<shader::GBufferTexel> turned = viewer.frame();
    std::uint32_t changed = 0;
    for (std::uint32_t i = 0; i < kW * kH; ++i) {
        ASSERT_EQ(turned[i].surfaceId, before[i].surfaceId) << "pixel " << i << ": the same surface";
        if (albedoDistance(turned[i], before[i]) > 0.02f) {
            EXPECT_EQ(turned[i].surfaceId, surface) << "pixel " << i << ": only the switch changes";
            ++changed;
        }
    }
    EXPECT_GT(changed, 4u) << "SW2's picture differs from SW1's where the lever is";

    // A repeatable switch turns back on its 35th tic; a one-shot one stays turned.
    for (int t = 0; t + 1 < doom::kButtonTics; ++t) level.tic(std::nullopt);
    EXPECT_EQ(viewer.apply(level), 0u);
    level.tic(std::nullopt);
    EXPECT_EQ(viewer.apply(level), repeatable ? 1u : 0u);
    if (!repeatable) return;
    const std::vector<shader::GBufferTexel> back = viewer.frame();
    for (std::uint32_t i = 0; i < kW * kH; ++i) EXPECT_LT(albedoDistance(back[i], before[i]), 1e-4f) << i;
}

TEST_F(ViewerSwitchKeyTest, PickedUpKeyIsDrawnNowhere) {
    PENUMBRA_REQUIRE_ASSET(kFreedoom);
    Scene scene = freedoomE1M1();
    doom::Level level = *scene.doomLevel;
    ASSERT_FALSE(level.keyMaterials().empty());
    const doom::KeyMaterial key = level.keyMaterials().front();
    const Sprite* sprite = nullptr;
    for (const Sprite& s : scene.sprites)
        if (s.material == key.material) sprite = &s;
    ASSERT_NE(sprite, nullptr);
    const Vec3 middle = sprite->position + Vec3(0.0f, 0.5f * (sprite->bottom + sprite->top), 0.0f);
    Viewer viewer(*ctx, scene);
    const std::uint32_t surface = key.material + 1;
    auto keyPixels = [&] {
        std::uint32_t n = 0;
        for (const shader::GBufferTexel& g : viewer.frame()) n += g.surfaceId == surface;
        return n;
    };
    // From whichever side a wall does not hide it, 40 map units away.
    std::uint32_t seen = 0;
    for (int side = 0; side < 4 && seen <= 8; ++side) {
        const float a = float(side) * 0.5f * kPiF;
        scene.camera.position = middle + 1.25f * Vec3(std::cos(a), 0.1f, std::sin(a));
        scene.camera.lookAt = middle;
        seen = keyPixels();
    }
    ASSERT_GT(seen, 8u) << "the key lies in view";

    const Vec3 at = wad::sceneToMap(sprite->position);
    level.touchThings({at.x, at.y, 0});
    ASSERT_TRUE(level.thingTaken(key.thing));
    EXPECT_EQ(viewer.apply(level), 1u);
    EXPECT_EQ(keyPixels(), 0u) << "the key picked up is still drawn";
}

}  // namespace
}  // namespace penumbra::test
