#include "gpu_fixture.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>

#include "core/error.h"

namespace penumbra::test {
namespace {

std::atomic<int> contextsOpened{0};  // in this process, by openTestContext

}  // namespace

gpu::ContextOptions testContextOptions() {
    gpu::ContextOptions options;
    const char* device = std::getenv("PENUMBRA_TEST_DEVICE");
    options.deviceSelector = device && *device ? device : "llvmpipe";
    options.validation = true;
    return options;
}

TestContext openTestContext(const gpu::ContextOptions& options) {
    TestContext out;
    try {
        gpu::ContextResult result = gpu::Context::create(options);
        out.context = std::move(result.context);
        out.error = result.error;
        out.skip = !out.context;
    } catch (const UsageError& e) {  // no device matches PENUMBRA_TEST_DEVICE here
        out.error = e.what();
        out.skip = true;
    } catch (const std::exception& e) {
        out.error = e.what();
    }
    if (out.context) {
        ++contextsOpened;
    } else if (out.skip && contextsOpened > 0) {
        out.skip = false;
        out.error = "a Vulkan context could not be created after " + std::to_string(contextsOpened.load()) +
                    " earlier ones in this process worked: " + out.error;
    }
    return out;
}

::testing::AssertionResult noValidationMessages(const gpu::ValidationLog& log, const std::string& when) {
    const std::vector<std::string> messages = log.messages();
    if (messages.empty()) return ::testing::AssertionSuccess();
    auto failure = ::testing::AssertionFailure() << messages.size() << " validation messages (" << when << "):";
    for (std::size_t i = 0; i < messages.size() && i < 3; ++i) failure << "\n  " << messages[i];
    return failure;
}

void GpuTest::SetUp() {
    TestContext opened = openTestContext();
    if (!opened.context) {
        if (!opened.skip) FAIL() << opened.error;
        if (std::getenv("CI")) FAIL() << "CI must have a Vulkan device (lavapipe): " << opened.error;
        GTEST_SKIP() << "no Vulkan device: " << opened.error;
    }
    ctx = std::move(opened.context);
}

void GpuTest::TearDown() {
    if (ctx) messagesAtTearDown_ = ctx->validationLog()->size();
}

// Runs after the derived fixtures' members (buffers, passes) are gone, so the device can go too.
GpuTest::~GpuTest() {
    if (!ctx) return;
    std::shared_ptr<const gpu::ValidationLog> log = ctx->validationLog();
    ctx.reset();
    const std::size_t atDestruction = log->size() - std::min(log->size(), messagesAtTearDown_);
    std::string when = std::to_string(atDestruction);
    when += " of them while the context was destroyed";
    EXPECT_TRUE(noValidationMessages(*log, when));
}

}  // namespace penumbra::test
