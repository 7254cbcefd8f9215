// Colour formulas the host and the shaders both need, written once. Valid GLSL and C++.
#ifndef PENUMBRA_SHADER_COLOR_H
#define PENUMBRA_SHADER_COLOR_H

#ifdef __cplusplus
#include <cmath>
namespace penumbra::shader {
#define PN_INLINE inline
using std::pow;
#else
#define PN_INLINE
#endif

// The sRGB transfer function's inverse: an encoded channel in [0, 1] to linear light.
PN_INLINE float srgbToLinear(float c) {
    return c <= 0.04045f ? c * (1.0f / 12.92f) : pow((c + 0.055f) * (1.0f / 1.055f), 2.4f);
}

// The sRGB transfer function (IEC 61966-2-1): linear light in [0, 1] to its encoded value; the
// linear toe and the power segment meet at 0.0031308.
PN_INLINE float linearToSrgb(float x) {
    return x <= 0.0031308f ? 12.92f * x : 1.055f * pow(x, 1.0f / 2.4f) - 0.055f;
}

#ifndef __cplusplus
// Rec. 709 luminance (the C++ side's is penumbra::luminance in core/vec.h, with these weights).
float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }
#else
}  // namespace penumbra::shader
#endif
#endif
