// Validation messages reach the Context they concern, also on the shared instance, and those the
// layer reports while a context is destroyed (objects left alive) are kept for the test to read.
#include "gpu_fixture.h"

namespace penumbra::test {
namespace {

// A buffer made and never destroyed: the layer reports it when its device is destroyed.
void leakABuffer(const gpu::Context& ctx) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = 64;
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    ASSERT_EQ(vkCreateBuffer(ctx.device(), &info, nullptr, &buffer), VK_SUCCESS);
}

TEST(ValidationLogTest, ObjectsLeftAliveAreReportedToTheirOwnContextWhenItIsDestroyed) {
    gpu::ContextOptions options = testContextOptions();
    options.printValidation = false;  // the message below is provoked on purpose
    TestContext clean = openTestContext(options);
    if (!clean.context) {
        if (!clean.skip || std::getenv("CI")) FAIL() << clean.error;
        GTEST_SKIP() << "no Vulkan device: " << clean.error;
    }
    TestContext leaky = openTestContext(options);
    ASSERT_TRUE(leaky.context) << leaky.error;
    ASSERT_EQ(clean.context->instance(), leaky.context->instance()) << "contexts alike share one instance";

    leakABuffer(*leaky.context);
    std::shared_ptr<const gpu::ValidationLog> leakyLog = leaky.context->validationLog();
    EXPECT_EQ(leakyLog->size(), 0u) << "nothing is wrong until the device is destroyed";
    leaky.context.reset();
    const std::vector<std::string> messages = leakyLog->messages();
    ASSERT_FALSE(messages.empty()) << "destroying a device with a live buffer must be reported";
    EXPECT_NE(messages.front().find("VkBuffer"), std::string::npos) << messages.front();

    std::shared_ptr<const gpu::ValidationLog> cleanLog = clean.context->validationLog();
    clean.context.reset();
    EXPECT_TRUE(noValidationMessages(*cleanLog, "in the other context, which leaked nothing"));
}

}  // namespace
}  // namespace penumbra::test
