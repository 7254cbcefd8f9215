#include "gpu/tally.h"

#include <atomic>

namespace penumbra::gpu {
namespace {

std::atomic<std::uint64_t> instancesCreated{0}, instancesDestroyed{0};
std::atomic<std::uint64_t> devicesCreated{0}, devicesDestroyed{0};
std::atomic<std::uint64_t> buffersLive{0}, bufferBytesLive{0};
std::atomic<std::uint64_t> deviceObjectsLive{0};

}  // namespace

VulkanTally vulkanTally() {
    VulkanTally t;
    t.instancesCreated = instancesCreated.load();
    t.instancesDestroyed = instancesDestroyed.load();
    t.devicesCreated = devicesCreated.load();
    t.devicesDestroyed = devicesDestroyed.load();
    t.buffersLive = buffersLive.load();
    t.bufferBytesLive = bufferBytesLive.load();
    t.deviceObjectsLive = deviceObjectsLive.load();
    return t;
}

namespace tally {
void instanceCreated() { ++instancesCreated; }
void instanceDestroyed() { ++instancesDestroyed; }
void deviceCreated() { ++devicesCreated; }
void deviceDestroyed() { ++devicesDestroyed; }
void deviceObjectCreated() { ++deviceObjectsLive; }
void deviceObjectDestroyed() { --deviceObjectsLive; }
}  // namespace tally

BufferTally::BufferTally(std::uint64_t bytes) : bytes_(bytes), live_(true) {
    ++buffersLive;
    bufferBytesLive += bytes;
}

void BufferTally::release() {
    if (!live_) return;
    --buffersLive;
    bufferBytesLive -= bytes_;
    live_ = false;
    bytes_ = 0;
}

}  // namespace penumbra::gpu
