// The BVH box overlay at depth 1 (the root) outlines the root box's projection: pixels on its projected
// edges turn the overlay colour, pixels well away from every edge (the centre) keep the image.
#include <algorithm>
#include <cmath>

#include "render/frame_uniforms.h"
#include "render/interactive_renderer.h"
#include "gpu_fixture.h"

namespace penumbra::test {
namespace {

using ViewerBoxesTest = GpuTest;

// Pixel distance from q to the projection of the root box's twelve edges, computed independently
// of the shader: corners projected with a pinhole (all corners lie in front of the camera here).
double distanceToBoxEdges(const shader::FrameUniforms& f, const shader::BvhNode& box, double qx, double qy) {
    auto project = [&](Vec3 p, double& x, double& y) {
        const Vec3 d = p - f.cameraPosition;
        const double cx = dot(d, f.cameraRight), cy = dot(d, f.cameraUp), cz = dot(d, f.cameraForward);
        x = (cx / (cz * f.aspect * f.tanHalfFovY) + 1.0) * 0.5 * f.width;
        y = (1.0 - cy / (cz * f.tanHalfFovY)) * 0.5 * f.height;
    };
    double px[8], py[8];
    for (int k = 0; k < 8; ++k)
        project(Vec3{k & 1 ? box.boundsMax.x : box.boundsMin.x, k & 2 ? box.boundsMax.y : box.boundsMin.y,
                     k & 4 ? box.boundsMax.z : box.boundsMin.z},
                px[k], py[k]);
    double best = 1e30;
    for (int a = 0; a < 8; ++a)
        for (int bit : {1, 2, 4}) {
            if (a & bit) continue;
            const int b = a | bit;
            const double ex = px[b] - px[a], ey = py[b] - py[a];
            const double len2 = ex * ex + ey * ey;
            const double t = len2 > 0 ? std::clamp(((qx - px[a]) * ex + (qy - py[a]) * ey) / len2, 0.0, 1.0) : 0.0;
            best = std::min(best, std::hypot(qx - px[a] - t * ex, qy - py[a] - t * ey));
        }
    return best;
}

TEST_F(ViewerBoxesTest, DepthOneOutlinesTheRootBox) {
    Scene scene;
    scene.name = "one sphere";
    scene.materials.push_back(Material{});
    scene.spheres.push_back({Vec3{0.1f, -0.05f, 0}, 0.5f, 0});
    scene.background = Vec3{0.2f};
    scene.camera.position = {1.2f, 0.9f, 3.0f};  // oblique, so the box shows three faces
    scene.camera.lookAt = {0, 0, 0};
    const std::uint32_t w = 40, h = 30;
    InteractiveRenderer viewer(*ctx, scene, false);
    viewer.resize(w, h);
    ViewSettings vs;
    vs.maxBounces = 1;
    vs.debug = DebugView::BvhBoxes;
    vs.boxDepth = 1;
    vs.boxLineWidth = 1.5f;
    viewer.commands().run([&](VkCommandBuffer cmd) { viewer.record(cmd, scene.camera, vs); });
    viewer.finishFrame();
    auto display = gpu::downloadBuffer<std::uint32_t>(*ctx, viewer.commands(), viewer.display(), w * h);

    RenderSettings rs;
    rs.width = w;
    rs.height = h;
    const shader::FrameUniforms f = makeFrameUniforms(scene.camera, Vec3{0}, rs, 0, 0, 0);
    const shader::BvhNode& root = viewer.sceneArrays().nodes.at(0);
    std::uint32_t onEdge = 0, away = 0;
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            const double d = distanceToBoxEdges(f, root, x + 0.5, y + 0.5);
            const bool marked = display[y * w + x] == PN_OVERLAY_COLOR;
            // Within half the line width: marked. Clearly beyond it: the image shows through.
            if (d < 0.6) {
                EXPECT_TRUE(marked) << x << "," << y << " at " << d << " px from an edge";
                ++onEdge;
            } else if (d > 0.9) {
                EXPECT_FALSE(marked) << x << "," << y << " at " << d << " px from an edge";
                ++away;
            }
        }
    EXPECT_GT(onEdge, 40u);  // a real outline was checked, not a handful of pixels
    EXPECT_GT(away, w * h / 2);
    EXPECT_NE(display[(h / 2) * w + w / 2], PN_OVERLAY_COLOR);  // the centre
    EXPECT_EQ(viewer.stats().passMilliseconds[std::size_t(ViewerPass::Boxes)] != 0, true);
}

}  // namespace
}  // namespace penumbra::test
