// Camera rays from the frame uniforms: a pinhole, or a thin lens when lensRadius > 0. Row 0 is
// the top of the image.
#ifndef PN_CAMERA_GLSL
#define PN_CAMERA_GLSL

#include "lib/rng.glsl"
#include "lib/sampling.glsl"

#include "shared/camera.h"

vec3 cameraRayDirection(vec2 pixelPosition) { return cameraRayDirection(frame, pixelPosition); }

// Shirley and Chiu's concentric map from the unit square to the unit disk: area preserving, so
// the point is uniform on the disk, and neighbouring samples stay neighbours.
vec2 sampleConcentricDisk(vec2 u) {
    vec2 o = 2.0 * u - 1.0;
    if (o.x == 0.0 && o.y == 0.0) return vec2(0.0);
    float r, theta;
    if (abs(o.x) > abs(o.y)) {
        r = o.x;
        theta = 0.25 * PN_PI * (o.y / o.x);
    } else {
        r = o.y;
        theta = 0.5 * PN_PI - 0.25 * PN_PI * (o.x / o.y);
    }
    return r * vec2(cos(theta), sin(theta));
}

// The camera ray through pixelPosition. With a lens, the ray starts at a uniform point of the
// lens disk and passes through the point the pinhole ray meets on the focal plane (the plane
// focusDistance along cameraForward), so that plane is sharp and the rest is blurred by the
// circle of confusion. A pinhole draws no random numbers, so its images are unchanged.
void cameraRay(vec2 pixelPosition, inout uint rng, out vec3 origin, out vec3 direction) {
    direction = cameraRayDirection(pixelPosition);
    origin = frame.cameraPosition;
    if (frame.lensRadius <= 0.0) return;
    vec3 focus = origin + direction * (frame.focusDistance / dot(direction, frame.cameraForward));
    vec2 lens = frame.lensRadius * sampleConcentricDisk(rngNext2(rng));
    origin += lens.x * frame.cameraRight + lens.y * frame.cameraUp;
    direction = normalize(focus - origin);
}

#endif
