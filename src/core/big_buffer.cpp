#include "core/big_buffer.h"

#include <cstdint>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace penumbra {
namespace {

constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kCacheLine = 64;

std::size_t alignmentFor(std::size_t bytes) {
    return bytes >= 4 * kHugePage ? kHugePage : kCacheLine;
}

std::size_t roundUp(std::size_t n, std::size_t a) { return (n + a - 1) / a * a; }

}  // namespace

void adviseHugePages(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const auto begin = roundUp(reinterpret_cast<std::uintptr_t>(data), kHugePage);
    const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) / kHugePage * kHugePage;
    if (end > begin)
        madvise(reinterpret_cast<void*>(begin), end - begin,
                MADV_HUGEPAGE);  // a hint: failure is fine
#else
    (void)data;
    (void)bytes;
#endif
}

void* bigAllocate(std::size_t bytes) {
    if (bytes == 0) return nullptr;
    const std::size_t align = alignmentFor(bytes);
    void* data = std::aligned_alloc(align, roundUp(bytes, align));
    if (!data) throw std::bad_alloc();
    if (align == kHugePage) adviseHugePages(data, roundUp(bytes, align));
    return data;
}

void bigFree(void* data, std::size_t) { std::free(data); }

}  // namespace penumbra
