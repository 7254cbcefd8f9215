// `penumbra render --walk FILE -o walk.mp4` as a user runs it (docs/RENDERING.md, "Walks and
// videos"): the video decoded back with FFmpeg's libraries (frame count, size, content, motion),
// the same frames as an image sequence, Ctrl-C leaving no video, one-line errors.
#include <csignal>
#include <fstream>

#include <stb/stb_image.h>

#include "cli_fixture.h"
#include "video_decode.h"

namespace penumbra::test {
namespace {

constexpr const char* kFreedoom = "/usr/share/games/doom/freedoom1.wad";

// Forward, a look to the right, forward again: 9 frames at 8 fps.
constexpr const char* kWalk =
    "# a short walk from the player start\n"
    "0 key W down\n"
    "0.5 mouse 300 0\n"
    "1 key W up\n";

void writeText(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

std::vector<std::uint8_t> readPngRgb(const fs::path& path) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.string().c_str(), &w, &h, &n, 3);
    if (!data) return {};
    std::vector<std::uint8_t> rgb(data, data + std::size_t(w) * h * 3);
    stbi_image_free(data);
    return rgb;
}

// What a walk video must show: its frames, its size, a lit level, and a camera that moves.
void expectWalkVideo(const DecodedVideo& video, std::size_t frames, int width, int height) {
    ASSERT_TRUE(video.error.empty()) << video.error;
    EXPECT_EQ(video.codec, "h264");
    EXPECT_EQ(video.width, width);
    EXPECT_EQ(video.height, height);
    ASSERT_EQ(video.frames.size(), frames);
    for (std::size_t i = 0; i < frames; ++i) EXPECT_GT(meanValue(video.frames[i]), 4.0) << "frame " << i << " is black";
    // Walking forward, then turning: every frame differs from the one before by more than codec
    // noise, but the last, which plays the release of W and so stands where the one before stood
    // (the final-quality test checks it differs from that frame by noise only).
    EXPECT_GT(meanAbsDifference(video.frames.front(), video.frames.back()), 8.0);
    for (std::size_t i = 1; i + 1 < frames; ++i)
        EXPECT_GT(meanAbsDifference(video.frames[i - 1], video.frames[i]), 0.5) << "frames " << i - 1 << ", " << i;
}

class WalkVideoTest : public CliTest {
protected:
    void SetUp() override {
        CliTest::SetUp();
        if (IsSkipped()) return;
        if (!fs::exists(kFreedoom)) GTEST_SKIP() << kFreedoom << " is not installed (Debian package freedoom)";
        writeText(dir / "walk.txt", kWalk);
    }
    std::string walkArgs() const {
        return std::string("render ") + kFreedoom + " --map E1M1 --walk walk.txt --fps 8 --width 64 --height 48 --seed 3 ";
    }
};

TEST_F(WalkVideoTest, AWalkBecomesAnH264VideoOfItsCameraPath) {
    const RunResult r = run(walkArgs() + "--spp 2 -o e1m1.mp4");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("9 frames 64x48 at 8 fps (final quality, 2 spp a frame)"), std::string::npos) << r.err;
    expectWalkVideo(decodeVideo(dir / "e1m1.mp4"), 9, 64, 48);
    {
        // The last frame plays the release of W: the camera stands. E1M1's flickering sectors go
        // on changing their light (the level's tics run), so the frame is not the one before bit
        // for bit, but it differs by noise, far less than a step of the walk moves the picture
        // (measured at 2 spp: 4.7 standing against 20 walking).
        const DecodedVideo v = decodeVideo(dir / "e1m1.mp4");
        ASSERT_EQ(v.frames.size(), 9u);
        EXPECT_LT(meanAbsDifference(v.frames[7], v.frames[8]), 0.5 * meanAbsDifference(v.frames[6], v.frames[7]));
    }
    EXPECT_EQ(filesIn(dir).size(), 2u);  // walk.txt and the video: no temporary file left

    // The same walk as images: the video's frames are these, up to the codec's loss.
    ASSERT_EQ(run(walkArgs() + "--spp 2 --quiet -o f_%02d.png").exitCode, 0);
    const DecodedVideo video = decodeVideo(dir / "e1m1.mp4");
    for (int i = 0; i < 9; ++i) {
        char name[16];
        std::snprintf(name, sizeof name, "f_%02d.png", i);
        const std::vector<std::uint8_t> png = readPngRgb(dir / name);
        ASSERT_FALSE(png.empty()) << name;
        const double own = meanAbsDifference(video.frames[i], png);
        EXPECT_LT(own, 6.0) << name;
        if (i > 0 && i < 8) {
            EXPECT_LT(own, meanAbsDifference(video.frames[i - 1], png)) << name;
        }
    }
}

TEST_F(WalkVideoTest, ViewerQualityRendersTheWalkWithTheViewersRenderer) {
    const RunResult r = run(walkArgs() + "--viewer-quality -o e1m1.mkv");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("(viewer quality, 1 spp a frame)"), std::string::npos) << r.err;
    expectWalkVideo(decodeVideo(dir / "e1m1.mkv"), 9, 64, 48);
}

// Starts a walk, sends SIGINT once it has reported progress, and waits for it.
RunResult interruptedWalk(const fs::path& dir, const std::string& args) {
    const char* device = std::getenv("PENUMBRA_TEST_DEVICE");
    const std::string cmd =
        "cd '" + dir.string() + "' || exit 1; env PENUMBRA_DEVICE=" + (device ? device : "llvmpipe") +
        " PENUMBRA_VALIDATION=1 '" + penumbraBinary() + "' " + args + " --progress json >stdout.txt 2>stderr.txt & " +
        "pid=$!; for i in $(seq 600); do grep -q progress stdout.txt 2>/dev/null && break; sleep 0.1; done; kill -INT " +
        "$pid; wait $pid; echo $? > rc.txt";
    std::system(cmd.c_str());
    RunResult r{std::stoi(readText(dir / "rc.txt")), readText(dir / "stderr.txt"), readText(dir / "stdout.txt")};
    for (const char* f : {"rc.txt", "stderr.txt", "stdout.txt"}) fs::remove(dir / f);
    return r;
}

TEST_F(CliTest, CtrlCDuringAWalkLeavesNoVideo) {
    // A long flight through the Cornell box whose frames take long: interrupted in its second frame.
    writeText(dir / "walk.txt", "0 key W down\n100 key W up\n");
    const RunResult r = interruptedWalk(dir, "render cornell --walk walk.txt --width 32 --height 32 --spp 1000000 "
                                             "--time-limit 2s -o walk.mp4");
    expectOneLineError(r, 128 + SIGINT, "interrupted by SIGINT after ");
    EXPECT_NE(r.err.find("no video was written"), std::string::npos) << r.err;
    EXPECT_EQ(filesIn(dir), std::vector<fs::path>{dir / "walk.txt"});  // no video, no temporary file
}

TEST_F(CliTest, ABadWalkIsOneLineAndWritesNothing) {
    expectOneLineError(run("render cornell --walk missing.txt -o w.mp4"), 1, "--walk: cannot read missing.txt");
    writeText(dir / "walk.txt", "0 key W down\n0.5 key NOPE down\n");
    expectOneLineError(run("render cornell --walk walk.txt -o w.mp4"), 1, "walk.txt:2:");
    writeText(dir / "walk.txt", "1 key W down\n0.5 key W up\n");
    expectOneLineError(run("render cornell --walk walk.txt -o w.mp4"), 1, "walk.txt:2:");
    expectOneLineError(run("render cornell --walk walk.txt --frames 0..3 -o w.mp4"), 2, "leave out --frames");
    expectOneLineError(run("render cornell -o w.mp4"), 2, "a video needs frames");
    expectOneLineError(run("render cornell --viewer-quality -o w.png"), 2, "--viewer-quality");
    writeText(dir / "walk.txt", "0 key W down\n");
    expectOneLineError(run("render cornell --walk walk.txt --width 33 --height 32 -o w.mp4"), 2, "even width");
    EXPECT_EQ(filesIn(dir), std::vector<fs::path>{dir / "walk.txt"});
}

TEST_F(CliTest, FramesOfAnAnimationBecomeAVideo) {
    const RunResult r = run("render cornell --frames 2..4 --width 16 --height 16 --spp 1 -o a.mp4");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const DecodedVideo video = decodeVideo(dir / "a.mp4");
    ASSERT_TRUE(video.error.empty()) << video.error;
    EXPECT_EQ(video.frames.size(), 3u);
    EXPECT_NEAR(video.fps, 24.0, 1e-6);
}

}  // namespace
}  // namespace penumbra::test
