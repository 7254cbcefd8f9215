// Two of the WebGPU renderer's view settings, as formulas the host and the shaders share (valid
// GLSL and C++): the render distance, beyond which geometry is not drawn, and the saturation of
// textures.
#ifndef PENUMBRA_SHADER_VIEW_LIMITS_H
#define PENUMBRA_SHADER_VIEW_LIMITS_H

#ifdef __cplusplus
#include <cmath>
namespace penumbra::shader {
#define PN_INLINE inline
using std::sqrt;
using std::max;
#else
#define PN_INLINE
#endif

#define PN_RENDER_DISTANCE_UNLIMITED 3.0e38

// Render distance: the WebGPU renderer leaves out geometry farther from the player, measured
// horizontally, than the distance; here every ray ends where it leaves the vertical cylinder of
// that radius around the camera, so nothing beyond it is hit (it shows the background) or casts
// a shadow. Returns the ray parameter of that exit for the ray o + t d, with (px, pz) = o - camera
// across the floor: PN_RENDER_DISTANCE_UNLIMITED for distance 0 (off) or a vertical ray, 0 for a
// ray that stays outside.
PN_INLINE float renderDistanceExit(float px, float pz, float dx, float dz, float distance) {
    float a = dx * dx + dz * dz;
    if (!(distance > 0.0f) || !(a > 0.0f)) return PN_RENDER_DISTANCE_UNLIMITED;
    float b = px * dx + pz * dz;
    float c = px * px + pz * pz - distance * distance;
    float disc = b * b - a * c;
    if (disc < 0.0f) return 0.0f;
    return max(0.0f, (sqrt(disc) - b) / a);
}

// Texture saturation: 1 keeps a texel's colour, 0 makes it grey, above 1 strengthens it (the
// WebGPU renderer boosts its textures by 1.4). Moves a channel away from the texel's luminance
// `lum`, kept within [0, 1] so an albedo never reflects more than it receives.
PN_INLINE float saturateChannel(float c, float lum, float saturation) {
    float x = lum + (c - lum) * saturation;
    return x < 0.0f ? 0.0f : (x > 1.0f ? 1.0f : x);
}

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
