// The alias table that lets shaders pick an emissive triangle in proportion to its power in
// O(1) (Vose's method).
#pragma once

#include <span>
#include <vector>

#include "shared/types.h"

namespace penumbra {

// weights[i] >= 0 is the sampling weight of triangles[i]. Entries with weight 0 are left out.
// The pmfs of the result sum to 1 (empty result when every weight is 0).
std::vector<shader::LightAlias> buildAliasTable(std::span<const std::uint32_t> triangles,
                                                std::span<const double> weights);

}  // namespace penumbra
