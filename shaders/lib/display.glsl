// What the window shows of linear radiance: the viewer's exposure and tone curve, sRGB encoding,
// packed RGBA8 (r in the low byte). The tonemap pass and the last a-trous pass (which displays
// directly when nothing is drawn over the image) both write pixels with it. Include after
// viewer_common.glsl.
#ifndef PN_DISPLAY_GLSL
#define PN_DISPLAY_GLSL

#include "shared/tone_curve.h"

uint toSrgb8(float linear) {
    float v = linear > 0.0 ? min(linear, 1.0) : 0.0;
    return uint(linearToSrgb(v) * 255.0 + 0.5);
}

// Radiance through exposure and the chosen curve: display-linear, in [0, 1].
vec3 toneMapped(vec3 radiance) {
    vec3 x = radiance * exp2(viewer.exposure);
    return viewer.toneMapper == PN_TONEMAP_ACES ? vec3(acesFilmic(x.r), acesFilmic(x.g), acesFilmic(x.b))
                                                : vec3(reinhard(x.r), reinhard(x.g), reinhard(x.b));
}

uint displayPixel(vec3 displayLinear) {
    return toSrgb8(displayLinear.r) | (toSrgb8(displayLinear.g) << 8) | (toSrgb8(displayLinear.b) << 16) | (255u << 24);
}

#endif
