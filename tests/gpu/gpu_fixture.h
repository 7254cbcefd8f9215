// Shared set-up for GPU tests: a Vulkan context on lavapipe (or PENUMBRA_TEST_DEVICE) with
// validation on. No device: the test is skipped, except under CI, where lavapipe must exist.
// Any validation message fails the test.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "gpu/context.h"

namespace penumbra::test {

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    std::unique_ptr<gpu::Context> ctx;
};

}  // namespace penumbra::test
