#include "render/light_table.h"

#include <numeric>

namespace penumbra {

std::vector<shader::LightAlias> buildAliasTable(std::span<const std::uint32_t> triangles,
                                                std::span<const double> weights) {
    std::vector<std::uint32_t> tri;
    std::vector<double> w;
    for (std::size_t i = 0; i < triangles.size(); ++i)
        if (weights[i] > 0) {
            tri.push_back(triangles[i]);
            w.push_back(weights[i]);
        }
    const std::size_t n = tri.size();
    std::vector<shader::LightAlias> table(n);
    if (n == 0) return table;
    const double total = std::accumulate(w.begin(), w.end(), 0.0);

    // Scaled probabilities: entries below 1 are "small" and get topped up by a "large" one.
    std::vector<double> scaled(n);
    std::vector<std::uint32_t> small, large;
    for (std::size_t i = 0; i < n; ++i) {
        scaled[i] = w[i] / total * double(n);
        (scaled[i] < 1.0 ? small : large).push_back(static_cast<std::uint32_t>(i));
        table[i] = {tri[i], 1.0f, static_cast<std::uint32_t>(i), float(w[i] / total)};
    }
    while (!small.empty() && !large.empty()) {
        std::uint32_t s = small.back(), l = large.back();
        small.pop_back();
        table[s].threshold = float(scaled[s]);
        table[s].alias = l;
        scaled[l] -= 1.0 - scaled[s];
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // Whatever is left is 1 up to rounding: keep it whole.
    for (std::uint32_t i : small) table[i].threshold = 1.0f;
    for (std::uint32_t i : large) table[i].threshold = 1.0f;
    return table;
}

}  // namespace penumbra
