// Minimal fork-join parallelism over index ranges, using every hardware thread.
#pragma once

#include <cstddef>
#include <functional>

namespace penumbra {

unsigned hardwareThreads();

// Calls body(begin, end) on disjoint chunks covering [0, count), on up to hardwareThreads()
// threads; returns when all are done. Exceptions from a chunk are rethrown on the caller.
void parallelFor(std::size_t count, std::size_t minChunk,
                 const std::function<void(std::size_t, std::size_t)>& body);

}  // namespace penumbra
