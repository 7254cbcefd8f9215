#include "gpu_fixture.h"

#include <cstdlib>

namespace penumbra::test {

void GpuTest::SetUp() {
    gpu::ContextOptions options;
    const char* device = std::getenv("PENUMBRA_TEST_DEVICE");
    options.deviceSelector = device ? device : "llvmpipe";
    options.validation = true;
    gpu::ContextResult result;
    try {
        result = gpu::Context::create(options);
    } catch (const std::exception& e) {
        result.error = e.what();
    }
    if (!result.context) {
        if (std::getenv("CI")) FAIL() << "CI must have a Vulkan device (lavapipe): " << result.error;
        GTEST_SKIP() << "no Vulkan device: " << result.error;
    }
    ctx = std::move(result.context);
}

void GpuTest::TearDown() {
    if (!ctx) return;
    auto messages = ctx->validationMessages();
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation messages, first: " << messages.front();
}

}  // namespace penumbra::test
