// The unified light sampler (lib/light_sampler.glsl through shaders/test/light_pick.comp) over a
// scene of many emitters of every kind: probabilities sum to one, every pick reports the
// probability MIS later recomputes for it, and picks follow those probabilities (chi-square).
// And a render with a thousand small emitters has the same mean as with uniform picking.
#include <random>

#include "chi_square.h"
#include "gpu_fixture.h"
#include "render/kernel_features.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/mesh_builder.h"
#include "scene_kernel.h"

namespace penumbra::test {
namespace {

// Emissive quads of many sizes, brightnesses and orientations above a floor, emissive spheres,
// a point light, a spot light, a sun disk and a constant sky.
Scene manyLightsScene(int quads, float maxSize, std::uint32_t seed, bool someFaceUp = true) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0, 1);
    Scene s;
    s.name = "many lights";
    Mesh floor;
    floor.material = addMaterial(s, "floor", Vec3{0.5f});
    addQuad(floor, {-6, 0, -6}, {-6, 0, 6}, {6, 0, 6}, {6, 0, -6});
    s.meshes.push_back(floor);
    for (int i = 0; i < quads; ++i) {
        const Vec3 c{12 * u(rng) - 6, 0.3f + 4 * u(rng), 12 * u(rng) - 6};
        const float half = 0.5f * maxSize * (0.05f + 0.95f * u(rng));
        Vec3 n = normalize(Vec3{u(rng) - 0.5f, -1.0f - u(rng), u(rng) - 0.5f});  // mostly facing down
        if (someFaceUp && i % 7 == 0) n = -n;  // a few face up, away from the floor
        Vec3 t = normalize(cross(n, Vec3{0.3f, 0.1f, 1.0f})), b = cross(n, t);
        Mesh m;
        m.material = addMaterial(s, "lamp" + std::to_string(i), Vec3{0}, Vec3{1 + 30 * u(rng), 1 + 10 * u(rng), 2});
        addQuad(m, c - t * half - b * half, c + t * half - b * half, c + t * half + b * half, c - t * half + b * half);
        s.meshes.push_back(m);
    }
    for (int i = 0; i < 3; ++i)
        s.spheres.push_back({{-3.0f + 3 * i, 2.5f, 1.5f}, 0.05f + 0.1f * i, addMaterial(s, "ball", Vec3{0}, Vec3{5.0f})});
    Light point;
    point.position = {2, 3, 1};
    point.intensity = 5;
    Light spot = point;
    spot.type = LightType::Spot;
    spot.position = {0, 4, 0};
    spot.intensity = 50;
    spot.outerConeRadians = 0.4f;
    spot.innerConeRadians = 0.3f;
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = normalize(Vec3{0.2f, -1, 0.1f});
    sun.intensity = 2;
    sun.angularRadius = 0.05f;
    s.lights = {point, spot, sun};
    s.background = {0.2f, 0.3f, 0.5f};
    s.camera.position = {0, 1.5f, 7};
    s.camera.lookAt = {0, 1, 0};
    return s;
}

// Shading points (origin) with their normals (direction), in the open and among the lights.
std::vector<shader::RayDesc> queryPoints() {
    return {{{0, 0, 0}, 0, {0, 1, 0}, 0},
            {{3, 1, -2}, 0, normalize(Vec3{0.3f, 0.9f, 0.1f}), 0},
            {{-4, 2, 3}, 0, {1, 0, 0}, 0},
            {{0.5f, 2, 0.2f}, 0, {0, -1, 0}, 0}};
}

// Picks at the query points, from the light grid's tables (render/light_grid.h) or (withGrid
// false) by the walk's own importance levels. With oneTopLight the sky is black, so the sun is
// the only top-level light, and the kernel is specialised for the scene as the renderers do it
// (PN_OPTION_ONE_TOP_LIGHT among its promises).
void expectPicksFollowTheProbabilitiesMisUses(const gpu::Context& ctx, bool withGrid, bool oneTopLight = false) {
    SCOPED_TRACE(std::string(withGrid ? "light grid" : "tree walk") + (oneTopLight ? ", one top-level light" : ""));
    Scene scene = manyLightsScene(300, 0.6f, 5);
    if (oneTopLight) scene.background = Vec3{0.0f};
    const SceneArrays arrays = buildSceneArrays(scene);
    const KernelSpec spec = oneTopLight ? kernelSpec(arrays) : KernelSpec{};
    ASSERT_TRUE(!oneTopLight || spec.hasOption(PN_OPTION_ONE_TOP_LIGHT));
    ASSERT_FALSE(arrays.lightGrid.empty());  // 600 emitters: deeper than the importance levels
    const auto noGrid = [withGrid](shader::FrameUniforms& f) {
        if (!withGrid) f.lightGridOffset = 0;
    };
    const auto points = queryPoints();
    const std::size_t refs = arrays.lightRefs.size();
    ASSERT_GT(refs, 600u);
    ASSERT_EQ(arrays.topLightCount, oneTopLight ? 1u : 2u);  // the sky and the sun

    const auto pmfs = runSceneKernel<Vec4, shader::RayDesc>(ctx, scene, arrays, "test_light_pick", points,
                                                            points.size() * refs,
                                                            {0, 1, std::uint32_t(points.size() * refs), 0}, {}, noGrid,
                                                            spec);
    const std::uint32_t perPoint = 200000;
    const auto picks = runSceneKernel<Vec4, shader::RayDesc>(ctx, scene, arrays, "test_light_pick", points,
                                                             points.size() * perPoint,
                                                             {perPoint, 0, std::uint32_t(points.size() * perPoint), 0}, {}, noGrid,
                                                             spec);
    for (std::size_t p = 0; p < points.size(); ++p) {
        double sum = 0;
        int reachable = 0;
        for (std::size_t r = 0; r < refs; ++r) {
            sum += pmfs[p * refs + r].x;
            reachable += pmfs[p * refs + r].x > 0;
        }
        // A descent can end where neither child's bounds can light p although their parent's
        // could (pbrt-v4's sampler does the same): that pick finds no light, and the rest of the
        // probability is that of "no light".
        EXPECT_LE(sum, 1.0 + 1e-4) << "point " << p;
        EXPECT_GT(sum, 0.6) << "point " << p;  // emitters facing every way: the hardest case
        EXPECT_GT(reachable, 100) << "point " << p;  // importance prunes, it does not starve

        std::vector<double> observed(refs + 1, 0.0), expected(refs + 1, 0.0);
        for (std::size_t r = 0; r < refs; ++r) expected[r] = double(perPoint) * pmfs[p * refs + r].x;
        expected[refs] = std::max(0.0, double(perPoint) * (1.0 - sum));
        for (std::uint32_t k = 0; k < perPoint; ++k) {
            const Vec4& pick = picks[p * perPoint + k];
            std::uint32_t ref;
            std::memcpy(&ref, &pick.x, sizeof ref);
            if (ref == PN_NO_LIGHT) {
                observed[refs] += 1;
                continue;
            }
            ASSERT_LT(ref, refs) << "point " << p;
            // The probability the pick reports is the one MIS recomputes from the bit trail.
            ASSERT_NEAR(pick.z, pick.y, 1e-5f * pick.y) << "point " << p << " light " << ref;
            ASSERT_NEAR(pick.y, pmfs[p * refs + ref].x, 1e-5f * pick.y) << "point " << p << " light " << ref;
            observed[ref] += 1;
        }
        const ChiSquareResult chi = chiSquareTest(observed, expected);
        EXPECT_FALSE(chi.observedWhereImpossible) << "point " << p;
        EXPECT_GT(chi.pValue, sidakAlpha(1e-3, int(points.size()))) << "point " << p << ": chi2 " << chi.statistic
                                                                   << " with " << chi.degreesOfFreedom << " dof";
    }
}

TEST_F(GpuTest, LightPicksFollowTheProbabilitiesMisUses) {
    expectPicksFollowTheProbabilitiesMisUses(*ctx, true);
    expectPicksFollowTheProbabilitiesMisUses(*ctx, false);
    expectPicksFollowTheProbabilitiesMisUses(*ctx, true, true);
}

// Uniform picks among 3 * 2^22 lights: a pick made as floor(u * count) from a 24-bit float u can
// reach only 2^24 of the indices' fractions, and picks the multiples of 3 twice as often as the
// others; the picks must be uniform over the residues mod 3 (and over the two halves).
TEST_F(GpuTest, UniformPicksStayUniformAmongMillionsOfLights) {
    const Scene scene = manyLightsScene(4, 0.6f, 9);
    const SceneArrays arrays = buildSceneArrays(scene);
    const std::vector<shader::RayDesc> point = {queryPoints()[0]};
    const std::uint32_t count = 3u << 22, picks = 300000;
    RenderSettings settings;
    settings.uniformLightPick = true;
    const auto out = runSceneKernel<Vec4, shader::RayDesc>(
        *ctx, scene, arrays, "test_light_pick", point, picks, {picks, 0, picks, 0}, settings,
        [&](shader::FrameUniforms& f) { f.lightRefCount = count; });
    std::vector<double> residues(3, 0.0), halves(2, 0.0);
    for (const Vec4& pick : out) {
        std::uint32_t ref;
        std::memcpy(&ref, &pick.x, sizeof ref);
        ASSERT_LT(ref, count);
        ASSERT_FLOAT_EQ(pick.y, 1.0f / float(count));
        residues[ref % 3] += 1;
        halves[ref < count / 2] += 1;
    }
    const ChiSquareResult r = chiSquareTest(residues, std::vector<double>(3, picks / 3.0));
    const ChiSquareResult h = chiSquareTest(halves, std::vector<double>(2, picks / 2.0));
    EXPECT_GT(r.pValue, 1e-4) << "picks per residue: " << residues[0] << " " << residues[1] << " " << residues[2];
    EXPECT_GT(h.pValue, 1e-4) << "picks per half: " << halves[0] << " " << halves[1];
}

// A thousand small emitters facing a floor, seen from above (so no pixel sees an emitter, whose
// edges would add noise that no light sampler can touch): choosing by contribution changes only
// the noise, so the image mean agrees with uniform picking within the two estimates' standard
// errors, and the noise is much lower.
TEST_F(GpuTest, ThousandSmallEmittersConvergeToTheUniformPickingMean) {
    Scene scene = manyLightsScene(1000, 0.08f, 9, false);
    scene.lights.clear();
    scene.spheres.clear();
    scene.background = Vec3{0};
    scene.camera.position = {0, 8, 0.01f};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.fovYDegrees = 60;
    RenderSettings rs = testSettings(24, 16, 256, 2);
    Renderer importance(*ctx, scene, rs);
    importance.render();
    rs.uniformLightPick = true;
    Renderer uniform(*ctx, scene, rs);
    uniform.render();
    const MeanEstimate a = imageMean(importance.accumulation(), rs.samplesPerPixel);
    const MeanEstimate b = imageMean(uniform.accumulation(), rs.samplesPerPixel);
    ASSERT_GT(a.mean, 0.0);
    EXPECT_NEAR(a.mean, b.mean, 4.0 * std::sqrt(a.stderr * a.stderr + b.stderr * b.stderr));
    // The point of the exercise: choosing by contribution is far less noisy.
    EXPECT_LT(a.stderr, 0.5 * b.stderr);
}

}  // namespace
}  // namespace penumbra::test
