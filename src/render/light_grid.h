// The light grid: a pick among the light tree's top clusters read from a table instead of weighed
// at every shading point. The tree walk (lib/light_sampler.glsl) spends most of a pick on the
// importance bounds of its first PN_LIGHT_TREE_IMPORTANCE_LEVELS levels, two per level; here each
// cell of a grid over the scene, for each bin of shading normals, holds an alias table over the
// nodes of that level (the clusters), each weighed by the same bound widened to the whole cell
// and bin (shared/light_importance.h). The bound is widened, not sampled, so a cluster that could
// light any point of the cell keeps a non-zero probability and the estimator stays unbiased; the
// walk goes on below the cluster by power, as before. Masses are integers, so the probability the
// table realises is exactly the one the shaders read back for MIS. Layout: shared/lights.h,
// LightGridHeader and PN_LIGHT_GRID_*.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/aabb.h"
#include "shared/geometry.h"  // PN_NO_HIT
#include "shared/lights.h"

namespace penumbra {

struct LightGridOptions {
    // The tree level whose nodes the tables pick among (2^levels clusters at most); the walk goes
    // on below by power. Five is the walk's own importance levels (PN_LIGHT_TREE_IMPORTANCE_LEVELS).
    std::uint32_t levels = PN_LIGHT_TREE_IMPORTANCE_LEVELS;
    // The tables' size is capped at this many words (alias entries are two words each), which
    // sets the cell size: cubic cells, as many as fit.
    std::uint64_t maxWords = std::uint64_t(1) << 21;
    // Below a cluster, one draw from its own alias table; false: the walk chooses level by level
    // (the same distribution; for measurements).
    bool drawInClusters = true;
};

// The grid's words over `bounds` (where shading points lie: the scene's geometry) for a compact
// light tree (compactLightTree), or nothing where a grid would not help: no tree, a tree no
// deeper than options.levels (the walk weighs every light there), or empty or unbounded bounds.
std::vector<std::uint32_t> buildLightGrid(std::span<const shader::LightTreeNode> tree, const Aabb& bounds,
                                          const LightGridOptions& options = {});

// The first word of the table the shaders read for a point p with shading normal n (as
// lib/light_sampler.glsl lightGridTable does), or PN_NO_HIT off the grid.
std::uint32_t lightGridTableAt(std::span<const std::uint32_t> grid, Vec3 p, Vec3 n);

// The header at the start of a grid's words (a grid of fewer words than a header: Error).
shader::LightGridHeader lightGridHeader(std::span<const std::uint32_t> grid);

// One table's alias entries for non-negative weights (its masses sum to 2^PN_LIGHT_GRID_MASS_BITS
// times the count; a positive weight gets a positive mass; all zero: every mass zero).
// Two words per entry, as in the grid.
std::vector<std::uint32_t> lightGridAliasTable(std::span<const double> weights);

// The probability an alias table realises for entry k, exactly as the shaders draw it: the
// threshold of k plus what the other entries hand to k, over 2^PN_LIGHT_GRID_MASS_BITS x count.
double lightGridRealisedProbability(std::span<const std::uint32_t> table, std::uint32_t k);

}  // namespace penumbra
