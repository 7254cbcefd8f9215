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

ImageRgb displayedImage(const ImageRgb& image, const ToneMapSettings& settings) {
    ImageRgb out = image;
    for (Vec3& p : out.pixels)
        for (int c = 0; c < 3; ++c) p[c] = srgbOetf(toneMapChannel(p[c], settings));
    return out;
}

double displayedPsnr(const ImageRgb& image, const ImageRgb& reference) {
    return -20.0 * std::log10(rmse(displayedImage(image), displayedImage(reference)));
}

double gradientEnergy(const ImageRgb& img) {
    double e = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const double c = luminance(img.at(x, y));
            if (x + 1 < img.width) e += std::pow(luminance(img.at(x + 1, y)) - c, 2);
            if (y + 1 < img.height) e += std::pow(luminance(img.at(x, y + 1)) - c, 2);
        }
    return e;
}

}  // namespace penumbra
