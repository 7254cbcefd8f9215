// The dungeon's phantom switched off and on in the viewer (issue 40, scene/phantom.h), seen from
// the preset's camera down its corridor: off, no pixel shows it, and the wall and floor it
// uncovers take no history from it (no ghost); on again, it is drawn where it stood, and its
// pixels take no history from the wall that was there.
#include <set>

#include "gpu_fixture.h"
#include "render/interactive_renderer.h"
#include "scene/phantom.h"
#include "scene/presets/presets.h"

namespace penumbra::test {
namespace {

using ViewerPhantomTest = GpuTest;

constexpr std::uint32_t kW = 48, kH = 36;

struct Frame {
    std::vector<shader::GBufferTexel> gbuffer;
    std::vector<shader::HistoryTexel> history;
};

TEST_F(ViewerPhantomTest, SwitchedOffItIsNotDrawnAndLeavesNoGhost) {
    Scene scene = makePreset("dungeon");  // flat-coloured without Freedoom: the same geometry
    PhantomSwitch phantom(scene);
    ASSERT_TRUE(phantom.present());
    std::set<std::uint32_t> phantomSurfaces;  // surface id: material + 1
    for (const Mesh& m : scene.prototypes[scene.instances[0].prototype].meshes) phantomSurfaces.insert(m.material + 1);

    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(kW, kH);
    ViewSettings vs;
    vs.maxBounces = 1;
    auto frame = [&] {
        viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, vs); });
        viewer.finishFrame();
        return Frame{gpu::downloadBuffer<shader::GBufferTexel>(*ctx, viewer.commands(), viewer.gbuffer(), kW * kH),
                     gpu::downloadBuffer<shader::HistoryTexel>(*ctx, viewer.commands(), viewer.history(), kW * kH)};
    };
    auto isPhantom = [&](const shader::GBufferTexel& g) { return phantomSurfaces.count(g.surfaceId) != 0; };
    Frame shown;
    for (int k = 0; k < 3; ++k) shown = frame();
    std::uint32_t phantomPixels = 0;
    for (const shader::GBufferTexel& g : shown.gbuffer) phantomPixels += isPhantom(g);
    ASSERT_GT(phantomPixels, 20u) << "the phantom stands in the corridor ahead";

    ASSERT_TRUE(phantom.set(scene, false, 0.0));
    viewer.setInstanceTransforms(scene);
    const Frame off = frame();
    std::uint32_t uncovered = 0;
    for (std::uint32_t i = 0; i < kW * kH; ++i) {
        EXPECT_FALSE(isPhantom(off.gbuffer[i])) << "pixel " << i << " still shows the phantom";
        if (isPhantom(shown.gbuffer[i]) && off.gbuffer[i].surfaceId != 0) {
            ++uncovered;
            EXPECT_LT(off.history[i].samples, 1.5f) << "pixel " << i << ": a ghost of the phantom";
        }
    }
    EXPECT_GT(uncovered, phantomPixels * 9 / 10);
    Frame still;
    for (int k = 0; k < 3; ++k) still = frame();  // the uncovered wall converges on its own

    ASSERT_TRUE(phantom.set(scene, true, 0.0));
    viewer.setInstanceTransforms(scene);
    const Frame on = frame();
    std::uint32_t back = 0;
    for (std::uint32_t i = 0; i < kW * kH; ++i) {
        EXPECT_EQ(isPhantom(on.gbuffer[i]), isPhantom(shown.gbuffer[i])) << "pixel " << i;  // where it stood
        if (isPhantom(on.gbuffer[i])) {
            ++back;
            EXPECT_LT(on.history[i].samples, 1.5f) << "pixel " << i << ": the wall's history on the phantom";
        } else {
            EXPECT_GT(on.history[i].samples, 1.5f) << "pixel " << i << ": the rest keeps its history";
        }
    }
    EXPECT_EQ(back, phantomPixels);
}

}  // namespace
}  // namespace penumbra::test
