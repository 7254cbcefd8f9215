// How one image's samples are split across ranks. The renderer's random numbers depend on the
// pass index (and the seed), so ranks that render disjoint passes draw disjoint random streams,
// and ranks that together render passes 0..P-1 render exactly the single-process image's
// samples: the result differs from one process's only in the order of float additions.
//
// Passes go in rounds (render/progressive.h's roundPasses: the adaptive sampler's decisions are
// made between rounds); each round's passes are shared out in contiguous pieces.
#pragma once

#include <cstdint>

namespace penumbra::distributed {

struct PassRange {
    std::uint32_t first = 0, count = 0;
    std::uint32_t end() const { return first + count; }
};

// Rank `rank` of `ranks`'s piece of `all`: contiguous, disjoint from the other ranks' pieces,
// together exactly `all`, sizes differing by at most one.
PassRange shareOf(PassRange all, int rank, int ranks);

// The passes of round `round` (roundPasses each) of a render of totalPasses passes: empty past the end.
PassRange roundRange(std::uint32_t round, std::uint32_t roundPasses, std::uint32_t totalPasses);

}  // namespace penumbra::distributed
