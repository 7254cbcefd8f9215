// The camera ray's direction through a pixel, which the host (picking) and the shaders (tracing,
// reprojection) both need, written once. Valid GLSL and C++; include after shared/types.h.
#ifndef PENUMBRA_SHADER_CAMERA_H
#define PENUMBRA_SHADER_CAMERA_H

#ifdef __cplusplus
namespace penumbra::shader {
#endif
#include "shared/inline.h"

// The unit direction of the pinhole ray through a continuous pixel position (pixels, row 0 at
// the top of the image, (0.5, 0.5) the centre of the first pixel).
PN_INLINE vec3 cameraRayDirection(FrameUniforms f, vec2 pixelPosition) {
    float ndcX = 2.0f * pixelPosition.x / float(f.width) - 1.0f;
    float ndcY = 1.0f - 2.0f * pixelPosition.y / float(f.height);
    return normalize(f.cameraForward + f.cameraRight * (ndcX * f.aspect * f.tanHalfFovY) +
                     f.cameraUp * (ndcY * f.tanHalfFovY));
}

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
