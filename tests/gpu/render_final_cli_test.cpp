// `penumbra render`'s final-frame options as a user meets them (docs/RENDERING.md): time
// budgets, Ctrl-C and --resume, AOV layers, image sequences, JSON progress, one-line errors.
#include <csignal>
#include <fstream>
#include <regex>
#include <set>

#include <nlohmann/json.hpp>
#include <stb/stb_image.h>

#include "cli_fixture.h"
#include "image/exr_layers.h"
#include "render/settings.h"

namespace penumbra::test {
namespace {

constexpr const char* kSmall = "render cornell --width 8 --height 8 --seed 5 ";

std::vector<nlohmann::json> jsonLines(const std::string& out) {
    std::vector<nlohmann::json> lines;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
    return lines;
}

TEST_F(CliTest, TimeLimitStopsTheRenderAndReportsTheSamplesReached) {
    const RunResult r = run(std::string(kSmall) + "--spp 1000000 --time-limit 1s --progress json -o a.exr");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("time limit reached"), std::string::npos) << r.err;
    const std::vector<nlohmann::json> lines = jsonLines(r.out);
    ASSERT_FALSE(lines.empty());
    const nlohmann::json& last = lines.back();
    EXPECT_TRUE(last["final"].get<bool>());
    EXPECT_EQ(last["unit"], "spp");
    EXPECT_EQ(last["total"], 1000000);
    const int reached = last["done"];
    EXPECT_GT(reached, 0);
    EXPECT_LT(reached, 1000000);
    EXPECT_NE(r.err.find(", " + std::to_string(reached) + " spp"), std::string::npos) << r.err;
    // Wall clock of the render loop: the limit plus at most the pass in flight (the first pass,
    // which compiles the shaders on lavapipe, always runs).
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.err, m, std::regex(" in ([0-9.]+) s")));
    EXPECT_LT(std::stod(m[1]), 1.0 + 15.0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "a.exr"));
    EXPECT_FALSE(fs::exists(dir / "a.exr.state"));
}

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Starts a render, sends `signal` once it has reported progress, and waits for it.
RunResult interruptedRun(const fs::path& dir, const std::string& args, int signal) {
    const char* device = std::getenv("PENUMBRA_TEST_DEVICE");
    const std::string cmd =
        "cd '" + dir.string() + "' || exit 1; env PENUMBRA_DEVICE=" + (device ? device : "llvmpipe") +
        " PENUMBRA_VALIDATION=1 '" + penumbraBinary() + "' " + args + " --progress json >stdout.txt 2>stderr.txt & " +
        "pid=$!; for i in $(seq 600); do grep -q progress stdout.txt 2>/dev/null && break; sleep 0.1; done; kill -" +
        std::to_string(signal) + " $pid; wait $pid; echo $? > rc.txt";
    std::system(cmd.c_str());
    return RunResult{std::stoi(readText(dir / "rc.txt")), readText(dir / "stderr.txt"), readText(dir / "stdout.txt")};
}

TEST_F(CliTest, CtrlCKeepsTheImageAndResumeFinishesItAsAnUninterruptedRenderWould) {
    const std::string args = std::string(kSmall) + "--spp 1000000 -o a.exr";
    const RunResult r = interruptedRun(dir, args, SIGINT);
    expectOneLineError(r, 128 + SIGINT, "interrupted by SIGINT");
    EXPECT_NE(r.err.find("--resume 'a.exr.state'"), std::string::npos) << r.err;
    ASSERT_TRUE(fs::exists(dir / "a.exr.state"));
    EXPECT_EQ(readExrChannels(dir / "a.exr").width, 8);  // a valid image of what was rendered
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.err, m, std::regex("at ([0-9]+) of 1000000 spp"))) << r.err;
    const int reached = std::stoi(m[1]);

    // Another scene's or setting's state is refused, and kept.
    expectOneLineError(run("render cornell --width 8 --height 8 --seed 6 --spp 64 -o b.exr --resume a.exr.state"), 1,
                       "another scene or other settings");
    ASSERT_TRUE(fs::exists(dir / "a.exr.state"));

    // Resumed with a budget a little past where it stopped: the same passes and rounds as an
    // uninterrupted render of that many samples, so the same image, bit for bit.
    const std::string spp = std::to_string(reached + 3);
    const RunResult resumed = run(std::string(kSmall) + "--spp " + spp + " -o a.exr --resume a.exr.state");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    EXPECT_NE(resumed.err.find("resuming"), std::string::npos) << resumed.err;
    EXPECT_FALSE(fs::exists(dir / "a.exr.state"));
    ASSERT_EQ(run(std::string(kSmall) + "--spp " + spp + " -o b.exr -q").exitCode, 0);
    const ExrChannels a = readExrChannels(dir / "a.exr"), b = readExrChannels(dir / "b.exr");
    for (const char* c : {"R", "G", "B"}) EXPECT_EQ(a.channels.at(c), b.channels.at(c)) << c;
}

TEST_F(CliTest, SigtermStopsASequenceWhichResumesByItsPattern) {
    const RunResult r = interruptedRun(dir, std::string(kSmall) + "--spp 1000000 --frames 0..1 -o s_%d.png", SIGTERM);
    expectOneLineError(r, 128 + SIGTERM, "interrupted by SIGTERM");
    EXPECT_NE(r.err.find("--resume 's_%d.png'"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(dir / "s_0.png"));
    EXPECT_TRUE(fs::exists(dir / "s_0.png.state"));
    EXPECT_FALSE(fs::exists(dir / "s_1.png"));
}

TEST_F(CliTest, AovLayersAreNamedAsDocumented) {
    const RunResult r = run(std::string(kSmall) + "--spp 4 -o a.png -q --aov albedo,normal,depth,variance,samples");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "a.png"));
    const ExrChannels aov = readExrChannels(dir / "a.exr");  // beside the PNG
    std::set<std::string> names;
    for (const auto& [name, values] : aov.channels) names.insert(name);
    EXPECT_EQ(names, (std::set<std::string>{"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z", "Z",
                                            "variance.Y", "samples.N"}));
    for (std::size_t i = 0; i < 64; ++i) {
        const float nx = aov.channels.at("N.X")[i], ny = aov.channels.at("N.Y")[i], nz = aov.channels.at("N.Z")[i];
        EXPECT_NEAR(nx * nx + ny * ny + nz * nz, 1.0f, 1e-4f) << i;  // the Cornell box fills the view
        EXPECT_GT(aov.channels.at("Z")[i], 0.0f);
        EXPECT_EQ(aov.channels.at("samples.N")[i], 4.0f);
        EXPECT_GE(aov.channels.at("variance.Y")[i], 0.0f);
    }
}

TEST_F(CliTest, FramesFollowACameraPathOneFileEachAndResumeSkipsFinishedOnes) {
    std::ofstream(dir / "path.json") << R"({"assets": [{"preset": "cornell"}],
        "camera_path": {"interpolation": "linear", "keys": [
            {"time": 0, "position": [0.278, 0.273, -0.8], "look_at": [0.278, 0.273, 0]},
            {"time": 2, "position": [0.1, 0.273, -0.6], "look_at": [0.278, 0.273, 0]}]}})";
    const std::string args = "render path.json --width 8 --height 8 --spp 2 --fps 1 --frames 0..2 -o f_%02d.exr";
    const RunResult r = run(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* f : {"f_00.exr", "f_01.exr", "f_02.exr"}) EXPECT_TRUE(fs::exists(dir / f)) << f;
    EXPECT_NE(readExrChannels(dir / "f_00.exr").channels.at("R"), readExrChannels(dir / "f_02.exr").channels.at("R"));
    fs::remove(dir / "f_01.exr");
    const RunResult again = run(args + " --resume f_%02d.exr");
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_NE(again.err.find("2 finished frames were skipped"), std::string::npos) << again.err;
    EXPECT_NE(again.err.find("frame 1 "), std::string::npos) << again.err;
    EXPECT_TRUE(fs::exists(dir / "f_01.exr"));
}

TEST_F(CliTest, JpegTgaBmpAndRadianceHdrOutputs) {
    for (const char* name : {"a.jpg", "a.tga", "a.bmp", "a.hdr"}) {
        ASSERT_EQ(run(std::string(kSmall) + "--spp 2 -q -o " + name).exitCode, 0) << name;
        int w = 0, h = 0, n = 0;
        void* data = std::string(name) == "a.hdr" ? static_cast<void*>(stbi_loadf((dir / name).c_str(), &w, &h, &n, 3))
                                                  : static_cast<void*>(stbi_load((dir / name).c_str(), &w, &h, &n, 3));
        ASSERT_NE(data, nullptr) << name;
        EXPECT_EQ(w, 8);
        EXPECT_EQ(h, 8);
        stbi_image_free(data);
    }
}

// A plain `render` on lavapipe (a CPU device) picks a size and a budget that finish in about 10 s,
// and says so; on a GPU it renders the default size and says nothing.
TEST_F(CliTest, OnACpuThePlainRenderIsSmallAndBudgeted) {
    const bool onCpu = ctx->info().type == VK_PHYSICAL_DEVICE_TYPE_CPU;
    const RunResult r = run("render -o a.png");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const bool said = r.err.find("runs Vulkan on the CPU, so this render is 320x240") != std::string::npos;
    EXPECT_EQ(said, onCpu) << r.err;
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load((dir / "a.png").c_str(), &w, &h, &n, 3);
    ASSERT_NE(data, nullptr);
    stbi_image_free(data);
    const RenderSettings defaults;
    EXPECT_EQ(w, onCpu ? 320 : int(defaults.width));
    EXPECT_EQ(h, onCpu ? 240 : int(defaults.height));
    // A size chosen by the user is kept, and nothing is said.
    const RunResult sized = run("render --width 8 --height 8 --spp 1 -o b.png");
    EXPECT_EQ(sized.err.find("runs Vulkan on the CPU"), std::string::npos) << sized.err;
}

TEST_F(CliTest, CompareReportsTheNumbersAndReadsMultiLayerFiles) {
    ASSERT_EQ(run(std::string(kSmall) + "--spp 2 -q -o a.exr --aov albedo").exitCode, 0);
    ASSERT_EQ(run(std::string(kSmall) + "--spp 8 -q -o b.exr").exitCode, 0);
    const RunResult same = run("compare a.exr a.exr");
    ASSERT_EQ(same.exitCode, 0) << same.err;
    EXPECT_NE(same.out.find("rmse 0\n"), std::string::npos) << same.out;
    EXPECT_NE(same.out.find("psnr inf dB"), std::string::npos) << same.out;
    const RunResult other = run("compare a.exr b.exr");
    ASSERT_EQ(other.exitCode, 0) << other.err;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(other.out, m, std::regex("psnr ([0-9.]+) dB"))) << other.out;
    EXPECT_GT(std::stod(m[1]), 5.0);
    ASSERT_EQ(run("render cornell --width 4 --height 4 --spp 1 -q -o c.exr").exitCode, 0);
    expectOneLineError(run("compare a.exr c.exr"), 1, "different sizes");
    expectOneLineError(run("compare a.exr none.exr"), 1, "none.exr");
}

TEST_F(CliTest, BadFinalFrameOptionsAreOneLineErrors) {
    expectOneLineError(run("render --time-limit 5x"), 2, "--time-limit");
    expectOneLineError(run("render --noise-threshold 2"), 2, "--noise-threshold");
    expectOneLineError(run("render --aov alpha"), 2, "unknown --aov 'alpha'");
    expectOneLineError(run("render --frames 5..2"), 2, "--frames");
    expectOneLineError(run("render --progress loud"), 2, "--progress");
    expectOneLineError(run(std::string(kSmall) + "--spp 2 --resume missing.state"), 1, "missing.state");
}

}  // namespace
}  // namespace penumbra::test
