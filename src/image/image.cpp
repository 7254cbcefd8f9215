#include "image/image.h"

#include <algorithm>

namespace penumbra {

Vec3 ImageRgb::mean() const {
    if (pixels.empty()) return {};
    // Double accumulation: a float sum over millions of pixels loses the low bits that
    // known-answer tests compare.
    double sum[3] = {0, 0, 0};
    for (const Vec3& p : pixels) {
        sum[0] += p.x;
        sum[1] += p.y;
        sum[2] += p.z;
    }
    auto n = static_cast<double>(pixels.size());
    return {static_cast<float>(sum[0] / n), static_cast<float>(sum[1] / n),
            static_cast<float>(sum[2] / n)};
}

bool ImageRgb::hasNonFinite() const {
    return std::any_of(pixels.begin(), pixels.end(), [](Vec3 p) { return !isFinite(p); });
}

}  // namespace penumbra
