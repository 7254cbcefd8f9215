// Uninitialised scratch arrays for large one-off jobs (a BVH build over millions of
// primitives), backed by transparent huge pages where the system offers them: fresh memory is
// paid for in page faults, and one 2 MiB fault costs about what one 4 KiB fault does.
#pragma once

#include <cstddef>
#include <type_traits>
#include <vector>

namespace penumbra {

// Asks the kernel to back [data, data + bytes) with huge pages where it can (Linux
// MADV_HUGEPAGE on the whole 2 MiB pages inside the range); a no-op elsewhere or on failure.
// Call it before the memory is first touched.
void adviseHugePages(void* data, std::size_t bytes);

// A vector of n copies of `value` whose storage is advised for huge pages before it is first
// touched (loaders and builders filling millions of elements).
template <typename T>
std::vector<T> hugeVector(std::size_t n, const T& value = T()) {
    std::vector<T> v;
    v.reserve(n);
    adviseHugePages(v.data(), n * sizeof(T));
    v.resize(n, value);
    return v;
}

// Reserves room for n elements in an empty vector, advised for huge pages.
template <typename T>
void reserveHuge(std::vector<T>& v, std::size_t n) {
    v.reserve(n);
    adviseHugePages(v.data(), n * sizeof(T));
}

// `count` uninitialised elements of a trivially copyable T; move-only.
template <typename T>
class BigBuffer {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

public:
    BigBuffer() = default;
    explicit BigBuffer(std::size_t count);
    ~BigBuffer() { release(); }
    BigBuffer(BigBuffer&& other) noexcept : data_(other.data_), count_(other.count_) {
        other.data_ = nullptr;
    }
    BigBuffer& operator=(BigBuffer&& other) noexcept {
        if (this != &other) {
            release();
            data_ = other.data_;
            count_ = other.count_;
            other.data_ = nullptr;
        }
        return *this;
    }
    BigBuffer(const BigBuffer&) = delete;
    BigBuffer& operator=(const BigBuffer&) = delete;

    T* data() { return data_; }
    const T* data() const { return data_; }
    std::size_t size() const { return count_; }
    T& operator[](std::size_t i) { return data_[i]; }
    const T& operator[](std::size_t i) const { return data_[i]; }

private:
    void release();

    T* data_ = nullptr;
    std::size_t count_ = 0;
};

// The untyped allocation behind BigBuffer: aligned to 2 MiB when large, else to 64 bytes.
void* bigAllocate(std::size_t bytes);
void bigFree(void* data, std::size_t bytes);

template <typename T>
BigBuffer<T>::BigBuffer(std::size_t count)
    : data_(static_cast<T*>(bigAllocate(count * sizeof(T)))), count_(count) {}

template <typename T>
void BigBuffer<T>::release() {
    if (data_) bigFree(data_, count_ * sizeof(T));
    data_ = nullptr;
}

}  // namespace penumbra
