// What a failed context creation says. Issue 16: after about 30 contexts, the NVIDIA driver
// refused another, and the tests skipped with "no Vulkan driver could be loaded; install a GPU
// driver", though the driver had worked all along.
#include <cstdlib>

#include "gpu_fixture.h"
#include "scoped_env.h"

namespace penumbra::test {
namespace {

TEST(ContextErrorTest, ADriverThatWorkedEarlierInTheProcessIsNotCalledMissing) {
    TestContext first = openTestContext();
    if (!first.context) {
        if (!first.skip || std::getenv("CI")) FAIL() << first.error;
        GTEST_SKIP() << "no Vulkan device: " << first.error;
    }
    std::string error;
    bool skip = true;
    {
        // A new instance (the old behaviour) while the loader finds no driver: what a driver that
        // refuses one more instance looks like.
        ScopedEnv perContext("PENUMBRA_INSTANCE_PER_CONTEXT", "1");
        ScopedEnv drivers("VK_DRIVER_FILES", "/nonexistent/icd.json");
        ScopedEnv icds("VK_ICD_FILENAMES", "/nonexistent/icd.json");
        TestContext second = openTestContext();
        ASSERT_FALSE(second.context);
        error = second.error;
        skip = second.skip;
    }
    EXPECT_FALSE(skip) << "a failure after an earlier success must fail the test, not skip it: " << error;
    EXPECT_NE(error.find("vkCreateInstance returned VK_ERROR_INCOMPATIBLE_DRIVER"), std::string::npos) << error;
    EXPECT_NE(error.find("after this process had created"), std::string::npos) << error;
    EXPECT_EQ(error.find("install a GPU driver"), std::string::npos) << "the driver is there: " << error;

    TestContext third = openTestContext();  // the environment is back: contexts work again
    EXPECT_TRUE(third.context) << third.error;
}

}  // namespace
}  // namespace penumbra::test
