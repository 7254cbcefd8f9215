// `penumbra view` for real: a window under Xvfb, lavapipe presenting to it with validation on,
// a few frames, a screenshot, exit 0. Skipped where xvfb-run is not installed.
#include <stb/stb_image.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "binary_path.h"

namespace penumbra::test {
namespace {

namespace fs = std::filesystem;

struct RunResult {
    int exitCode;
    std::string err;
};

RunResult runPenumbra(const fs::path& dir, const std::string& args, bool underXvfb) {
    const char* device = std::getenv("PENUMBRA_TEST_DEVICE");
    std::string cmd = "cd '" + dir.string() + "' && env PENUMBRA_VALIDATION=1 PENUMBRA_DEVICE=" +
                      (device ? device : "llvmpipe") + " " +
                      (underXvfb ? "xvfb-run -a -s '-screen 0 640x480x24' " : "") + penumbraBinary() + " " + args +
                      " 2> stderr.txt";
    int status = std::system(cmd.c_str());
    std::ifstream in(dir / "stderr.txt");
    std::stringstream err;
    err << in.rdbuf();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, err.str()};
}

class ViewerSmokeTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("penumbra-view-" + std::to_string(::getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    fs::path dir;
};

TEST_F(ViewerSmokeTest, OpensUnderXvfbRendersFramesAndWritesTheScreenshot) {
    if (std::system("command -v xvfb-run > /dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
    RunResult r = runPenumbra(dir, "view cornell --width 160 --height 120 --frames 4 --denoise --screenshot shot.png", true);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
    int w = 0, h = 0, channels = 0;
    unsigned char* pixels = stbi_load((dir / "shot.png").c_str(), &w, &h, &channels, 3);
    ASSERT_NE(pixels, nullptr) << "no readable screenshot";
    EXPECT_EQ(w, 160);
    EXPECT_EQ(h, 120);
    // The Cornell box fills most of the frame: the image is neither black nor uniform.
    double sum = 0;
    int distinct = 0;
    for (int i = 0; i < w * h * 3; ++i) {
        sum += pixels[i];
        distinct += i > 0 && pixels[i] != pixels[i - 3 > 0 ? i - 3 : 0];
    }
    stbi_image_free(pixels);
    EXPECT_GT(sum / (w * h * 3), 20.0);
    EXPECT_GT(distinct, w * h / 4);
    EXPECT_FALSE(fs::exists(dir / "imgui.ini"));
}

TEST_F(ViewerSmokeTest, ScreenshotWithoutFramesIsAUsageErrorBeforeAnyWindowOpens) {
    RunResult r = runPenumbra(dir, "view cornell --screenshot shot.png", false);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err.rfind("penumbra: error: --screenshot needs --frames", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
}  // namespace penumbra::test
