// The render command's small parsers: --frames, frame file names, --aov.
#include <gtest/gtest.h>

#include "app/render_options.h"
#include "app/render_outputs.h"
#include "app/render_sequence.h"
#include "core/error.h"

namespace penumbra::app {
namespace {

TEST(RenderOptions, FrameRanges) {
    EXPECT_EQ(parseFrames("1..48").first, 1);
    EXPECT_EQ(parseFrames("1..48").last, 48);
    EXPECT_EQ(parseFrames("7..7").last, 7);
    for (const char* bad : {"", "1", "..4", "1..", "a..b", "-1..3", "1..2..3", "4..1", "1..x", "0..99999999", "1...3"})
        EXPECT_THROW(parseFrames(bad), UsageError) << bad;
}

TEST(RenderOptions, FrameFileNames) {
    EXPECT_EQ(framePath("out/a.png", 7), "out/a_0007.png");
    EXPECT_EQ(framePath("out/a_%d.exr", 12), "out/a_12.exr");
    EXPECT_EQ(framePath("out/%06d-a.png", 12), "out/000012-a.png");
    EXPECT_EQ(framePath("out%d/a.png", 3), "out%d/a_0003.png");  // only the file name is a pattern
    EXPECT_THROW(framePath("a%s.png", 1), UsageError);
    EXPECT_THROW(framePath("a%d%d.png", 1), UsageError);
    EXPECT_THROW(framePath("a%.png", 1), UsageError);
}

TEST(RenderOptions, AovNames) {
    const AovSet all = parseAovs({"albedo", "normal", "depth", "variance", "samples"});
    EXPECT_TRUE(all.albedo && all.normal && all.depth && all.variance && all.samples);
    EXPECT_FALSE(parseAovs({}).any());
    EXPECT_TRUE(parseAovs({"depth"}).needsGuides());
    EXPECT_FALSE(parseAovs({"samples"}).needsGuides());
    EXPECT_THROW(parseAovs({"alpha"}), UsageError);
}

TEST(RenderOptions, AovFileGoesBesideAPngOrIntoAnExr) {
    EXPECT_EQ(aovPathFor("out/a.exr"), "out/a.exr");
    EXPECT_EQ(aovPathFor("out/a.png"), "out/a.exr");
    EXPECT_EQ(statePathFor("out/a.png"), "out/a.png.state");
}

}  // namespace
}  // namespace penumbra::app
