// app/environment_settings: every PENUMBRA_* switch the program reads at start lands in the
// setting it names, unset ones keep the shipped defaults, and a malformed value is one usage
// error naming its variable.
#include "app/environment_settings.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"

namespace penumbra::app {
namespace {

constexpr const char* kVariables[] = {
    "PENUMBRA_TRACE_KERNEL",   "PENUMBRA_WAVE_TAIL_PATHS", "PENUMBRA_WAVE_STAGE_TIMES",
    "PENUMBRA_GENERIC_KERNEL", "PENUMBRA_LIGHT_GRID",      "PENUMBRA_LIGHT_GRID_LEVELS",
    "PENUMBRA_LIGHT_GRID_MB",  "PENUMBRA_LIGHT_GRID_DRAW", "PENUMBRA_FORCE_INSTANCES",
    "PENUMBRA_REST_TREE",      "PENUMBRA_CACHE_DIR",      "XDG_CACHE_HOME",           "HOME"};

class EnvironmentSettingsTest : public ::testing::Test {
protected:
    void SetUp() override {
        for (const char* name : kVariables) {
            if (const char* v = std::getenv(name)) saved_.emplace_back(name, v);
            unsetenv(name);
        }
    }
    void TearDown() override {
        for (const char* name : kVariables) unsetenv(name);
        for (const auto& [name, value] : saved_) setenv(name.c_str(), value.c_str(), 1);
    }
    static void set(const char* name, const char* value) { setenv(name, value, 1); }

private:
    std::vector<std::pair<std::string, std::string>> saved_;
};

TEST_F(EnvironmentSettingsTest, NothingSetGivesTheShippedDefaults) {
    const RenderTuning t = renderTuningFromEnvironment(), shipped;
    EXPECT_EQ(t.traceKernel, TraceKernel::Auto);
    EXPECT_EQ(t.waveTailPaths, kDefaultWaveTailPaths);
    EXPECT_FALSE(t.waveStageTimes);
    EXPECT_FALSE(t.genericKernel);
    EXPECT_TRUE(t.lightGrid);
    EXPECT_EQ(t.lightGridOptions.levels, shipped.lightGridOptions.levels);
    EXPECT_EQ(t.lightGridOptions.maxWords, shipped.lightGridOptions.maxWords);
    EXPECT_TRUE(t.lightGridOptions.drawInClusters);
    EXPECT_FALSE(t.forceInstances);
    EXPECT_TRUE(t.restTree);
    EXPECT_TRUE(bvhCacheDirectoryFromEnvironment().empty());
}

TEST_F(EnvironmentSettingsTest, EachVariableSetsItsSetting) {
    set("PENUMBRA_TRACE_KERNEL", "mega");
    set("PENUMBRA_WAVE_TAIL_PATHS", "0");
    set("PENUMBRA_WAVE_STAGE_TIMES", "1");
    set("PENUMBRA_GENERIC_KERNEL", "yes");  // anything but 0
    set("PENUMBRA_LIGHT_GRID", "0");
    set("PENUMBRA_LIGHT_GRID_LEVELS", "3");
    set("PENUMBRA_LIGHT_GRID_MB", "2");
    set("PENUMBRA_LIGHT_GRID_DRAW", "0");
    set("PENUMBRA_FORCE_INSTANCES", "1");
    set("PENUMBRA_REST_TREE", "0");
    const RenderTuning t = renderTuningFromEnvironment();
    EXPECT_EQ(t.traceKernel, TraceKernel::Megakernel);
    EXPECT_EQ(t.waveTailPaths, 0u);
    EXPECT_TRUE(t.waveStageTimes);
    EXPECT_TRUE(t.genericKernel);
    EXPECT_FALSE(t.lightGrid);
    EXPECT_EQ(t.lightGridOptions.levels, 3u);
    EXPECT_EQ(t.lightGridOptions.maxWords, 2u << 18);  // 2 MiB of 4-byte words
    EXPECT_FALSE(t.lightGridOptions.drawInClusters);
    EXPECT_TRUE(t.forceInstances);
    EXPECT_FALSE(t.restTree);
    set("PENUMBRA_TRACE_KERNEL", "wavefront");
    EXPECT_EQ(renderTuningFromEnvironment().traceKernel, TraceKernel::Wavefront);
}

// The switches keep their old reading: only "1" turns these on, "0" leaves generic off.
TEST_F(EnvironmentSettingsTest, SwitchesReadAsBefore) {
    set("PENUMBRA_WAVE_STAGE_TIMES", "yes");
    set("PENUMBRA_FORCE_INSTANCES", "2");
    set("PENUMBRA_GENERIC_KERNEL", "0");
    const RenderTuning t = renderTuningFromEnvironment();
    EXPECT_FALSE(t.waveStageTimes);
    EXPECT_FALSE(t.forceInstances);
    EXPECT_FALSE(t.genericKernel);
}

TEST_F(EnvironmentSettingsTest, MalformedValuesAreOneUsageErrorNamingTheVariable) {
    const std::pair<const char*, const char*> bad[] = {
        {"PENUMBRA_TRACE_KERNEL", "megakernel"},    {"PENUMBRA_WAVE_TAIL_PATHS", "-1"},
        {"PENUMBRA_WAVE_TAIL_PATHS", "4294967296"}, {"PENUMBRA_LIGHT_GRID", "2"},
        {"PENUMBRA_LIGHT_GRID_LEVELS", "0"},        {"PENUMBRA_LIGHT_GRID_MB", "1025"},
        {"PENUMBRA_LIGHT_GRID_DRAW", "off"}};
    for (const auto& [name, value] : bad) {
        set(name, value);
        try {
            renderTuningFromEnvironment();
            ADD_FAILURE() << name << "=" << value << " accepted";
        } catch (const UsageError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(name), std::string::npos) << message;
            EXPECT_NE(message.find(value), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
        }
        unsetenv(name);
    }
}

TEST_F(EnvironmentSettingsTest, CacheDirectoryFallsBackInOrder) {
    set("HOME", "/home/someone");
    EXPECT_EQ(bvhCacheDirectoryFromEnvironment(), "/home/someone/.cache/penumbra");
    set("XDG_CACHE_HOME", "/xdg");
    EXPECT_EQ(bvhCacheDirectoryFromEnvironment(), "/xdg/penumbra");
    set("PENUMBRA_CACHE_DIR", "/exact");
    EXPECT_EQ(bvhCacheDirectoryFromEnvironment(), "/exact");
}

}  // namespace
}  // namespace penumbra::app
