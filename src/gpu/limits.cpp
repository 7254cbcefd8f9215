#include "gpu/limits.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "core/environment.h"
#include "core/error.h"

namespace penumbra::gpu {
namespace {

// A positive number of bytes from the environment, at most `fallback` (a test may only lower a limit).
std::uint64_t lowered(const char* variable, std::uint64_t fallback) {
    return std::min(environmentSetting(variable, fallback, 1, UINT64_MAX), fallback);
}

}  // namespace

MemoryLimits memoryLimits(const Context& ctx) {
    MemoryLimits limits;
    limits.maxStorageBufferRange = lowered("PENUMBRA_TEST_MAX_STORAGE_BUFFER", ctx.info().limits.maxStorageBufferRange);
    limits.deviceLocalBytes = lowered("PENUMBRA_TEST_DEVICE_MEMORY", ctx.info().deviceLocalBytes);
    return limits;
}

std::string formatBytes(std::uint64_t bytes) {
    char text[32];
    if (bytes < (1u << 20))
        std::snprintf(text, sizeof text, "%.1f KiB", double(bytes) / 1024.0);
    else if (bytes < (std::uint64_t(1) << 30))
        std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(1u << 20));
    else
        std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(std::uint64_t(1) << 30));
    return text;
}

void checkStorageBufferFits(const Context& ctx, std::uint64_t bytes, const std::string& what, const std::string& fix) {
    const std::uint64_t limit = memoryLimits(ctx).maxStorageBufferRange;
    if (bytes <= limit) return;
    throw Error(what + " of " + formatBytes(bytes) + " is larger than " + ctx.info().name +
                " allows for one storage buffer (maxStorageBufferRange " + formatBytes(limit) + "): " + fix);
}

}  // namespace penumbra::gpu
