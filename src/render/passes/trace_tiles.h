// How the trace pass splits a pass into dispatches. A display watchdog (Windows TDR, 2 s; Linux
// drivers' job timeouts) resets a GPU whose dispatch runs too long, and lavapipe cannot be
// interrupted mid-dispatch at all; tiles of at most `pathBudget` paths (pixels x samples per
// pass) keep each dispatch short, around 100 ms or less on the slowest device of each kind.
// Every pixel keeps its own index and random numbers, so tiling never changes the image.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace penumbra {

struct TraceTile {
    std::uint32_t x, y, width, height;  // pixels; x, y and width are whole workgroups
};

// Tiles covering width x height row-major: full-width bands of whole workgroup rows when a
// band of one workgroup row fits the budget, else narrower tiles one workgroup row high; never
// smaller than one workgroup.
std::vector<TraceTile> traceTiles(std::uint32_t width, std::uint32_t height, std::uint32_t samplesPerPass,
                                  std::uint64_t pathBudget);

// The part of `tile` inside width x height: a tile is whole workgroups, so the last ones overhang.
TraceTile clipTile(const TraceTile& tile, std::uint32_t width, std::uint32_t height);

// Paths per dispatch by device: a CPU implementation (lavapipe) traces well under a million paths a
// second on two cores; a GPU, even integrated, far more.
std::uint64_t defaultPathBudget(VkPhysicalDeviceType type);

}  // namespace penumbra
