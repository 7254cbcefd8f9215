// Shared set-up for GPU tests: a Vulkan context on lavapipe (or PENUMBRA_TEST_DEVICE) with
// validation on. No device: the test is skipped, except under CI, where lavapipe must exist, and
// except after an earlier context in this process worked (a device cannot vanish: that is a bug).
// Any validation message fails the test, including those reported while the context is destroyed
// (objects left alive are reported at vkDestroyDevice).
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "gpu/context.h"

namespace penumbra::test {

// The options every GPU test uses: PENUMBRA_TEST_DEVICE (default "llvmpipe"), validation on.
gpu::ContextOptions testContextOptions();

// A context for a test, or why there is none: `skip` when this machine lacks the device the tests
// ask for (no Vulkan, no such device), otherwise a failure to report.
struct TestContext {
    std::unique_ptr<gpu::Context> context;
    std::string error;
    bool skip = false;
};
TestContext openTestContext(const gpu::ContextOptions& options = testContextOptions());

// Success when `log` holds no message; `when` qualifies the count in the failure.
::testing::AssertionResult noValidationMessages(const gpu::ValidationLog& log, const std::string& when);

class GpuTest : public ::testing::Test {
protected:
    ~GpuTest() override;  // destroys ctx, then checks every message, those at destruction included
    void SetUp() override;
    void TearDown() override;

    std::unique_ptr<gpu::Context> ctx;

private:
    std::size_t messagesAtTearDown_ = 0;
};

}  // namespace penumbra::test
