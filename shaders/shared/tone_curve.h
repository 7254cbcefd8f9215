// The display's tone curves, written once for the CPU tone mapper (src/image/tonemap.cpp) and the
// viewer's shaders (lib/display.glsl). Valid GLSL and C++. Both send negatives and NaN to 0 (the
// comparison fails) and +inf to 1 (rather than inf / inf = NaN).
#ifndef PENUMBRA_SHADER_TONE_CURVE_H
#define PENUMBRA_SHADER_TONE_CURVE_H

#include "shared/inline.h"

#ifdef __cplusplus
#include <cmath>
namespace penumbra::shader {
using std::isinf;
#endif

// Reinhard per channel, x / (1 + x).
PN_INLINE float reinhard(float x) {
    if (!(x > 0.0f)) return 0.0f;
    if (isinf(x)) return 1.0f;
    return x / (1.0f + x);
}

// Narkowicz's fit of the ACES reference rendering and output transforms, clamped to [0, 1].
PN_INLINE float acesFilmic(float x) {
    if (!(x > 0.0f)) return 0.0f;
    if (isinf(x)) return 1.0f;
    float y = x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f);
    return y < 1.0f ? y : 1.0f;
}

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
