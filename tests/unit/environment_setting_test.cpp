// Numeric settings from environment variables: defaults, accepted values, and one clear usage
// error (naming the variable) for anything malformed or out of range.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "core/environment.h"
#include "core/error.h"

namespace penumbra {
namespace {

constexpr const char* kName = "PENUMBRA_TEST_ENVIRONMENT_SETTING";

class EnvironmentSettingTest : public ::testing::Test {
protected:
    void TearDown() override { unsetenv(kName); }
    void set(const char* value) { setenv(kName, value, 1); }
};

TEST_F(EnvironmentSettingTest, UnsetOrEmptyGivesTheFallback) {
    unsetenv(kName);
    EXPECT_EQ(environmentSetting(kName, 7, 0, 10), 7u);
    set("");
    EXPECT_EQ(environmentSetting(kName, 7, 0, 10), 7u);
}

TEST_F(EnvironmentSettingTest, WholeNumbersInRangeAreRead) {
    set("0");
    EXPECT_EQ(environmentSetting(kName, 7, 0, 10), 0u);
    set("10");
    EXPECT_EQ(environmentSetting(kName, 7, 0, 10), 10u);
    set("18446744073709551615");
    EXPECT_EQ(environmentSetting(kName, 7, 1, UINT64_MAX), UINT64_MAX);
}

TEST_F(EnvironmentSettingTest, AnythingElseIsAUsageErrorNamingTheVariable) {
    for (const char* bad : {"11", "-1", "+3", " 3", "3 ", "3x", "0x10", "1.5", "18446744073709551616", "abc"}) {
        set(bad);
        try {
            environmentSetting(kName, 7, 0, 10);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const UsageError& e) {
            EXPECT_NE(std::string(e.what()).find(kName), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace penumbra
