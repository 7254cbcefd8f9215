// The settings panel over the network (serve/remote_settings.h): each setting reaches the view's
// settings, out-of-range values are clamped, wrong types and unknown names change nothing.
#include <gtest/gtest.h>

#include "serve/remote_settings.h"

namespace penumbra::serve {
namespace {

bool apply(RemoteState& s, const std::string& name, const nlohmann::json& value) {
    std::string error;
    const bool ok = applySetting(s, name, value, error);
    EXPECT_EQ(ok, error.empty()) << name << ": " << error;
    return ok;
}

TEST(ServeSettings, EachSettingReachesTheView) {
    RemoteState s;
    EXPECT_TRUE(apply(s, "spp", 4));
    EXPECT_TRUE(apply(s, "bounces", 3));
    EXPECT_TRUE(apply(s, "scale", 0.5));
    EXPECT_TRUE(apply(s, "temporal", false));
    EXPECT_TRUE(apply(s, "denoise", 3));
    EXPECT_TRUE(apply(s, "debug", "normals"));
    EXPECT_TRUE(apply(s, "debugOpacity", 0.25));
    EXPECT_TRUE(apply(s, "torch", true));
    EXPECT_TRUE(apply(s, "exposure", -1.5));
    EXPECT_TRUE(apply(s, "playing", false));
    EXPECT_TRUE(s.phantom);
    EXPECT_TRUE(apply(s, "phantom", false));
    EXPECT_FALSE(apply(s, "phantom", 1));  // a number is not a switch
    EXPECT_EQ(s.view.samplesPerFrame, 4u);
    EXPECT_EQ(s.view.maxBounces, 3u);
    EXPECT_FLOAT_EQ(s.view.resolutionScale, 0.5f);
    EXPECT_FALSE(s.view.temporal);
    EXPECT_TRUE(s.view.denoise);
    EXPECT_EQ(s.view.denoiseIterations, 3u);
    EXPECT_EQ(s.view.debug, DebugView::Normals);
    EXPECT_FLOAT_EQ(s.view.debugOpacity, 0.25f);
    EXPECT_TRUE(s.view.torch);
    EXPECT_FLOAT_EQ(s.view.exposure, -1.5f);
    EXPECT_FALSE(s.playing);
    EXPECT_FALSE(s.phantom);
    // And back out as the JSON the page reads.
    const nlohmann::json j = settingsJson(s);
    EXPECT_EQ(j["spp"], 4);
    EXPECT_EQ(j["denoise"], 3);
    EXPECT_EQ(j["debug"], "normals");
    EXPECT_EQ(j["playing"], false);
    EXPECT_EQ(j["phantom"], false);
    EXPECT_TRUE(apply(s, "denoise", 0));
    EXPECT_FALSE(s.view.denoise);
    EXPECT_EQ(settingsJson(s)["denoise"], 0);
}

TEST(ServeSettings, ClampsToTheRanges) {
    RemoteState s;
    apply(s, "spp", 1000);
    apply(s, "bounces", -5);
    apply(s, "scale", 7);
    apply(s, "exposure", -99);
    apply(s, "debugOpacity", 2);
    EXPECT_EQ(s.view.samplesPerFrame, 64u);
    EXPECT_EQ(s.view.maxBounces, 1u);
    EXPECT_FLOAT_EQ(s.view.resolutionScale, kResolutionScaleRange.max);  // 2: supersampling
    EXPECT_FLOAT_EQ(s.view.exposure, -10.0f);
    EXPECT_FLOAT_EQ(s.view.debugOpacity, 1.0f);
}

TEST(ServeSettings, ResolutionScaleGoesFromAQuarterToTwiceTheWindow) {
    RemoteState s;
    apply(s, "scale", 0.1);
    EXPECT_FLOAT_EQ(s.view.resolutionScale, 0.25f);
    apply(s, "scale", 1.5);
    EXPECT_FLOAT_EQ(s.view.resolutionScale, 1.5f);
    // The page's control takes its limits from the same range.
    const nlohmann::json ranges = settingRangesJson();
    EXPECT_EQ(ranges["scale"], nlohmann::json::array({0.25f, 2.0f}));
    // The renderer's size: a quarter to twice the window.
    EXPECT_EQ(scaledSide(1280, 2.0f), 2560u);
    EXPECT_EQ(scaledSide(1280, 0.25f), 320u);
    EXPECT_EQ(scaledSide(1280, 9.0f), 2560u);
    EXPECT_EQ(scaledSide(2, 0.01f), 1u);
}

TEST(ServeSettings, WrongTypesAndUnknownNamesChangeNothing) {
    RemoteState s;
    const ViewSettings before = s.view;
    for (const auto& [name, value] : std::vector<std::pair<std::string, nlohmann::json>>{
             {"spp", "4"}, {"spp", nullptr}, {"temporal", 1}, {"debug", "sideways"}, {"debug", 3},
             {"torch", "on"}, {"exposure", nlohmann::json::array()}, {"warp", 9}, {"", 1}}) {
        std::string error;
        EXPECT_FALSE(applySetting(s, name, value, error)) << name;
        EXPECT_FALSE(error.empty());
    }
    EXPECT_TRUE(s.view == before);
    EXPECT_TRUE(s.playing);
}

TEST(ServeSettings, DebugViewsStartWithNone) {
    const nlohmann::json names = debugViewsJson();
    ASSERT_GE(names.size(), 2u);
    EXPECT_EQ(names[0], "none");
    for (const auto& name : names) {
        RemoteState s;
        EXPECT_TRUE(apply(s, "debug", name));
        EXPECT_EQ(settingsJson(s)["debug"], name);
    }
}

}  // namespace
}  // namespace penumbra::serve
