// Process-wide counts of the Vulkan objects Penumbra made, for leak tests and for error messages
// that say how many came before a failure. Thread-safe; never reset.
#pragma once

#include <cstdint>
#include <utility>

namespace penumbra::gpu {

struct VulkanTally {
    std::uint64_t instancesCreated = 0, instancesDestroyed = 0;
    std::uint64_t devicesCreated = 0, devicesDestroyed = 0;
    std::uint64_t buffersLive = 0, bufferBytesLive = 0;  // gpu::Buffer objects and their sizes
    // Objects owned through gpu::DeviceHandle: buffers, memory, pipelines and their layouts,
    // descriptor pools, shader modules, fences, command pools, query pools.
    std::uint64_t deviceObjectsLive = 0;

    std::uint64_t instancesLive() const { return instancesCreated - instancesDestroyed; }
    std::uint64_t devicesLive() const { return devicesCreated - devicesDestroyed; }
};

VulkanTally vulkanTally();

namespace tally {
void instanceCreated();
void instanceDestroyed();
void deviceCreated();
void deviceDestroyed();
void deviceObjectCreated();
void deviceObjectDestroyed();
}  // namespace tally

// Counts one live buffer of `bytes` while it lives; a move carries the count along.
class BufferTally {
public:
    BufferTally() = default;
    explicit BufferTally(std::uint64_t bytes);
    BufferTally(BufferTally&& o) noexcept : bytes_(std::exchange(o.bytes_, 0)), live_(std::exchange(o.live_, false)) {}
    BufferTally& operator=(BufferTally&& o) noexcept {
        if (this != &o) {
            release();
            bytes_ = std::exchange(o.bytes_, 0);
            live_ = std::exchange(o.live_, false);
        }
        return *this;
    }
    BufferTally(const BufferTally&) = delete;
    BufferTally& operator=(const BufferTally&) = delete;
    ~BufferTally() { release(); }

private:
    void release();

    std::uint64_t bytes_ = 0;
    bool live_ = false;
};

}  // namespace penumbra::gpu
