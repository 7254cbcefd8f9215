// Validation messages reach the Context they concern, also on the shared instance, and those the
// layer reports while a context is destroyed (objects left alive) are kept for the test to read.
#include <algorithm>
#include <cstdlib>
#include <vector>

#include "gpu_fixture.h"

namespace penumbra::test {
namespace {

// Host memory for objects the test leaves to the driver on purpose: the driver never frees it,
// so the test does, once the device is gone (LeakSanitizer stays quiet).
class LeakArena {
public:
    LeakArena() {
        callbacks_.pUserData = this;
        callbacks_.pfnAllocation = [](void* self, std::size_t size, std::size_t align, VkSystemAllocationScope) {
            return static_cast<LeakArena*>(self)->allocate(size, align);
        };
        callbacks_.pfnReallocation = [](void*, void*, std::size_t, std::size_t, VkSystemAllocationScope) -> void* {
            return nullptr;  // never needed for an event; the driver would report an allocation failure
        };
        callbacks_.pfnFree = [](void* self, void* block) { static_cast<LeakArena*>(self)->release(block); };
    }
    ~LeakArena() {
        for (void* block : blocks_) std::free(block);
    }
    const VkAllocationCallbacks* callbacks() const { return &callbacks_; }

private:
    void* allocate(std::size_t size, std::size_t align) {
        void* block = std::aligned_alloc(align, (size + align - 1) / align * align);
        if (block) blocks_.push_back(block);
        return block;
    }
    void release(void* block) {
        auto found = std::find(blocks_.begin(), blocks_.end(), block);
        if (found == blocks_.end()) return;
        blocks_.erase(found);
        std::free(block);
    }

    VkAllocationCallbacks callbacks_{};
    std::vector<void*> blocks_;
};

// An event made and never destroyed: the layer reports it when its device is destroyed. (An
// event, because lavapipe allocates all of it through the callbacks; a buffer would leak more.)
void leakAnEvent(const gpu::Context& ctx, const LeakArena& arena) {
    VkEventCreateInfo info{VK_STRUCTURE_TYPE_EVENT_CREATE_INFO};
    VkEvent event = VK_NULL_HANDLE;
    ASSERT_EQ(vkCreateEvent(ctx.device(), &info, arena.callbacks(), &event), VK_SUCCESS);
}

TEST(ValidationLogTest, ObjectsLeftAliveAreReportedToTheirOwnContextWhenItIsDestroyed) {
    LeakArena arena;  // outlives the contexts: a driver may free the leaked event with its device
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

    leakAnEvent(*leaky.context, arena);
    std::shared_ptr<const gpu::ValidationLog> leakyLog = leaky.context->validationLog();
    EXPECT_EQ(leakyLog->size(), 0u) << "nothing is wrong until the device is destroyed";
    leaky.context.reset();
    const std::vector<std::string> messages = leakyLog->messages();
    ASSERT_FALSE(messages.empty()) << "destroying a device with a live event must be reported";
    EXPECT_NE(messages.front().find("VkEvent"), std::string::npos) << messages.front();

    std::shared_ptr<const gpu::ValidationLog> cleanLog = clean.context->validationLog();
    clean.context.reset();
    EXPECT_TRUE(noValidationMessages(*cleanLog, "in the other context, which leaked nothing"));
}

}  // namespace
}  // namespace penumbra::test
