// Where in its pixel a camera ray shared by the samples of a pass goes (PN_TRACE_SHARED_CAMERA):
// pass n takes the n-th point of the R2 sequence (Roberts 2018: n times the inverse powers of the
// plastic number, mod 1), shifted by a rotation drawn once per pixel. Consecutive passes cover the
// pixel evenly, so one position per pass converges over the pixel like many random ones would;
// the rotation makes every pass's position uniform in the pixel, so the mean is unbiased. Valid
// GLSL and C++ (tests check the coverage); include after shared/types.h.
#ifndef PENUMBRA_SHADER_PASS_JITTER_H
#define PENUMBRA_SHADER_PASS_JITTER_H

#ifdef __cplusplus
namespace penumbra::shader {
#endif
#include "shared/inline.h"

// 2^32 / g and 2^32 / g^2, g = 1.3247179572... (the real root of x^3 = x + 1): fixed point, so the
// sequence wraps exactly however many passes there are.
#define PN_R2_STEP_X 3242174889u
#define PN_R2_STEP_Y 2447445414u

// The pass-th position in [0, 1)^2 of a pixel whose rotation is (rotationX, rotationY) / 2^32.
PN_INLINE vec2 passJitter(uint rotationX, uint rotationY, uint pass) {
    uint x = rotationX + pass * PN_R2_STEP_X;
    uint y = rotationY + pass * PN_R2_STEP_Y;
    return vec2(float(x >> 8u) * (1.0f / 16777216.0f), float(y >> 8u) * (1.0f / 16777216.0f));
}

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
