// Issue 12: a scene larger than the device allows is refused before anything is allocated, with
// a line that names the scene's size, the device's limit and what to do. lavapipe's limits are
// lowered through PENUMBRA_TEST_MAX_STORAGE_BUFFER / PENUMBRA_TEST_DEVICE_MEMORY (gpu/limits.h).
#include <algorithm>
#include <numeric>

#include "core/error.h"
#include "gpu/commands.h"
#include "gpu/limits.h"
#include "gpu/tally.h"
#include "gpu_fixture.h"
#include "render/scene_limits.h"
#include "scene/presets/presets.h"
#include "scoped_env.h"

namespace penumbra::test {
namespace {

class DeviceLimitsTest : public GpuTest {
protected:
    SceneArrays arrays = buildSceneArrays(makeCornellBox());

    std::uint64_t largestBuffer() const {
        std::uint64_t largest = 0;
        for (const SceneBufferSize& b : sceneBufferSizes(arrays)) largest = std::max(largest, b.bytes);
        return largest;
    }

    // The message of the Error uploading `arrays` throws, or "" when it fits.
    std::string uploadError() {
        gpu::Commands commands(*ctx);
        const gpu::VulkanTally before = gpu::vulkanTally();
        try {
            GpuScene scene(*ctx, commands, arrays);
        } catch (const Error& e) {
            // Refused before the first buffer: nothing was made and freed again on the way out.
            EXPECT_EQ(gpu::vulkanTally().buffersLive, before.buffersLive);
            return e.what();
        }
        return "";
    }
};

TEST(SceneBufferSizes, AddUpToTheBytesTheSceneTakesOnTheDevice) {
    const SceneArrays arrays = buildSceneArrays(makeCornellBox());
    const std::vector<SceneBufferSize> sizes = sceneBufferSizes(arrays);
    const std::uint64_t sum = std::accumulate(sizes.begin(), sizes.end(), std::uint64_t(0),
                                              [](std::uint64_t s, const SceneBufferSize& b) { return s + b.bytes; });
    EXPECT_EQ(sum, deviceBytes(arrays)) << "a buffer GpuScene uploads is missing from sceneBufferSizes";
}

TEST_F(DeviceLimitsTest, ABufferPastMaxStorageBufferRangeIsRefusedBeforeAnyUpload) {
    const std::uint64_t largest = largestBuffer();
    ASSERT_GT(largest, 16u);
    ScopedEnv limit("PENUMBRA_TEST_MAX_STORAGE_BUFFER", std::to_string(largest - 1));
    const std::string error = uploadError();
    EXPECT_NE(error.find("the scene's "), std::string::npos) << error;
    EXPECT_NE(error.find(gpu::formatBytes(largest)), std::string::npos) << "the scene's size: " << error;
    EXPECT_NE(error.find("maxStorageBufferRange " + gpu::formatBytes(largest - 1)), std::string::npos) << error;
    EXPECT_NE(error.find(ctx->info().name), std::string::npos) << "which device: " << error;
    EXPECT_NE(error.find("another device (--device)"), std::string::npos) << "what to do: " << error;
}

TEST_F(DeviceLimitsTest, ASceneLargerThanDeviceMemoryIsRefused) {
    const std::uint64_t total = deviceBytes(arrays);
    ScopedEnv limit("PENUMBRA_TEST_DEVICE_MEMORY", std::to_string(total - 1));
    const std::string error = uploadError();
    EXPECT_NE(error.find("takes " + gpu::formatBytes(total)), std::string::npos) << error;
    EXPECT_NE(error.find("smaller scene"), std::string::npos) << error;
}

TEST_F(DeviceLimitsTest, ASceneExactlyAtTheLimitsUploads) {
    ScopedEnv range("PENUMBRA_TEST_MAX_STORAGE_BUFFER", std::to_string(largestBuffer()));
    ScopedEnv memory("PENUMBRA_TEST_DEVICE_MEMORY", std::to_string(deviceBytes(arrays)));
    EXPECT_EQ(uploadError(), "");
}

TEST_F(DeviceLimitsTest, AnyStorageBufferPastTheRangeIsRefusedOtherBuffersAreNot) {
    ScopedEnv limit("PENUMBRA_TEST_MAX_STORAGE_BUFFER", "4096");
    try {
        gpu::Buffer image(*ctx, 4096 + 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryKind::DeviceLocal);
        ADD_FAILURE() << "a storage buffer past the range was made";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--width/--height"), std::string::npos) << e.what();
    }
    gpu::Buffer fits(*ctx, 4096, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryKind::DeviceLocal);
    gpu::Buffer staging(*ctx, 8192, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryKind::HostVisible);
    EXPECT_EQ(fits.size(), 4096u);
}

TEST_F(DeviceLimitsTest, ALimitThatIsNotANumberIsAnError) {
    ScopedEnv limit("PENUMBRA_TEST_MAX_STORAGE_BUFFER", "lots");
    EXPECT_THROW(gpu::memoryLimits(*ctx), Error);
}

}  // namespace
}  // namespace penumbra::test
