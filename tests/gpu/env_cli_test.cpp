// The environment flags as a user meets them: --env with a map (and its rotation and intensity
// reaching the image), --env sky, and one-line errors with the documented exit codes.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "gpu_fixture.h"
#include "image/write.h"
#include "scene/environment.h"
#include "run_penumbra.h"

namespace penumbra::test {
namespace {

namespace fs = std::filesystem;

class EnvCliTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        if (!ctx) return;
        dir = fs::temp_directory_path() / ("penumbra-envcli-" + std::to_string(::getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
        // A camera looking along -z at nothing: every pixel sees the environment directly.
        std::ofstream(dir / "void.json") << R"({
            "materials": [{"name": "m"}],
            "meshes": [{"material": "m", "positions": [0,-100,0, 1,-100,0, 0,-100,1], "indices": [0,1,2]}],
            "camera": {"position": [0,0,0], "look_at": [0,0,-1], "fov": 1}})";
    }
    void TearDown() override {
        fs::remove_all(dir);
        GpuTest::TearDown();
    }

    RunResult run(const std::string& args) { return runPenumbra(dir, args); }

    fs::path dir;
};

TEST_F(EnvCliTest, MapRotationAndIntensityReachTheImage) {
    // Three columns of distinct colours: which one the camera sees depends on the rotation
    // (-z is u = 0.5, the middle column's centre; turned 90 degrees, u = 0.25 or 0.75).
    ImageRgb map(3, 2);
    const Vec3 colours[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) map.pixels[std::size_t(y) * 3 + x] = colours[x];
    writeImage(dir / "cols.exr", map, {});
    for (float rotation : {0.0f, 90.0f, -90.0f}) {
        RunResult r = run("render void.json --env cols.exr --env-intensity 3 --env-rotation " + std::to_string(rotation) +
                       " --spp 1 --width 4 --height 4 -o out.exr");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        ImageRgb img = readExr(dir / "out.exr");
        Environment env;
        env.map = EnvironmentMap{"cols", 3, 2, map.pixels};
        env.intensity = 3;
        env.rotationDegrees = rotation;
        const Vec3 expected = environmentRadiance(env, Vec3{0}, Vec3{0, 0, -1});
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(img.at(1, 1)[c], expected[c], 1e-4f) << "rotation " << rotation;
    }
}

TEST_F(EnvCliTest, SkyRendersAndBadEnvironmentsAreOneLineErrors) {
    RunResult ok = run("render void.json --env sky --spp 1 --width 4 --height 4 -o sky.exr");
    ASSERT_EQ(ok.exitCode, 0) << ok.err;
    ImageRgb img = readExr(dir / "sky.exr");
    EXPECT_FALSE(img.hasNonFinite());
    EXPECT_GT(luminance(img.mean()), 0.0f);

    RunResult missing = run("render void.json --env nowhere.hdr -o x.png");
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_EQ(missing.err.rfind("penumbra: error: ", 0), 0u) << missing.err;
    EXPECT_NE(missing.err.find("nowhere.hdr"), std::string::npos) << missing.err;
    EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
    RunResult negative = run("render void.json --env sky --env-intensity -1 -o x.png");
    EXPECT_EQ(negative.exitCode, 2) << negative.err;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

}  // namespace
}  // namespace penumbra::test
