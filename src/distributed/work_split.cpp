#include "distributed/work_split.h"

#include <algorithm>

#include "core/error.h"

namespace penumbra::distributed {

PassRange shareOf(PassRange all, int rank, int ranks) {
    PN_CHECK(ranks > 0 && rank >= 0 && rank < ranks);
    const std::uint64_t n = all.count, r = std::uint64_t(rank), k = std::uint64_t(ranks);
    const auto start = [&](std::uint64_t i) { return std::uint32_t(i * n / k); };
    return PassRange{all.first + start(r), start(r + 1) - start(r)};
}

PassRange roundRange(std::uint32_t round, std::uint32_t roundPasses, std::uint32_t totalPasses) {
    PN_CHECK(roundPasses > 0);
    const std::uint64_t first = std::uint64_t(round) * roundPasses;
    if (first >= totalPasses) return PassRange{totalPasses, 0};
    return PassRange{std::uint32_t(first), std::uint32_t(std::min<std::uint64_t>(roundPasses, totalPasses - first))};
}

}  // namespace penumbra::distributed
