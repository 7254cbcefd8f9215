// Moving objects in the viewer: a bright card crosses a dark wall as an instance moved each frame
// (only the top level changes). With per-object motion vectors the G-buffer's motion follows the
// card and the temporal pass keeps the card's history as it moves; two frames after the card has
// passed, the wall pixels it covered equal the still image (no ghost). Without them (the
// renderer's switch), the card's motion vectors are the still camera's (zero) and its pixels lose
// their history every frame: the comparison that shows what the object motion adds.
#include <cmath>

#include "render/interactive_renderer.h"
#include "render/picking.h"
#include "gpu_fixture.h"
#include "shared/constants.h"

namespace penumbra::test {
namespace {

using ViewerMotionTest = GpuTest;

constexpr std::uint32_t kW = 32, kH = 24;
constexpr float kFovY = 40.0f;
constexpr float kCardDepth = 2.8f;  // metres in front of the camera (the wall is at 3)
constexpr float kStep = 0.6f;       // metres the card moves per frame: more than its 0.5 m width

// A dark wall (world mesh, material 0) at z = -3, a bright 0.5 m card (instance 0, material 1)
// 0.2 m in front of it, a directional light along the view, seen from the origin. Direct light
// only (one bounce) from a delta light: the wall's radiance is the same at every point and in
// every frame, so "within noise" is a tight tolerance.
Scene wallAndCard() {
    Scene scene;
    scene.name = "wall and card";
    Material wall{"wall", Vec3{0.3f}};
    Material card{"card", Vec3{1.0f}};
    scene.materials = {wall, card};
    Mesh quad{"wall"};
    quad.positions = {{-6, -4, -3}, {6, -4, -3}, {6, 4, -3}, {-6, 4, -3}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    scene.meshes.push_back(quad);
    Mesh face{"card"};
    face.positions = {{-0.25f, -0.25f, 0}, {0.25f, -0.25f, 0}, {0.25f, 0.25f, 0}, {-0.25f, 0.25f, 0}};
    face.indices = {0, 1, 2, 0, 2, 3};
    face.material = 1;
    scene.prototypes.push_back({"card", {face}});
    scene.instances.push_back({0, Affine::translation({100, 0, -kCardDepth})});  // out of view
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0, 0, -1};
    sun.intensity = 3.0f;
    scene.lights.push_back(sun);
    scene.camera.position = {0, 0, 0};
    scene.camera.lookAt = {0, 0, -1};
    scene.camera.fovYDegrees = kFovY;
    return scene;
}

struct Frame {
    std::vector<shader::GBufferTexel> gbuffer;
    std::vector<shader::HistoryTexel> history;
};

struct MotionRun {
    std::vector<shader::HistoryTexel> still;  // the wall alone, converged
    std::vector<Frame> crossing;              // one per card position
    std::vector<shader::HistoryTexel> after;  // two frames after the card left
};

MotionRun runCrossing(gpu::Context& ctx, bool objectMotion) {
    Scene scene = wallAndCard();
    InteractiveRenderer viewer(ctx, scene, false);
    viewer.setObjectMotionVectors(objectMotion);
    viewer.resize(kW, kH);
    ViewSettings vs;
    vs.maxBounces = 1;
    vs.denoise = false;
    auto frame = [&] {
        viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, vs); });
        viewer.finishFrame();
        return Frame{gpu::downloadBuffer<shader::GBufferTexel>(ctx, viewer.commands(), viewer.gbuffer(), kW * kH),
                     gpu::downloadBuffer<shader::HistoryTexel>(ctx, viewer.commands(), viewer.history(), kW * kH)};
    };
    auto placeCard = [&](float x) {
        scene.instances[0].transform = Affine::translation({x, 0, -kCardDepth});
        viewer.setInstanceTransforms(scene);
    };
    MotionRun run;
    for (int k = 0; k < 4; ++k) run.still = frame().history;
    for (int k = 0; k < 5; ++k) {
        placeCard(-1.2f + kStep * float(k));
        run.crossing.push_back(frame());
    }
    placeCard(100.0f);
    frame();
    run.after = frame().history;
    return run;
}

bool onCard(const shader::GBufferTexel& g) { return g.surfaceId == 2u; }

// Pixels per metre at the card's depth.
float pixelsPerMetre() { return float(kH) / (2.0f * kCardDepth * std::tan(degreesToRadians(kFovY * 0.5f))); }

TEST_F(ViewerMotionTest, MovingCardLeavesNoGhostAndKeepsItsHistory) {
    const MotionRun run = runCrossing(*ctx, true);
    std::vector<bool> covered(kW * kH, false);
    std::uint32_t cardPixels = 0, followed = 0;
    for (std::size_t k = 0; k < run.crossing.size(); ++k) {
        const Frame& f = run.crossing[k];
        for (std::uint32_t i = 0; i < kW * kH; ++i) {
            if (!onCard(f.gbuffer[i])) continue;
            covered[i] = true;
            if (k == 0) continue;  // it jumped in from out of view
            ++cardPixels;
            // The card moved kStep to the right: its points were that far to the left.
            EXPECT_NEAR(f.gbuffer[i].motion.x, -kStep * pixelsPerMetre(), 0.05f) << "frame " << k << " pixel " << i;
            EXPECT_NEAR(f.gbuffer[i].motion.y, 0.0f, 0.05f);
            EXPECT_NEAR(f.gbuffer[i].prevDepth, kCardDepth, 1e-3f);
            followed += f.history[i].samples > 1.5f;
        }
    }
    ASSERT_GT(cardPixels, 40u);
    // Reprojection follows the card: its pixels keep its history (edge pixels may lose theirs).
    EXPECT_GT(followed, cardPixels * 2 / 3) << followed << " of " << cardPixels;

    std::uint32_t checked = 0;
    for (std::uint32_t i = 0; i < kW * kH; ++i) {
        if (!covered[i]) continue;
        ++checked;
        for (int c = 0; c < 3; ++c) {
            const float want = run.still[i].color[c];
            ASSERT_GT(want, 0.0f);
            EXPECT_NEAR(run.after[i].color[c], want, 1e-3f * want) << "pixel " << i << ": a ghost of the card";
        }
    }
    EXPECT_GT(checked, 100u);
}

// The same crossing with object motion switched off: the card's motion vectors are zero, so each
// frame its pixels look for history where the wall was and find none. (The covered wall pixels
// still come back clean: the previous G-buffer shows the card there, another surface, so their
// history is dropped with or without object motion.)
TEST_F(ViewerMotionTest, WithoutObjectMotionTheCardLosesItsHistory) {
    const MotionRun run = runCrossing(*ctx, false);
    std::uint32_t cardPixels = 0, followed = 0;
    for (std::size_t k = 1; k < run.crossing.size(); ++k) {
        const Frame& f = run.crossing[k];
        for (std::uint32_t i = 0; i < kW * kH; ++i) {
            if (!onCard(f.gbuffer[i])) continue;
            ++cardPixels;
            EXPECT_NEAR(f.gbuffer[i].motion.x, 0.0f, 0.05f);
            followed += f.history[i].samples > 1.5f;
        }
    }
    ASSERT_GT(cardPixels, 40u);
    EXPECT_LT(followed, cardPixels / 10) << followed << " of " << cardPixels;
}

}  // namespace
}  // namespace penumbra::test
