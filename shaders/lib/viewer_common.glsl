// What the viewer's image passes share: the per-frame and viewer settings, pixel indexing,
// luminance and YCoCg, and projection into the previous frame's camera (the reprojection that a
// previous view-projection matrix would do, written with the camera basis the frame uses).
// Include after shared/types.h. Kernels that trace the scene get `frame` from scene_bindings.glsl
// and define PN_HAVE_FRAME first.
#ifndef PN_VIEWER_COMMON_GLSL
#define PN_VIEWER_COMMON_GLSL

#ifndef PN_HAVE_FRAME
layout(std140, set = 0, binding = PN_BINDING_FRAME) uniform FrameBuffer { FrameUniforms frame; };
#endif
layout(std430, set = 0, binding = PN_BINDING_VIEWER) readonly buffer ViewerBuffer { ViewerUniforms viewer; };

bool insideImage(ivec2 p) { return p.x >= 0 && p.y >= 0 && p.x < int(frame.width) && p.y < int(frame.height); }
ivec2 clampToImage(ivec2 p) { return clamp(p, ivec2(0), ivec2(frame.width, frame.height) - 1); }
uint pixelIndex(ivec2 p) { return uint(p.y) * frame.width + uint(p.x); }

#include "shared/color.h"

vec3 rgbToYCoCg(vec3 c) {
    return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b, -0.25 * c.r + 0.5 * c.g - 0.25 * c.b);
}
vec3 yCoCgToRgb(vec3 y) { return vec3(y.x + y.y - y.z, y.x + y.z, y.x - y.y - y.z); }

// Direction of the ray through a continuous pixel position in the current camera.
#include "shared/camera.h"
vec3 viewDirection(vec2 pixelPosition) { return cameraRayDirection(frame, pixelPosition); }

// Continuous pixel position of camera-space offset d (view z > 0) in the previous camera, or a
// position far outside the image when d is behind it.
vec2 projectDirectionPrev(vec3 d) {
    float z = dot(d, viewer.prevCameraForward);
    if (z <= 1e-6) return vec2(-1e9);
    vec2 ndc = vec2(dot(d, viewer.prevCameraRight) / (z * viewer.prevTanHalfFovY * viewer.prevAspect),
                    dot(d, viewer.prevCameraUp) / (z * viewer.prevTanHalfFovY));
    return vec2((ndc.x + 1.0) * 0.5 * float(frame.width), (1.0 - ndc.y) * 0.5 * float(frame.height));
}
vec2 projectPointPrev(vec3 p) { return projectDirectionPrev(p - viewer.prevCameraPosition); }

// The a-trous passes' guide (PN_DENOISE_GUIDE_BYTES): the normal, zero where nothing was hit, and
// the depth, negated where the pixel bypasses the filter (PN_GBUFFER_UNFILTERED): such a pixel
// is neither filtered nor a tap (both need w > 0), but its |w| still shapes the depth slope of its
// neighbours. A miss has w = 0.
vec4 denoiseGuide(vec3 normal, float depth, bool filtered) {
    return vec4(depth > 0.0 ? normal : vec3(0.0), filtered ? depth : -depth);
}

// The albedo the denoiser divides out: 1 where the primary ray missed or the surface is black.
vec3 demodulationAlbedo(GBufferTexel g) {
    return g.surfaceId == 0u ? vec3(1.0) : max(g.albedo, vec3(1e-3));
}

#endif
