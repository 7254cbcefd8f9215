// CPU tone mapping: linear radiance -> display-referred sRGB 8-bit, for PNG output.
//
// Reinhard is applied per channel, x / (1 + x), not on luminance. Per channel never produces a
// value above 1, so bright coloured lights fade to white the way film and most renderers'
// previews do; luminance-based Reinhard keeps the hue but pushes saturated highlights past 1,
// where they clip and shift hue anyway. It is also the simplest thing to match exactly in
// shaders/shared/tone_curve.h, written once for this and the viewer's shaders, so they agree.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"

namespace penumbra {

struct ToneMapSettings {
    float exposure = 0;  // stops: the input is scaled by 2^exposure before the curve
};

float reinhard(float x);     // x / (1 + x) for x >= 0; negatives and NaN -> 0, +inf -> 1
// Narkowicz's fit of the ACES filmic curve (the viewer's second tone mapper, in tonemap.comp):
// x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), clamped to [0, 1]; negatives and NaN -> 0.
float acesFilmic(float x);
float srgbOetf(float x);     // exact piecewise sRGB encoding of a linear value in [0, 1]
std::uint8_t toSrgb8(float linear);  // clamps to [0, 1], encodes, rounds to nearest

// Tone-mapped value of one linear channel after exposure, in [0, 1].
float toneMapChannel(float x, const ToneMapSettings& settings);

// RGB8, row-major, top row first: width * height * 3 bytes. NaN maps to black, +inf to white.
std::vector<std::uint8_t> toneMapToSrgb8(const ImageRgb& image, const ToneMapSettings& settings);

}  // namespace penumbra
