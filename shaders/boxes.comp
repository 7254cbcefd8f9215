#version 460
// The BVH box overlay: outlines, over the displayed image, the boxes of one depth of the BVH. Each
// pixel projects the twelve edges of every box into the image (clipped to the near side of the
// camera first, so edges that pass behind the eye still draw their visible part) and turns
// yellow when its centre lies within half a line width of one. Cost grows with the box count,
// which the host caps at PN_MAX_OVERLAY_BOXES: it is a teaching view, not a hot path.
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

#include "lib/viewer_common.glsl"

layout(std430, set = 0, binding = PN_BINDING_OVERLAY_BOXES) readonly buffer Boxes { BvhNode boxes[]; };
layout(std430, set = 0, binding = PN_BINDING_DISPLAY) buffer DisplayBuffer { uint display[]; };
layout(push_constant) uniform PushBlock { BoxOverlayPush push; };

const float kNear = 1e-3;  // metres: edges are clipped to this distance in front of the eye

// World point to camera space: x right, y up, z along the view.
vec3 toCamera(vec3 p) {
    vec3 d = p - frame.cameraPosition;
    return vec3(dot(d, frame.cameraRight), dot(d, frame.cameraUp), dot(d, frame.cameraForward));
}

// Camera space (z > 0) to continuous pixel coordinates, row 0 at the top (camera.glsl inverted).
vec2 toPixel(vec3 c) {
    vec2 ndc = vec2(c.x / (c.z * frame.aspect * frame.tanHalfFovY), c.y / (c.z * frame.tanHalfFovY));
    return vec2((ndc.x + 1.0) * 0.5 * float(frame.width), (1.0 - ndc.y) * 0.5 * float(frame.height));
}

// Distance in pixels from q to the projection of the camera-space segment a-b (infinite when
// the segment lies wholly behind the near plane).
float edgeDistance(vec2 q, vec3 a, vec3 b) {
    if (a.z < kNear && b.z < kNear) return 1e30;
    if (a.z < kNear) a = mix(a, b, (kNear - a.z) / (b.z - a.z));
    if (b.z < kNear) b = mix(b, a, (kNear - b.z) / (a.z - b.z));
    vec2 pa = toPixel(a), pb = toPixel(b);
    vec2 ab = pb - pa;
    float len2 = dot(ab, ab);
    float t = len2 > 0.0 ? clamp(dot(q - pa, ab) / len2, 0.0, 1.0) : 0.0;
    return length(q - (pa + t * ab));
}

bool onBoxEdge(vec2 q, vec3 lo, vec3 hi, float halfWidth) {
    vec3 corner[8];
    for (int k = 0; k < 8; ++k)
        corner[k] = toCamera(vec3((k & 1) != 0 ? hi.x : lo.x, (k & 2) != 0 ? hi.y : lo.y, (k & 4) != 0 ? hi.z : lo.z));
    // The twelve edges join corners whose indices differ in one bit.
    for (int k = 0; k < 8; ++k)
        for (int bit = 1; bit < 8; bit <<= 1)
            if ((k & bit) == 0 && edgeDistance(q, corner[k], corner[k | bit]) <= halfWidth) return true;
    return false;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (!insideImage(p)) return;
    vec2 q = vec2(p) + 0.5;
    float halfWidth = 0.5 * push.lineWidth;
    uint count = min(push.boxCount, PN_MAX_OVERLAY_BOXES);
    for (uint i = 0u; i < count; ++i) {
        if (onBoxEdge(q, boxes[i].boundsMin, boxes[i].boundsMax, halfWidth)) {
            display[pixelIndex(p)] = PN_OVERLAY_COLOR;
            return;
        }
    }
}
