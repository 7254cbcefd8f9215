#include "render/passes/trace_tiles.h"

#include <algorithm>

#include "shared/types.h"

namespace penumbra {

std::vector<TraceTile> traceTiles(std::uint32_t width, std::uint32_t height, std::uint32_t samplesPerPass,
                                  std::uint64_t pathBudget) {
    const std::uint64_t spp = std::max<std::uint32_t>(samplesPerPass, 1);
    const std::uint64_t budgetPixels = std::max<std::uint64_t>(pathBudget / spp, 1);
    const std::uint32_t groupX = PN_TRACE_GROUP_X, groupY = PN_TRACE_GROUP_Y;
    std::uint32_t tileW = width, tileH = height;
    if (std::uint64_t(width) * groupY > budgetPixels) {
        // Even one band of a workgroup's height is too much: narrower tiles, one band high.
        tileH = groupY;
        tileW = std::uint32_t(std::max<std::uint64_t>(budgetPixels / groupY / groupX, 1) * groupX);
    } else {
        tileH = std::uint32_t(std::max<std::uint64_t>(budgetPixels / width / groupY, 1) * groupY);
    }
    std::vector<TraceTile> tiles;
    for (std::uint32_t y = 0; y < height; y += tileH)
        for (std::uint32_t x = 0; x < width; x += tileW)
            tiles.push_back({x, y, std::min(tileW, width - x), std::min(tileH, height - y)});
    return tiles;
}

TraceTile clipTile(const TraceTile& tile, std::uint32_t width, std::uint32_t height) {
    return {tile.x, tile.y, std::min(tile.width, width - tile.x), std::min(tile.height, height - tile.y)};
}

std::uint64_t defaultPathBudget(VkPhysicalDeviceType type) {
    // lavapipe on the 2-core CI machine: see docs/RELIABILITY.md for the measured figure.
    if (type == VK_PHYSICAL_DEVICE_TYPE_CPU) return std::uint64_t(1) << 14;
    return std::uint64_t(1) << 22;  // 4 Mi paths: 1080p at 2 samples per pass in one dispatch
}

}  // namespace penumbra
