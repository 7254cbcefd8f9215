// What a process holds, read from /proc/self: the quantities a leak makes grow. Linux only.
#pragma once

#include <malloc.h>
#include <sys/resource.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace penumbra::test {

struct ProcessResources {
    long fds = 0;        // entries of /proc/self/fd
    long threads = 0;    // "Threads:" of /proc/self/status
    long mappings = 0;   // lines of /proc/self/maps
    long rssKiB = 0;     // "VmRSS:" of /proc/self/status
    long heapKiB = -1;   // bytes malloc has handed out and not had back (mallinfo2), -1 if unknown
};

inline long statusField(const std::string& name) {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind(name + ":", 0) == 0) return std::stol(line.substr(name.size() + 1));
    return -1;
}

inline ProcessResources sampleProcess() {
    ProcessResources r;
    std::error_code ec;
    for (auto it = std::filesystem::directory_iterator("/proc/self/fd", ec); !ec && it != std::filesystem::directory_iterator();
         it.increment(ec))
        ++r.fds;
    --r.fds;  // the directory iterator's own descriptor
    r.threads = statusField("Threads");
    r.rssKiB = statusField("VmRSS");
    std::ifstream maps("/proc/self/maps");
    std::string line;
    while (std::getline(maps, line)) ++r.mappings;
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
    struct mallinfo2 m = mallinfo2();
    if (m.uordblks > 0) r.heapKiB = long(m.uordblks / 1024);  // sanitizers' allocators report 0
#endif
    return r;
}

inline std::string describe(const ProcessResources& r) {
    char text[160];
    std::snprintf(text, sizeof text, "fds %ld, threads %ld, mappings %ld, rss %.1f MiB, heap ", r.fds, r.threads,
                  r.mappings, double(r.rssKiB) / 1024);
    char heap[32] = "unknown";
    if (r.heapKiB >= 0) std::snprintf(heap, sizeof heap, "%.1f MiB", double(r.heapKiB) / 1024);
    return std::string(text) + heap;
}

inline long openFileLimit() {
    rlimit limit{};
    return getrlimit(RLIMIT_NOFILE, &limit) == 0 ? long(limit.rlim_cur) : -1;
}

}  // namespace penumbra::test
