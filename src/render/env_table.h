// The environment map as the GPU samples it: radiance per texel and an alias table that picks a
// texel in proportion to luminance x solid angle, in O(1) (Vose's method). A direction is then
// drawn uniformly over the texel's solid angle, so the solid-angle pdf is constant per texel:
// pdf = pmf / solid angle = luminance / sum(luminance x solid angle).
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec.h"
#include "scene/scene.h"
#include "shared/types.h"

namespace penumbra {

struct EnvTable {
    std::uint32_t width = 0, height = 0;  // 0 x 0: no map
    std::vector<Vec4> radiance;           // rgb per texel (row-major, top row = +y), a unused
    std::vector<shader::EnvAlias> alias;  // one entry per texel
};

// Solid angle of one texel in row y of a width x height equirectangular map.
double envTexelSolidAngle(std::uint32_t y, std::uint32_t width, std::uint32_t height);

// O(texels). A black map gets pdfs proportional to solid angle (uniform over the sphere), so
// sampling it stays valid, merely useless.
EnvTable buildEnvTable(const EnvironmentMap& map);

}  // namespace penumbra
