// The penumbra executable as a user meets it: outputs, exit codes, one-line errors, no partial
// files.
#include <stb/stb_image.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_fixture.h"
#include "image/write.h"
#include "scene/io/load.h"
#include "scene/presets/presets.h"

namespace penumbra::test {
namespace {

namespace fs = std::filesystem;

TEST_F(CliTest, RenderWithoutSceneOrOutputWritesTheCornellBoxToOut) {
    RunResult r = run("render --width 40 --height 30 --spp 4 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
    int w = 0, h = 0, channels = 0;
    unsigned char* pixels = stbi_load((dir / "out" / "cornell.png").c_str(), &w, &h, &channels, 3);
    ASSERT_NE(pixels, nullptr);
    EXPECT_EQ(w, 40);
    EXPECT_EQ(h, 30);
    long sum = 0;
    for (int i = 0; i < w * h * 3; ++i) sum += pixels[i];
    stbi_image_free(pixels);
    EXPECT_GT(sum, 0) << "the image is black";
}

TEST_F(CliTest, ExrOutputHoldsLinearRadiance) {
    RunResult r = run("render cornell -o img.exr --width 16 --height 16 --spp 2 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ImageRgb img = readExr(dir / "img.exr");
    EXPECT_EQ(img.width, 16);
    EXPECT_FALSE(img.hasNonFinite());
    EXPECT_GT(luminance(img.mean()), 0.0f);
    // Only the image: no temporary left beside it.
    EXPECT_EQ(filesIn(dir).size(), 1u);
}

// render draws the dungeon's phantom as the viewer does with it on (by default), and
// --no-phantom leaves it out: pixel by pixel, the two images differ in the middle of the
// preset's view, where the phantom stands in the corridor, far more than at its left edge.
TEST_F(CliTest, RenderShowsThePhantomUnlessNoPhantom) {
    auto image = [&](const std::string& flags) {
        RunResult r = run("render dungeon -o p.exr --width 32 --height 24 --spp 4 --quiet " + flags);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return readExr(dir / "p.exr");
    };
    const ImageRgb shown = image(""), hidden = image("--no-phantom");
    ASSERT_EQ(shown.pixels.size(), hidden.pixels.size());
    // Mean |difference| over mean brightness, in rows 40-80 % and columns x0..x1 tenths.
    auto change = [&](int x0, int x1) {
        double diff = 0, level = 0;
        for (int y = shown.height * 2 / 5; y < shown.height * 4 / 5; ++y)
            for (int x = shown.width * x0 / 10; x < shown.width * x1 / 10; ++x) {
                const std::size_t i = std::size_t(y * shown.width + x);
                diff += std::abs(luminance(shown.pixels[i]) - luminance(hidden.pixels[i]));
                level += 0.5 * (luminance(shown.pixels[i]) + luminance(hidden.pixels[i]));
            }
        return diff / level;
    };
    const double middle = change(4, 6), edge = change(0, 2);
    RecordProperty("middle_change", std::to_string(middle));
    RecordProperty("edge_change", std::to_string(edge));
    EXPECT_GT(middle, 3 * edge) << "middle " << middle << ", edge " << edge;
    EXPECT_GT(middle, 0.3);
}

// A red torch adds red light only; a range shorter than any wall's distance adds nothing.
TEST_F(CliTest, TorchColourAndRangeShapeTheCameraLight) {
    auto meanOf = [&](const std::string& flags) {
        RunResult r = run("render cornell -o t.exr --width 16 --height 16 --spp 64 --quiet " + flags);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return readExr(dir / "t.exr").mean();
    };
    const Vec3 plain = meanOf("");
    const Vec3 red = meanOf("--torch 5 --torch-color 1,0,0");
    const Vec3 faded = meanOf("--torch 5 --torch-color 1,0,0 --torch-range 0.05");
    EXPECT_GT(red.x - plain.x, 0.05f);
    EXPECT_GT(red.x - plain.x, 5 * std::abs(red.y - plain.y));
    EXPECT_LT(std::abs(faded.x - plain.x), 0.2f * (red.x - plain.x));
    expectOneLineError(run("render --torch-color 2,0,0"), 2, "--torch-color");
    expectOneLineError(run("render --torch-range -1"), 2, "--torch-range");
}

// The help names every built-in scene and file format there is, not a list written by hand.
TEST_F(CliTest, RenderHelpNamesEveryBuiltInSceneAndFormat) {
    const RunResult r = run("render --help");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    for (const std::string& name : presetNames()) EXPECT_NE(r.out.find(name), std::string::npos) << name << " in:\n" << r.out;
    EXPECT_NE(r.out.find(sceneFileExtensions()), std::string::npos) << r.out;
    for (const char* ext : {".obj", ".ply", ".gltf", ".glb", ".wad", ".json"})
        EXPECT_NE(r.out.find(ext), std::string::npos) << ext;
}

TEST_F(CliTest, UnknownSceneIsAUsageError) { expectOneLineError(run("render nosuchscene"), 2, "cornell"); }

TEST_F(CliTest, BadFlagsAreUsageErrors) {
    expectOneLineError(run("render --bogus"), 2, "--bogus");
    expectOneLineError(run("render --spp lots"), 2, "--spp");
    expectOneLineError(run("render --camera 1,2"), 2, "--camera");
    expectOneLineError(run("render --look-at 0,0,-800 --camera 0,0,-800"), 2, "look-at");
    expectOneLineError(run("render --accel octree"), 2, "bvh");
    expectOneLineError(run("render --mis sometimes"), 2, "light");
    expectOneLineError(run("render -o picture.gif"), 2, ".png");
    expectOneLineError(run("render --wad-glow -1"), 2, "--wad-glow");
    expectOneLineError(run("render --wad-sector-light nan"), 2, "--wad-sector-light");
    expectOneLineError(run("render --wad-filter smooth"), 2, "--wad-filter");
    expectOneLineError(run("render --time nan"), 2, "--time");
    EXPECT_TRUE(filesIn(dir).empty());
}

TEST_F(CliTest, ZeroOrAbsurdSizesAreRefusedBeforeAnyWork) {
    expectOneLineError(run("render --width 0 -o a.png"), 2, "width");
    expectOneLineError(run("render --height 1000000 -o a.png"), 2, "16384");
    expectOneLineError(run("render --spp 0 -o a.png"), 2, "--spp");
    expectOneLineError(run("render --bounces 100000 -o a.png"), 2, "--bounces");
    EXPECT_TRUE(filesIn(dir).empty());
}

// A mesh with nothing renderable is one line and exit 1, never a black image: a NaN corner
// (refused by the parser) and finite corners whose triangle overflows float arithmetic.
TEST_F(CliTest, MeshWithoutARenderableFaceIsAnError) {
    std::ofstream(dir / "nan.obj") << "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n";
    std::ofstream(dir / "huge.obj") << "v 0 0 0\nv 1 0 0\nv 3e38 3e38 0\nf 1 2 3\n";
    expectOneLineError(run("render nan.obj --width 8 --height 8 --spp 1 -o nan.png"), 1, "not a finite number");
    expectOneLineError(run("render huge.obj --width 8 --height 8 --spp 1 -o huge.png"), 1, "no face can be rendered");
    EXPECT_FALSE(fs::exists(dir / "nan.png"));
    EXPECT_FALSE(fs::exists(dir / "huge.png"));
}

TEST_F(CliTest, UnwritableOutputFailsCleanlyAndKeepsTheOldFile) {
    expectOneLineError(run("render --spp 1 -o missing-dir/a.png"), 1, "missing-dir");
    fs::create_directory(dir / "adir");
    expectOneLineError(run("render --spp 1 -o adir"), 2, "adir");
    {
        std::ofstream(dir / "keep.png") << "old contents";
    }
    expectOneLineError(run("render --width 0 -o keep.png"), 2, "width");
    std::ifstream in(dir / "keep.png");
    std::string kept((std::istreambuf_iterator<char>(in)), {});
    EXPECT_EQ(kept, "old contents");
}

TEST_F(CliTest, NoVulkanDeviceSaysHowToGetOne) {
    RunResult r = run("render --spp 1 -o a.png", "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json");
    expectOneLineError(r, 1, "mesa-vulkan-drivers");
    EXPECT_FALSE(fs::exists(dir / "a.png"));
}

TEST_F(CliTest, LensFlagsRenderAndBadOnesAreUsageErrors) {
    EXPECT_EQ(run("render caffeine --width 16 --height 12 --spp 1 --aperture 0.05 --focus-point 0,0.55,0 -o a.png").exitCode, 0);
    EXPECT_TRUE(fs::exists(dir / "a.png"));
    expectOneLineError(run("render caffeine --spp 1 --aperture -1 -o b.png"), 2, "aperture");
    expectOneLineError(run("render caffeine --spp 1 --focus-distance 0 -o b.png"), 2, "--focus-distance");
    expectOneLineError(run("render caffeine --spp 1 --focus-point 0,0,100 -o b.png"), 2, "in front of the camera");
    expectOneLineError(run("render caffeine --spp 1 --focus-point 0,0,0 --focus-distance 2 -o b.png"), 2, "excludes");
    EXPECT_FALSE(fs::exists(dir / "b.png"));
}

}  // namespace
}  // namespace penumbra::test
