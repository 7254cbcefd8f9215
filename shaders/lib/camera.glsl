// Pinhole camera rays from the frame uniforms. Row 0 is the top of the image.
#ifndef PN_CAMERA_GLSL
#define PN_CAMERA_GLSL

vec3 cameraRayDirection(vec2 pixelPosition) {
    vec2 ndc = vec2(2.0 * pixelPosition.x / float(frame.width) - 1.0,
                    1.0 - 2.0 * pixelPosition.y / float(frame.height));
    vec2 plane = ndc * vec2(frame.aspect * frame.tanHalfFovY, frame.tanHalfFovY);
    return normalize(frame.cameraForward + plane.x * frame.cameraRight + plane.y * frame.cameraUp);
}

#endif
