// H.264 files written by VideoWriter, read back with FFmpeg's decoder: frame count, size, rate,
// and pixels close to what went in (a lossy codec: compared with a tolerance, not bit for bit).
#include "image/video_writer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/atomic_file.h"
#include "core/error.h"
#include "test_dir.h"
#include "video_decode.h"

namespace penumbra::test {
namespace {

// A frame whose content moves with its index: a bright square on a gradient.
std::vector<std::uint8_t> testFrame(std::uint32_t w, std::uint32_t h, int index) {
    std::vector<std::uint8_t> rgb(std::size_t(w) * h * 3);
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            std::uint8_t* p = &rgb[(std::size_t(y) * w + x) * 3];
            const bool square = x >= std::uint32_t(4 * index) && x < std::uint32_t(4 * index + 16) && y >= 8 && y < 24;
            p[0] = square ? 240 : std::uint8_t(x * 255 / w);
            p[1] = square ? 240 : std::uint8_t(y * 255 / h);
            p[2] = square ? 240 : 64;
        }
    return rgb;
}

TEST(VideoWriter, FramesComeBackWithTheirCountSizeRateAndPixels) {
    TempDir dir;
    const std::uint32_t w = 64, h = 48;
    {
        VideoWriter writer(dir / "a.mp4", dir / "a.mp4", VideoSettings{w, h, 25, 18});
        for (int i = 0; i < 7; ++i) writer.addFrame(testFrame(w, h, i));
        writer.finish();
        EXPECT_EQ(writer.frames(), 7u);
    }
    const DecodedVideo video = decodeVideo(dir / "a.mp4");
    ASSERT_TRUE(video.error.empty()) << video.error;
    EXPECT_EQ(video.codec, "h264");
    EXPECT_EQ(video.width, int(w));
    EXPECT_EQ(video.height, int(h));
    EXPECT_NEAR(video.fps, 25.0, 1e-6);
    ASSERT_EQ(video.frames.size(), 7u);
    for (int i = 0; i < 7; ++i) {
        // Each decoded frame is closest to the frame written in its place.
        const double own = meanAbsDifference(video.frames[i], testFrame(w, h, i));
        EXPECT_LT(own, 6.0) << "frame " << i;
        for (int j = 0; j < 7; ++j) {
            if (j == i) continue;
            EXPECT_LT(own, meanAbsDifference(video.frames[i], testFrame(w, h, j))) << i << " vs " << j;
        }
    }
}

TEST(VideoWriter, OddSizesAndUnknownContainersAreUsageErrors) {
    TempDir dir;
    EXPECT_THROW(VideoWriter(dir / "a.mp4", dir / "a.mp4", VideoSettings{63, 48, 24, 18}), UsageError);
    EXPECT_THROW(VideoWriter(dir / "a.avi", dir / "a.avi", VideoSettings{64, 48, 24, 18}), UsageError);
    EXPECT_THROW(VideoWriter(dir / "a.mp4", dir / "a.mp4", VideoSettings{64, 48, 0, 18}), UsageError);
}

TEST(VideoWriter, AnUnfinishedVideoInAPendingFileLeavesNothingBehind) {
    TempDir dir;
    {
        PendingFile file(dir / "v.mp4");
        VideoWriter writer(file.tmp(), file.target(), VideoSettings{32, 32, 24, 18});
        writer.addFrame(testFrame(32, 32, 0));
        // No finish, no commit: an error or Ctrl-C unwinding.
    }
    EXPECT_TRUE(dir.entries().empty());
    {
        PendingFile file(dir / "v.mp4");
        VideoWriter writer(file.tmp(), file.target(), VideoSettings{32, 32, 24, 18});
        writer.addFrame(testFrame(32, 32, 0));
        writer.finish();
        file.commit();
    }
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"v.mp4"});
    EXPECT_EQ(decodeVideo(dir / "v.mp4").frames.size(), 1u);
}

TEST(VideoWriter, IsVideoPathKnowsTheContainers) {
    EXPECT_TRUE(isVideoPath("a.mp4"));
    EXPECT_TRUE(isVideoPath("dir/A.MKV"));
    EXPECT_TRUE(isVideoPath("a.mov"));
    EXPECT_FALSE(isVideoPath("a.png"));
    EXPECT_FALSE(isVideoPath("mp4"));
}

}  // namespace
}  // namespace penumbra::test
