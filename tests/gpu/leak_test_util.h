// Shared by the leak tests: settings from the environment, a progress line, and the check that
// what a process holds did not grow between two samples.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "gpu/tally.h"
#include "process_resources.h"

namespace penumbra::test {

inline int envInt(const char* name, int fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::atoi(v) : fallback;
}

// One line of the leak tests' log; every line starts with "[leak]" for scripts/gpu-tests.sh.
inline void leakLog(const std::string& line) {
    std::printf("[leak] %s\n", line.c_str());
    std::fflush(stdout);
}

inline std::string describe(const gpu::VulkanTally& t) {
    return "instances live " + std::to_string(t.instancesLive()) + " (created " + std::to_string(t.instancesCreated) +
           "), devices live " + std::to_string(t.devicesLive()) + " (created " + std::to_string(t.devicesCreated) +
           "), buffers live " + std::to_string(t.buffersLive) + " (" + std::to_string(t.bufferBytesLive) +
           " bytes), device objects live " + std::to_string(t.deviceObjectsLive);
}

// Allowed growth between a sample taken after warm-up (caches filled, thread pools started) and
// the last one, `cycles` repetitions later. Each bound is far below what one object leaked per
// cycle adds up to (`cycles` is 80 or more), and above the noise seen on lavapipe.
struct LeakSlack {
    long fds = 2, threads = 2, mappings = 24;
    long rssKiB = 16 * 1024, heapKiB = 4 * 1024;
};

// Live Vulkan objects are counted exactly: equal phases of a repeated cycle must hold equal counts.
inline void expectSameObjects(const gpu::VulkanTally& warm, const gpu::VulkanTally& last, const char* what) {
    EXPECT_EQ(last.devicesLive(), warm.devicesLive()) << "live devices changed over the " << what;
    EXPECT_EQ(last.buffersLive, warm.buffersLive) << "live buffers changed over the " << what;
    EXPECT_EQ(last.bufferBytesLive, warm.bufferBytesLive) << "live buffer bytes changed over the " << what;
    EXPECT_EQ(last.deviceObjectsLive, warm.deviceObjectsLive) << "live device objects changed over the " << what;
}

// AddressSanitizer's allocator keeps freed memory in quarantine and maps more as it goes, so under
// it mappings and memory measure the sanitizer; LeakSanitizer checks memory better then.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitizedAllocator = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitizedAllocator = true;
#else
constexpr bool kSanitizedAllocator = false;
#endif
#else
constexpr bool kSanitizedAllocator = false;
#endif

inline void expectNoGrowth(const ProcessResources& warm, const ProcessResources& last, int cycles, const char* what,
                           const LeakSlack& slack = {}) {
    const std::string over = std::string(" grew over ") + std::to_string(cycles) + " " + what;
    EXPECT_LE(last.fds - warm.fds, slack.fds) << "open file descriptors" << over;
    EXPECT_LE(last.threads - warm.threads, slack.threads) << "threads" << over;
    if (kSanitizedAllocator) return;
    EXPECT_LE(last.mappings - warm.mappings, slack.mappings) << "memory mappings" << over;
    EXPECT_LE(last.rssKiB - warm.rssKiB, slack.rssKiB) << "resident memory (KiB)" << over;
    if (warm.heapKiB >= 0 && last.heapKiB >= 0) {
        EXPECT_LE(last.heapKiB - warm.heapKiB, slack.heapKiB) << "heap in use (KiB)" << over;
    }
}

}  // namespace penumbra::test
