// What a pixel is worth so far, as the scale of the shadow-ray roulette (lib/path.glsl
// keepShadowRay), from the running moments of its samples: written by the viewer's temporal pass
// from its history, computed by the trace from the sums of a headless render. Include after
// shared/types.h.
#ifndef PN_PIXEL_ESTIMATE_GLSL
#define PN_PIXEL_ESTIMATE_GLSL

#include "shared/color.h"

// The mean colour, shrunk by how uncertain its luminance still is (less two standard errors, in
// proportion), so that a pixel whose few samples hold a firefly is not taken for a bright one: a
// scale too large would send its next light samples through the roulette hard, and the variance
// the roulette adds grows with the square of the scale. meanSquares is the mean of the samples'
// squared luminance. None below PN_PIXEL_ESTIMATE_MIN_SAMPLES samples.
vec3 pixelEstimateFromMoments(vec3 mean, float meanSquares, float samples) {
    float m1 = luminance(mean);
    if (samples < float(PN_PIXEL_ESTIMATE_MIN_SAMPLES) || !(m1 > 0.0)) return vec3(0.0);
    float standardError = sqrt(max(meanSquares - m1 * m1, 0.0) / samples);
    return max(mean, vec3(0.0)) * clamp(1.0 - 2.0 * standardError / m1, 0.0, 1.0);
}

#endif
