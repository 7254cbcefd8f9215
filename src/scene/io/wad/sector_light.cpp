#include "scene/io/wad/sector_light.h"

#include <algorithm>

#include "shared/color.h"

namespace penumbra::wad {

float doomBrightness(int level) {
    constexpr int kLightLevels = 16, kColormaps = 32;
    const int step = std::clamp(level, 0, 255) >> 4;  // LIGHTSEGSHIFT
    const int startMap = (kLightLevels - 1 - step) * 2 * kColormaps / kLightLevels;
    // At 128 units a wall's projection scale is 160 / 128 * 16 = 20 light-scale steps, and the
    // colormap drops by half of that (DISTMAP = 2); flats give the same at that distance.
    const int colormap = std::clamp(startMap - 10, 0, kColormaps - 1);
    return 1.0f - float(colormap) / float(kColormaps);
}

float sectorRadiance(int level) {
    constexpr float kInverseViewFactor = 2.0f;
    return kInverseViewFactor * shader::srgbToLinear(doomBrightness(level));
}

}  // namespace penumbra::wad
