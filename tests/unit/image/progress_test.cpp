#include "core/progress.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace penumbra {
namespace {

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

TEST(FormatDuration, MinutesAndHours) {
    EXPECT_EQ(formatDuration(0), "0:00");
    EXPECT_EQ(formatDuration(65), "1:05");
    EXPECT_EQ(formatDuration(3600 + 2 * 60 + 3), "1:02:03");
    EXPECT_EQ(formatDuration(-1), "--:--");
}

TEST(FormatProgress, ShowsPercentCountsElapsedAndEta) {
    std::string line = formatProgress("render", 250, 1000, 10.0, 100);
    EXPECT_TRUE(contains(line, "render [")) << line;
    EXPECT_TRUE(contains(line, " 25%")) << line;
    EXPECT_TRUE(contains(line, "250/1000")) << line;
    EXPECT_TRUE(contains(line, "0:10 elapsed")) << line;
    EXPECT_TRUE(contains(line, "ETA 0:30")) << line;  // 10 s per quarter, three quarters left
    EXPECT_EQ(line.size(), 100u);                      // bar fills the width exactly
}

TEST(FormatProgress, BarFillMatchesFraction) {
    std::string half = formatProgress("x", 50, 100, 1.0, 80);
    auto open = half.find('['), close = half.find(']');
    ASSERT_NE(open, std::string::npos);
    std::string bar = half.substr(open + 1, close - open - 1);
    EXPECT_EQ(static_cast<std::size_t>(std::count(bar.begin(), bar.end(), '=')), bar.size() / 2);
    std::string full = formatProgress("x", 100, 100, 1.0, 80);
    EXPECT_FALSE(contains(full, ">")) << full;
    EXPECT_TRUE(contains(full, "100%")) << full;
}

TEST(FormatProgress, EdgeCases) {
    EXPECT_TRUE(contains(formatProgress("r", 0, 10, 0.0, 80), "ETA --:--"));
    EXPECT_TRUE(contains(formatProgress("r", 0, 0, 0.0, 80), "100%"));
    EXPECT_TRUE(contains(formatProgress("r", 20, 10, 0.0, 80), "10/10"));  // clamped
    std::string narrow = formatProgress("render", 5, 10, 1.0, 30);
    EXPECT_FALSE(contains(narrow, "[")) << narrow;  // no room for a bar
    EXPECT_LE(narrow.size(), 30u);
}

TEST(ProgressBar, DisabledOrNotATerminalIsSilent) {
    testing::internal::CaptureStderr();
    {
        ProgressBar bar("render", 10, false);
        for (int i = 0; i <= 10; ++i) bar.update(i);
        bar.finish();
    }
    {
        ProgressBar bar("render", 10, true);  // stderr is captured, so not a terminal
        bar.update(5);
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(FormatProgressJson, OneObjectWithCountsTimesAndEta) {
    ProgressState s{250, 1000, 10.0, -1, "spp"};
    EXPECT_EQ(formatProgressJson("render", s, false),
              R"({"progress":"render","done":250,"total":1000,"unit":"spp","elapsed":10.000,"eta":30.000,"final":false})");
    s.etaSeconds = 4.5;  // a time limit that comes first replaces the rate's estimate
    EXPECT_TRUE(contains(formatProgressJson("render", s, false), R"("eta":4.500)"));
    EXPECT_TRUE(contains(formatProgressJson("render", s, true), R"("eta":0.000,"final":true})"));
    EXPECT_TRUE(contains(formatProgressJson("r", ProgressState{0, 10, 0.5, -1, "spp"}, false), R"("eta":null)"));
    // A label can never break the JSON.
    EXPECT_TRUE(contains(formatProgressJson("frame \"7\"\n", s, false), R"("progress":"frame 7")"));
}

TEST(FormatProgress, AGivenEtaReplacesTheRatesEstimate) {
    const std::string line = formatProgress("render", ProgressState{250, 1000, 10.0, 5.0, "spp"}, 100);
    EXPECT_TRUE(contains(line, "ETA 0:05")) << line;
    EXPECT_TRUE(contains(line, "250/1000 spp")) << line;
}

}  // namespace
}  // namespace penumbra
