// The median of a sample of timings (the mean of the middle two for an even count; 0 when empty):
// benchmarks report it because one slow frame moves a mean far more.
#pragma once

#include <algorithm>
#include <vector>

namespace penumbra {

inline double median(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace penumbra
