// The walks shipped in scenes/walks/ end their level: each is played through the viewer's own
// controls and navigation at its fixed time step, as `penumbra view --script FILE --fixed-dt
// 0.03125` plays it (no window, no GPU; the GPU run at 64x64 is tests/gpu's). DOOM1.WAD is not in
// Debian: its walk is checked where DOOM1_WAD names a copy (default /tmp/DOOM1.WAD), else skipped.
// PENUMBRA_WRITE_WALKS=DIR plans the walks again (walk_planner.h) and writes them into DIR.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "../wad/freedoom_wad.h"
#include "interact/controls.h"
#include "interact/doom_play.h"
#include "interact/walk_replay.h"
#include "scene/doom/level_looks.h"
#include "scene/doom/level.h"
#include "scene/io/wad/sector_light.h"
#include "scene/io/wad/wad_loader.h"
#include "walk_planner.h"

namespace penumbra::test {
namespace {

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::filesystem::path walksDir() { return std::filesystem::path(PENUMBRA_SOURCE_DIR) / "scenes" / "walks"; }

std::string doom1Path() {
    const char* env = std::getenv("DOOM1_WAD");
    return env && *env ? env : "/tmp/DOOM1.WAD";
}

void checkWalk(const Scene& scene, const std::string& file) {
    const std::string script = readText(walksDir() / file);
    ASSERT_FALSE(script.empty()) << file;
    const std::optional<std::string> done = playWalk(scene, script, 600);
    ASSERT_TRUE(done.has_value()) << file << " did not end the level";
    EXPECT_EQ(done->rfind("E1M1 complete in ", 0), 0u) << *done;
    std::printf("%s: %s\n", file.c_str(), done->c_str());
}

void writeWalk(const Scene& scene, const std::string& title, const std::string& file) {
    const char* dir = std::getenv("PENUMBRA_WRITE_WALKS");
    if (!dir) return;
    std::string why;
    const std::optional<PlannedWalk> walk = planWalk(scene, title, &why);
    ASSERT_TRUE(walk.has_value()) << why;
    std::ofstream(std::filesystem::path(dir) / file) << walk->script;
    std::printf("wrote %s: the level ends at %.2f s\n", file.c_str(), walk->seconds);
}

TEST(DoomWalks, FreedoomE1M1WalkEndsTheLevel) {
    REQUIRE_WAD(bytes, "freedoom1.wad");
    const Scene scene = loadWadFromMemory(bytes, "E1M1", "freedoom1.wad");
    writeWalk(scene, "Freedoom Phase 1 E1M1, from the player start to the exit switch", "freedoom1-e1m1-exit.txt");
    checkWalk(scene, "freedoom1-e1m1-exit.txt");
}

TEST(DoomWalks, Doom1E1M1WalkEndsTheLevel) {
    if (!std::filesystem::exists(doom1Path())) GTEST_SKIP() << doom1Path() << " is absent (DOOM1.WAD is not in Debian)";
    const Scene scene = loadWad(doom1Path(), "E1M1");
    writeWalk(scene, "DOOM1.WAD (shareware) E1M1, from the player start to the exit switch", "doom1-e1m1-exit.txt");
    checkWalk(scene, "doom1-e1m1-exit.txt");
}

// The Freedoom walk replayed as `render --walk` replays it: when the level ends, the exit
// switch's wall shows its other texture and the key picked up on the way is hidden, in the
// scene's materials the renderer is sent.
TEST(DoomWalks, FreedoomWalkTurnsTheExitSwitchAndHidesTheKeyTaken) {
    REQUIRE_WAD(bytes, "freedoom1.wad");
    Scene scene = loadWadFromMemory(bytes, "E1M1", "freedoom1.wad");
    const std::vector<Material> loaded = scene.materials;
    viewer::WalkReplay replay(scene, viewer::parseInputScript(readText(walksDir() / "freedoom1-e1m1-exit.txt"), "w"),
                              kWalkStep);
    std::set<std::uint32_t> sent;
    bool ended = false;
    for (std::uint64_t f = 0; f < replay.frameCount() && !ended; ++f) {
        const viewer::WorldChange change = replay.nextFrame(scene);
        sent.insert(change.materialsChanged.begin(), change.materialsChanged.end());
        ended = change.levelCompleted.has_value();
    }
    ASSERT_TRUE(ended);
    const doom::Level& level = replay.navigation().doom()->level();
    auto name = [&](const std::vector<Material>& list, std::uint32_t m) {
        return scene.textures.at(std::size_t(list.at(m).albedoTexture.texture)).name;
    };
    std::size_t exits = 0;
    for (const doom::SwitchMaterial& s : level.switchMaterials()) {
        if (level.lines()[s.line].special != 0 || !level.switchFlipped(s.line)) continue;  // used one-shots
        EXPECT_EQ(name(scene.materials, s.material), doom::otherSwitchTexture(name(loaded, s.material)));
        EXPECT_TRUE(sent.count(s.material));
        exits += scene.doomLevel->lines()[s.line].special == 11;  // as loaded: S1 exit
    }
    EXPECT_EQ(exits, 1u) << "the exit switch turned";
    std::size_t hidden = 0;
    for (const doom::KeyMaterial& k : level.keyMaterials()) {
        EXPECT_EQ(scene.materials[k.material].alphaCutoff > 1.0f, level.thingTaken(k.thing));
        hidden += level.thingTaken(k.thing) && sent.count(k.material);
    }
    EXPECT_GE(hidden, 1u) << "the blue key, taken on the way";
}

// Space is Doom's use key while walking and still moves up in free flight; Enter uses too.
TEST(DoomControls, SpaceAndEnterUse) {
    viewer::InputState in;
    viewer::applyKey(in, GLFW_KEY_SPACE, true);
    EXPECT_TRUE(in.use);
    EXPECT_EQ(viewer::cameraInputFrom(in).up, 1.0f);
    viewer::endInputFrame(in);
    EXPECT_FALSE(in.use);
    EXPECT_EQ(viewer::cameraInputFrom(in).up, 1.0f);  // held: still up, used once
    viewer::applyKey(in, GLFW_KEY_SPACE, false);
    viewer::applyKey(in, GLFW_KEY_ENTER, true);
    EXPECT_TRUE(in.use);
    EXPECT_EQ(viewer::cameraInputFrom(in).up, 0.0f);
}

// Freedoom's E1M1 has flashing and strobing sectors: as the level plays, their fill light's
// materials (their own, one sector each) follow the sector's light level.
TEST(DoomLightMaterials, SectorLightSpecialsDriveTheirFillLight) {
    REQUIRE_WAD(bytes, "freedoom1.wad");
    Scene scene = loadWadFromMemory(bytes, "E1M1", "freedoom1.wad");
    ASSERT_FALSE(scene.doomLevel->lightMaterials().empty());
    viewer::DoomPlay play(*scene.doomLevel);
    viewer::CameraController controller(scene.camera, 1.0f, scene.walkMap);
    std::size_t changes = 0;
    for (int frame = 0; frame < 70; ++frame) {
        play.update(controller, std::nullopt, float(kWalkStep));
        const std::vector<std::uint32_t> changed = play.applyLights(scene);
        changes += changed.size();
        for (const doom::LightMaterial& l : play.level().lightMaterials()) {
            const float want = wad::sectorRadiance(play.level().lightLevel(l.sector)) * l.scale;
            EXPECT_EQ(scene.materials[l.material].emission.x, want) << scene.materials[l.material].name;
        }
    }
    EXPECT_GT(changes, 0u);
}

}  // namespace
}  // namespace penumbra::test
