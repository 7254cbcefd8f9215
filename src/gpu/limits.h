// The device limits Penumbra checks before it allocates: the largest storage buffer a shader may
// bind (maxStorageBufferRange) and the device-local memory. Exceeding either fails late and
// obscurely (a validation error, VK_ERROR_OUT_OF_DEVICE_MEMORY, or a silently clamped binding),
// so callers compare first and refuse with a line that says what to do.
#pragma once

#include <cstdint>
#include <string>

#include "gpu/context.h"

namespace penumbra::gpu {

struct MemoryLimits {
    std::uint64_t maxStorageBufferRange = 0;
    std::uint64_t deviceLocalBytes = 0;  // all device-local heaps together
};

// The device's limits, lowered by PENUMBRA_TEST_MAX_STORAGE_BUFFER and PENUMBRA_TEST_DEVICE_MEMORY
// (bytes) when set: tests pretend to be a small device on lavapipe that way, and a user can check
// that a scene fits a smaller GPU before sending it there. The variables never raise a limit.
MemoryLimits memoryLimits(const Context& ctx);

// "12.5 MiB", "3.0 GiB": sizes in refusals.
std::string formatBytes(std::uint64_t bytes);

// Throws an Error when a storage buffer of `bytes` exceeds maxStorageBufferRange; `what` names it
// ("a storage buffer") and `fix` says what to do.
void checkStorageBufferFits(const Context& ctx, std::uint64_t bytes, const std::string& what, const std::string& fix);

}  // namespace penumbra::gpu
