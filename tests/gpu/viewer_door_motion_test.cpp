// A Doom door that opens in the viewer (issue 40): Freedoom E1M1's first door seen from the room
// in front of it, opened by its line special and moved tic by tic as the viewer moves it (the
// instance carrying the door's ceiling and face, scene/doom/level.h). Its motion vectors follow
// the door up, so the door face keeps its history while it rises; the floor and walls it uncovers
// take no history from it (no ghost of the door): their first frame starts a new running mean.
#include <cmath>
#include <filesystem>
#include <set>

#include "gpu_fixture.h"
#include "render/interactive_renderer.h"
#include "scene/doom/level.h"
#include "scene/io/wad/units.h"
#include "scene/io/wad/wad_loader.h"
#include "shared/constants.h"

namespace penumbra::test {
namespace {

using ViewerDoorMotionTest = GpuTest;

constexpr std::uint32_t kW = 32, kH = 24;
constexpr int kDoorLine = 55;     // DR door, AQDOOR02: (896, 544) -> (768, 544), room 9 on its north
constexpr int kDoorSector = 10;
constexpr double kDistance = 100;  // map units from the camera to the door face
constexpr int kTicsPerFrame = 4;   // 8 units of door per frame

struct Frame {
    std::vector<shader::GBufferTexel> gbuffer;
    std::vector<shader::HistoryTexel> history;
};

TEST_F(ViewerDoorMotionTest, OpeningDoorMovesWithItsMotionVectorsAndLeavesNoGhost) {
    const char* wadPath = "/usr/share/games/doom/freedoom1.wad";
    if (!std::filesystem::exists(wadPath)) {
        if (std::getenv("CI")) FAIL() << wadPath << " is missing (install freedoom)";
        GTEST_SKIP() << wadPath << " is not installed (apt install freedoom)";
    }
    Scene scene = loadWad(wadPath, "E1M1");
    ASSERT_TRUE(scene.doomLevel);
    doom::Level level = *scene.doomLevel;
    const std::int32_t room = walk::sectorAt(level.walkMap(), 832, 544 + kDistance);
    ASSERT_GE(room, 0);
    const double eye = level.walkMap().sectors[std::size_t(room)].floor + 41;
    scene.camera.position = wad::mapToScene(832, 544 + kDistance, eye);
    scene.camera.lookAt = wad::mapToScene(832, 544, eye);
    const doom::PlaneInstance* door = nullptr;
    for (const doom::PlaneInstance& p : level.planeInstances())
        if (p.sector == kDoorSector && p.plane == doom::Plane::Ceiling) door = &p;
    ASSERT_NE(door, nullptr);
    // The door face: the walls its instance carries; and every surface that moves with it.
    std::uint32_t faceSurface = 0;
    std::set<std::uint32_t> doorSurfaces;
    for (const Mesh& m : scene.prototypes[scene.instances[door->instance].prototype].meshes) {
        if (m.name.find("walls") != std::string::npos) faceSurface = m.material + 1;
        doorSurfaces.insert(m.material + 1);
    }
    ASSERT_NE(faceSurface, 0u);

    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(kW, kH);
    ViewSettings vs;
    vs.maxBounces = 1;
    vs.denoise = false;
    auto frame = [&] {
        viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, vs); });
        viewer.finishFrame();
        return Frame{gpu::downloadBuffer<shader::GBufferTexel>(*ctx, viewer.commands(), viewer.gbuffer(), kW * kH),
                     gpu::downloadBuffer<shader::HistoryTexel>(*ctx, viewer.commands(), viewer.history(), kW * kH)};
    };
    Frame last;
    for (int k = 0; k < 3; ++k) last = frame();
    std::uint32_t doorPixels = 0;
    for (const shader::GBufferTexel& g : last.gbuffer) doorPixels += g.surfaceId == faceSurface;
    ASSERT_GT(doorPixels, kW * kH / 4) << "the closed door fills much of the view";

    ASSERT_TRUE(level.trigger(kDoorLine));
    const float pixelsPerMetre =
        float(kH) / (2.0f * float(kDistance / wad::kUnitsPerMetre) * std::tan(degreesToRadians(scene.camera.fovYDegrees * 0.5f)));

    std::uint32_t faceChecked = 0, faceMoved = 0, faceFollowed = 0, uncovered = 0;
    for (int k = 0; k < 12; ++k) {
        const double before = level.height(kDoorSector, doom::Plane::Ceiling);
        for (int t = 0; t < kTicsPerFrame; ++t) level.tic(std::nullopt);
        const double rise = level.height(kDoorSector, doom::Plane::Ceiling) - before;  // 8 units, less at the top
        const float risePixels = float(rise / wad::kUnitsPerMetre) * pixelsPerMetre;
        const float offset = float((level.height(kDoorSector, doom::Plane::Ceiling) - door->base) / wad::kUnitsPerMetre);
        scene.instances[door->instance].transform = Affine::translation({0, offset, 0});
        viewer.setInstanceTransforms(scene);
        const Frame now = frame();
        for (std::uint32_t i = 0; i < kW * kH; ++i) {
            const shader::GBufferTexel& g = now.gbuffer[i];
            if (g.surfaceId == faceSurface && last.gbuffer[i].surfaceId == faceSurface) {
                // The face rose kTicsPerFrame tics of door: that many pixels below, a frame ago.
                // (A static wall of the same texture may share the face's surface id: counted, not failed.)
                ++faceChecked;
                faceMoved += std::abs(std::abs(g.motion.y) - risePixels) < 0.05f && std::abs(g.motion.x) < 0.05f;
                faceFollowed += now.history[i].samples > 1.5f;
            } else if (last.gbuffer[i].surfaceId == faceSurface && !doorSurfaces.count(g.surfaceId)) {
                // Uncovered by the door, a surface that stays: its history starts again (nothing of
                // the door blended in). The door's own underside, seen as it rises, keeps its own.
                ++uncovered;
                EXPECT_LT(now.history[i].samples, 1.5f) << "frame " << k << " pixel " << i << ": a ghost of the door";
            }
        }
        last = now;
    }
    EXPECT_GT(faceChecked, 50u);
    EXPECT_GT(faceMoved, faceChecked * 95 / 100) << faceMoved << " of " << faceChecked << " move with the door";
    EXPECT_GT(faceFollowed, faceChecked * 2 / 3) << faceFollowed << " of " << faceChecked;
    EXPECT_GT(uncovered, 20u);
    EXPECT_GT(level.height(kDoorSector, doom::Plane::Ceiling), level.height(kDoorSector, doom::Plane::Floor) + 56);
}

}  // namespace
}  // namespace penumbra::test
