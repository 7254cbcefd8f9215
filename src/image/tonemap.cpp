#include "image/tonemap.h"

#include <cmath>

#include "shared/color.h"
#include "shared/tone_curve.h"

namespace penumbra {

float reinhard(float x) { return shader::reinhard(x); }

float acesFilmic(float x) { return shader::acesFilmic(x); }

float srgbOetf(float x) { return shader::linearToSrgb(x); }

std::uint8_t toSrgb8(float linear) {
    float v = linear > 0 ? (linear < 1 ? linear : 1) : 0;  // also sends NaN to 0
    return static_cast<std::uint8_t>(std::lround(srgbOetf(v) * 255.0f));
}

float toneMapChannel(float x, const ToneMapSettings& settings) {
    return reinhard(x * std::exp2(settings.exposure));
}

std::vector<std::uint8_t> toneMapToSrgb8(const ImageRgb& image, const ToneMapSettings& settings) {
    std::vector<std::uint8_t> out;
    out.reserve(image.pixels.size() * 3);
    float scale = std::exp2(settings.exposure);
    for (const Vec3& p : image.pixels) {
        for (int c = 0; c < 3; ++c) out.push_back(toSrgb8(reinhard(p[c] * scale)));
    }
    return out;
}

}  // namespace penumbra
