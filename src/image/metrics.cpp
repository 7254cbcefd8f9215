#include "image/metrics.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace penumbra {

double meanLuminance(const ImageRgb& image) {
    if (image.pixels.empty()) return 0;
    double sum = 0;
    for (const Vec3& p : image.pixels) sum += luminance(p);
    return sum / static_cast<double>(image.pixels.size());
}

double rmse(const ImageRgb& a, const ImageRgb& b) {
    if (!a.sameSize(b)) {
        throw Error("cannot compare images of different sizes: " + std::to_string(a.width) + "x" +
                    std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                    std::to_string(b.height));
    }
    if (a.pixels.empty()) return 0;
    double sum = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            double d = static_cast<double>(a.pixels[i][c]) - static_cast<double>(b.pixels[i][c]);
            sum += d * d;
        }
    }
    return std::sqrt(sum / (3.0 * static_cast<double>(a.pixels.size())));
}

}  // namespace penumbra
