#include "render/light_grid.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "core/parallel.h"
#include "shared/light_importance.h"

namespace penumbra {
namespace {

constexpr std::uint32_t kOne = 1u << PN_LIGHT_GRID_MASS_BITS;  // a whole alias slot
// Normals whose largest component is along one axis lie within acos(1/sqrt(3)) (54.7 degrees) of
// it; the bins' cones are a little wider, so rounding never leaves a normal out.
constexpr float kBinCos = 0.577f;

struct Cluster {
    std::uint32_t record;  // the node's own record (its bounds)
    std::uint32_t word;    // its childOrLight: where the walk goes on below it
    std::uint32_t level;
    std::uint32_t prefix;  // its trail's first `level` bits
};

// The tree's nodes on level `levels`, and its leaves above it, left to right.
std::vector<Cluster> clustersOf(std::span<const shader::LightTreeNode> tree, std::uint32_t levels) {
    std::vector<Cluster> out;
    std::vector<Cluster> stack{{0, tree[0].childOrLight, 0, 0}};
    while (!stack.empty()) {
        const Cluster c = stack.back();
        stack.pop_back();
        if ((c.word & PN_LIGHT_NODE_LEAF) != 0 || c.level == levels) {
            out.push_back(c);
            continue;
        }
        const std::uint32_t first = c.word & PN_LIGHT_NODE_INDEX;
        PN_CHECK(first + 1 < tree.size());
        stack.push_back({first + 1, tree[first + 1].childOrLight, c.level + 1, c.prefix | (1u << c.level)});
        stack.push_back({first, tree[first].childOrLight, c.level + 1, c.prefix});
    }
    return out;
}

// Whether the walk goes on below some cluster: otherwise it weighs every light already.
bool deeperThanTheLevels(const std::vector<Cluster>& clusters) {
    for (const Cluster& c : clusters)
        if ((c.word & PN_LIGHT_NODE_LEAF) == 0) return true;
    return false;
}

shader::LightCluster widenedCluster(const shader::LightTreeNode& n, float extraRadius) {
    return shader::LightCluster{n.center,    n.radius + extraRadius, n.axis,      n.phi,
                                n.cosThetaO, n.sinThetaO,            n.cosThetaE, (n.childOrLight & PN_LIGHT_NODE_TWO_SIDED) != 0};
}

struct GridShape {
    Vec3 origin;
    float cellSize = 0;
    std::uint32_t dims[3] = {1, 1, 1};
    std::uint64_t cells() const { return std::uint64_t(dims[0]) * dims[1] * dims[2]; }
};

// Cubic cells, as many as maxCells allows.
GridShape shapeFor(const Aabb& bounds, std::uint64_t maxCells) {
    GridShape g;
    g.origin = bounds.lo;
    const Vec3 e = bounds.extent();
    const float largest = std::max({e.x, e.y, e.z, 1e-6f});
    const float floorSize = largest * 1e-3f;
    const double volume = double(std::max(e.x, floorSize)) * std::max(e.y, floorSize) * std::max(e.z, floorSize);
    float size = float(std::cbrt(volume / double(std::max<std::uint64_t>(maxCells, 1))));
    size = std::max(size, floorSize);
    for (int attempt = 0; attempt < 1000; ++attempt) {
        for (int k = 0; k < 3; ++k) g.dims[k] = std::max(1u, std::uint32_t(std::ceil(e[k] / size)));
        if (g.cells() <= std::max<std::uint64_t>(maxCells, 1)) break;
        size *= 1.05f;
    }
    g.cellSize = size;
    return g;
}

}  // namespace

std::vector<std::uint32_t> lightGridAliasTable(std::span<const double> weights) {
    const std::uint32_t count = std::uint32_t(weights.size());
    std::vector<std::uint32_t> table(2 * std::size_t(count), 0u);
    double total = 0;
    for (double w : weights) total += w > 0 ? w : 0;
    if (count == 0 || !(total > 0) || !std::isfinite(total)) return table;
    // Integer masses summing to kOne x count, every positive weight at least 1.
    const std::int64_t whole = std::int64_t(kOne) * count;
    std::vector<std::int64_t> mass(count);
    std::int64_t sum = 0;
    std::uint32_t largest = 0;
    for (std::uint32_t k = 0; k < count; ++k) {
        const double w = weights[k] > 0 ? weights[k] : 0;
        mass[k] = std::int64_t(std::floor(w / total * double(whole)));
        if (w > 0) mass[k] = std::max<std::int64_t>(mass[k], 1);
        sum += mass[k];
        if (mass[k] > mass[largest]) largest = k;
    }
    mass[largest] += whole - sum;  // rounding: at most `count` either way, against at least kOne
    PN_CHECK(mass[largest] > 0);
    // Vose's alias method on integers: every slot ends exactly full.
    std::vector<std::int64_t> left = mass;
    std::vector<std::uint32_t> small, large;
    for (std::uint32_t k = 0; k < count; ++k) (left[k] < kOne ? small : large).push_back(k);
    std::vector<std::uint32_t> threshold(count, kOne), alias(count);
    for (std::uint32_t k = 0; k < count; ++k) alias[k] = k;
    while (!small.empty() && !large.empty()) {
        const std::uint32_t s = small.back(), l = large.back();
        small.pop_back();
        threshold[s] = std::uint32_t(left[s]);
        alias[s] = l;
        left[l] -= kOne - left[s];
        if (left[l] < kOne) {
            large.pop_back();
            small.push_back(l);
        }
    }
    PN_CHECK(small.empty());  // exact integers: what is left is exactly full
    for (std::uint32_t k = 0; k < count; ++k) {
        table[2 * k] = threshold[k] | (alias[k] << PN_LIGHT_GRID_ALIAS_SHIFT);
        table[2 * k + 1] = std::uint32_t(mass[k]);
    }
    return table;
}

double lightGridRealisedProbability(std::span<const std::uint32_t> table, std::uint32_t k) {
    const std::uint32_t count = std::uint32_t(table.size() / 2);
    std::uint64_t mass = table[2 * k] & PN_LIGHT_GRID_THRESHOLD_MASK;
    for (std::uint32_t j = 0; j < count; ++j)
        if (j != k && (table[2 * j] >> PN_LIGHT_GRID_ALIAS_SHIFT) == k) mass += kOne - (table[2 * j] & PN_LIGHT_GRID_THRESHOLD_MASK);
    return double(mass) / (double(kOne) * count);
}

std::uint32_t lightGridTableAt(std::span<const std::uint32_t> grid, Vec3 p, Vec3 n) {
    if (grid.size() <= PN_LIGHT_GRID_PREFIXES) return PN_NO_HIT;
    const shader::LightGridHeader h = lightGridHeader(grid);
    const std::uint32_t table = shader::lightGridTableIndex((p - h.origin) * h.inverseCellSize, h.cellsX, h.cellsY, h.cellsZ, n);
    return table == PN_NO_HIT ? PN_NO_HIT : h.firstTable + table * 2 * h.clusterCount;
}

shader::LightGridHeader lightGridHeader(std::span<const std::uint32_t> grid) {
    if (grid.size() < PN_LIGHT_GRID_PREFIXES) throw Error("light grid: " + std::to_string(grid.size()) + " words hold no header");
    shader::LightGridHeader header{};
    std::memcpy(static_cast<void*>(&header), grid.data(), sizeof(header));  // plain words (its vec3 has initialisers)
    return header;
}

namespace {

// Below a cluster the walk would choose by power alone; the same choice in one draw: an alias
// table per cluster over its lights (in the order a depth-first walk meets them) and, per light,
// its mass there, which MIS reads back. A cluster that is a leaf, or too large for an alias index,
// keeps the walk (count 0).
struct ClusterPicks {
    std::vector<std::uint32_t> entries;  // per light: (threshold | alias << PN_LIGHT_GRID_ALIAS_SHIFT, LightRef)
    std::vector<std::uint32_t> masses;   // per LightRef: its mass in its cluster's table
    std::vector<std::uint32_t> first, count;  // per cluster: its first entry, its lights
};

ClusterPicks clusterPicks(std::span<const shader::LightTreeNode> tree, const std::vector<Cluster>& clusters, bool draw) {
    ClusterPicks out;
    for (const Cluster& c : clusters) {
        std::vector<std::uint32_t> refs;
        std::vector<double> power;
        std::vector<std::uint32_t> stack{c.record};
        while (!stack.empty() && (c.word & PN_LIGHT_NODE_LEAF) == 0) {
            const shader::LightTreeNode& n = tree[stack.back()];
            stack.pop_back();
            if (n.childOrLight & PN_LIGHT_NODE_LEAF) {
                refs.push_back(n.childOrLight & PN_LIGHT_NODE_INDEX);
                power.push_back(n.phi);
                continue;
            }
            stack.push_back((n.childOrLight & PN_LIGHT_NODE_INDEX) + 1);
            stack.push_back(n.childOrLight & PN_LIGHT_NODE_INDEX);
        }
        const bool aliased = draw && refs.size() > 1 && refs.size() < (1u << 15);
        out.first.push_back(std::uint32_t(out.entries.size() / 2));
        out.count.push_back(aliased ? std::uint32_t(refs.size()) : 0u);
        if (!aliased) continue;
        const std::vector<std::uint32_t> table = lightGridAliasTable(power);
        for (std::size_t j = 0; j < refs.size(); ++j) {
            out.entries.push_back(table[2 * j]);
            out.entries.push_back(refs[j]);
            if (refs[j] >= out.masses.size()) out.masses.resize(refs[j] + 1, 0u);
            out.masses[refs[j]] = table[2 * j + 1];
        }
    }
    return out;
}

// The header, the prefix map and the clusters' words (node word, level, first entry, count).
struct GridLayout {
    std::uint32_t firstEntry, firstMass, firstTree, firstTable;
};

void writeHeader(std::vector<std::uint32_t>& words, const GridShape& g, const std::vector<Cluster>& clusters,
                 std::uint32_t levels, const ClusterPicks& picks, const GridLayout& at) {
    shader::LightGridHeader header{};
    header.origin = g.origin;
    header.inverseCellSize = 1.0f / g.cellSize;
    header.cellsX = g.dims[0];
    header.cellsY = g.dims[1];
    header.cellsZ = g.dims[2];
    header.clusterCount = std::uint32_t(clusters.size());
    header.levels = levels;
    header.firstTable = at.firstTable;
    header.firstMass = at.firstMass;
    header.firstTree = at.firstTree;
    std::memcpy(words.data(), &header, sizeof(header));
    const std::uint32_t clusterWords = PN_LIGHT_GRID_PREFIXES + (1u << levels);
    for (std::uint32_t i = 0; i < clusters.size(); ++i) {
        const Cluster& c = clusters[i];
        for (std::uint32_t rest = 0; rest < (1u << (levels - c.level)); ++rest)
            words[PN_LIGHT_GRID_PREFIXES + (c.prefix | (rest << c.level))] = i;
        std::uint32_t* w = &words[clusterWords + PN_LIGHT_GRID_CLUSTER_WORDS * i];
        w[0] = c.word;
        w[1] = c.level;
        w[2] = at.firstEntry + 2 * picks.first[i];
        w[3] = picks.count[i];
    }
    std::copy(picks.entries.begin(), picks.entries.end(), words.begin() + at.firstEntry);
    std::copy(picks.masses.begin(), picks.masses.end(), words.begin() + at.firstMass);
}

// Every cell's table for every bin: each cluster weighed by its bound widened to the cell and bin;
// and the tree's root weighed the same way.
void fillCellTables(std::vector<std::uint32_t>& words, const GridShape& g, std::span<const shader::LightTreeNode> tree,
                    const std::vector<Cluster>& clusters, const GridLayout& layout) {
    const auto count = std::uint32_t(clusters.size());
    // Every point the shaders file under a cell lies within its circumscribed sphere, widened for
    // the rounding of (p - origin) / size.
    const float reach = std::max({std::abs(g.origin.x), std::abs(g.origin.y), std::abs(g.origin.z)}) +
                        g.cellSize * float(std::max({g.dims[0], g.dims[1], g.dims[2]}));
    const float cellRadius = 0.5f * g.cellSize * std::sqrt(3.0f) * 1.001f + reach * 1e-5f;
    const float binSin = std::sqrt(1.0f - kBinCos * kBinCos);
    // The clusters (and the root) grown by a cell's radius: the same for every cell.
    std::vector<shader::LightCluster> widened(count);
    for (std::uint32_t i = 0; i < count; ++i) widened[i] = widenedCluster(tree[clusters[i].record], cellRadius);
    const shader::LightCluster widenedRoot = widenedCluster(tree[0], cellRadius);
    parallelFor(g.cells(), 64, [&](std::size_t begin, std::size_t end) {
        std::vector<double> weights(count);
        for (std::size_t cell = begin; cell < end; ++cell) {
            const std::uint32_t q[3] = {std::uint32_t(cell % g.dims[0]), std::uint32_t(cell / g.dims[0] % g.dims[1]),
                                        std::uint32_t(cell / g.dims[0] / g.dims[1])};
            Vec3 centre;
            for (int k = 0; k < 3; ++k) centre[k] = g.origin[k] + (float(q[k]) + 0.5f) * g.cellSize;
            for (std::uint32_t bin = 0; bin < PN_LIGHT_GRID_BINS; ++bin) {
                Vec3 axis{0.0f};
                axis[int(bin / 2)] = bin % 2 == 0 ? 1.0f : -1.0f;
                for (std::uint32_t i = 0; i < count; ++i)
                    weights[i] = shader::clusterImportanceWithin(widened[i], centre, axis, true, binSin, kBinCos);
                const std::vector<std::uint32_t> table = lightGridAliasTable(weights);
                const std::size_t index = cell * PN_LIGHT_GRID_BINS + bin;
                std::copy(table.begin(), table.end(), words.begin() + std::ptrdiff_t(layout.firstTable + index * 2 * count));
                const float root = shader::clusterImportanceWithin(widenedRoot, centre, axis, true, binSin, kBinCos);
                std::memcpy(&words[layout.firstTree + index], &root, 4);
            }
        }
    });
}

}  // namespace

std::vector<std::uint32_t> buildLightGrid(std::span<const shader::LightTreeNode> tree, const Aabb& bounds,
                                          const LightGridOptions& options) {
    if (tree.empty() || bounds.empty()) return {};
    // A scene spanning more than a float can hold (its extent overflows) keeps the walk.
    const Vec3 extent = bounds.extent();
    if (!std::isfinite(extent.x) || !std::isfinite(extent.y) || !std::isfinite(extent.z)) return {};
    const std::uint32_t levels = std::clamp(options.levels, 1u, PN_LIGHT_GRID_MAX_LEVELS);
    const std::vector<Cluster> clusters = clustersOf(tree, levels);
    if (!deeperThanTheLevels(clusters)) return {};
    const auto count = std::uint32_t(clusters.size());
    PN_CHECK(count <= (1u << levels));
    const ClusterPicks picks = clusterPicks(tree, clusters, options.drawInClusters);
    GridLayout at{};
    at.firstEntry = PN_LIGHT_GRID_PREFIXES + (1u << levels) + PN_LIGHT_GRID_CLUSTER_WORDS * count;
    at.firstMass = std::uint32_t(at.firstEntry + picks.entries.size());
    at.firstTree = std::uint32_t(at.firstMass + picks.masses.size());
    const std::uint64_t cellWords = std::uint64_t(PN_LIGHT_GRID_BINS) * (count * 2 + 1);  // tables and tree weights
    const std::uint64_t budget = options.maxWords > at.firstTree ? options.maxWords - at.firstTree : 0;
    const GridShape g = shapeFor(bounds, budget / cellWords);
    at.firstTable = std::uint32_t(at.firstTree + g.cells() * PN_LIGHT_GRID_BINS);
    std::vector<std::uint32_t> words(at.firstTree + g.cells() * cellWords, 0u);
    writeHeader(words, g, clusters, levels, picks, at);
    fillCellTables(words, g, tree, clusters, at);
    return words;
}

}  // namespace penumbra
