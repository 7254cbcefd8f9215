// Issue 12: a lost device or exhausted memory, at any Vulkan call, is an Error with one line that
// says what happened and what to do, never a hang or a crash (a destructor that threw would call
// std::terminate). Faked through the PN_VK test hook (gpu/check.h), since lavapipe cannot be lost.
#include "gpu/check.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/presets.h"

namespace penumbra::test {
namespace {

// Arms the hook for a scope; the device "recovers" when it ends.
struct InjectedFailure {
    InjectedFailure(VkResult result, std::uint64_t afterCalls) { gpu::injectVkFailure(result, afterCalls); }
    ~InjectedFailure() { gpu::injectVkFailure(VK_SUCCESS, 0); }
};

using DeviceLossTest = GpuTest;

TEST_F(DeviceLossTest, ALostDeviceIsOneLineNamingTheCallAndWhatToDo) {
    gpu::Commands commands(*ctx);
    InjectedFailure lost(VK_ERROR_DEVICE_LOST, 0);
    try {
        commands.run([](VkCommandBuffer) {});
        FAIL() << "the lost device went unnoticed";
    } catch (const gpu::VulkanError& e) {
        const std::string message = e.what();
        EXPECT_EQ(e.result, VK_ERROR_DEVICE_LOST);
        EXPECT_NE(message.find("returned VK_ERROR_DEVICE_LOST"), std::string::npos) << message;
        EXPECT_NE(message.find("the GPU was lost"), std::string::npos) << message;
        EXPECT_NE(message.find("--device"), std::string::npos) << "what to do: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    }
}

TEST_F(DeviceLossTest, OutOfMemoryAtAnyCallSaysWhatToShrink) {
    InjectedFailure oom(VK_ERROR_OUT_OF_DEVICE_MEMORY, 0);
    try {
        gpu::Buffer buffer(*ctx, 1024, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryKind::DeviceLocal);
        FAIL() << "the failed allocation went unnoticed";
    } catch (const gpu::VulkanError& e) {
        EXPECT_NE(std::string(e.what()).find("out of memory: render a smaller image"), std::string::npos) << e.what();
    }
}

// The renderer is lost part-way through a render, at every fifth of its calls from the first to
// the last; each time the Error reaches the caller and everything is torn down cleanly. (It once
// crashed lavapipe's queue thread: a loss injected into the wait after a submission unwound the
// Renderer's buffers while that submission still ran, because ~Commands, the member made first,
// waited for it only after they were gone. gpu::Commands::run now waits before it rethrows.)
TEST_F(DeviceLossTest, ARendererLostAtAnyCallUnwindsWithoutCrashing) {
    const Scene scene = makeCornellBox();
    const RenderSettings settings = testSettings(8, 8, 4, 2);
    auto renderOnce = [&] {
        Renderer renderer(*ctx, scene, settings);
        renderer.render();
        (void)renderer.image();
    };
    std::uint64_t calls = 0;
    {
        InjectedFailure never(VK_ERROR_DEVICE_LOST, UINT64_MAX);  // counts down, never fails
        renderOnce();
        calls = UINT64_MAX - gpu::injectVkFailureCallsLeft();
    }
    ASSERT_GT(calls, 20u);
    for (std::uint64_t at : {std::uint64_t(0), calls / 5, 2 * calls / 5, 3 * calls / 5, 4 * calls / 5, calls - 1}) {
        InjectedFailure lost(VK_ERROR_DEVICE_LOST, at);
        bool threw = false;
        try {
            renderOnce();
        } catch (const gpu::VulkanError& e) {
            threw = true;
            EXPECT_EQ(e.result, VK_ERROR_DEVICE_LOST) << e.what();
        }
        EXPECT_TRUE(threw) << "lost after " << at << " of " << calls << " calls, yet the render finished";
    }
}

}  // namespace
}  // namespace penumbra::test
