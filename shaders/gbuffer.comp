#version 460
// The G-buffer: what the pixel-centre primary ray hits (normal, linear depth, textured albedo,
// surface id, whether the denoiser leaves it alone) and the motion vector to where that point was
// in the previous frame. A pass of its own, so the path tracer stays untouched and the denoiser's
// guides are noise-free. Final frames
// also trace the 16 cells of a 4x4 grid in each pixel (PN_GBUFFER_SUBPIXEL) to average the albedo
// over the pixel as the path tracer's jittered samples average the radiance.
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

#include "lib/scene_bindings.glsl"
#define PN_HAVE_FRAME
#include "lib/viewer_common.glsl"
#include "lib/offset.glsl"
#include "lib/bvh.glsl"
#include "lib/surface.glsl"
#include "lib/material.glsl"

layout(std430, set = 0, binding = PN_BINDING_GBUFFER) writeonly buffer GBufferOut { GBufferTexel gbuffer[]; };
// The instances as the previous frame placed them (the current ones where nothing moved), so a
// moving object's motion vector points to where its point was.
layout(std430, set = 0, binding = PN_BINDING_INSTANCES_PREV) readonly buffer InstancesPrev { Instance instancesPrev[]; };

// Where world point p (on instance `instance`, or PN_NO_HIT) was in the previous frame. An
// instance that did not move gives p itself, exactly, so still scenes keep their still pixels.
vec3 previousPosition(uint instance, vec3 p) {
    if (!PN_HAS(PN_FEATURE_INSTANCES) || instance == PN_NO_HIT) return p;
    Instance before = instancesPrev[instance];
    Instance now = instances[instance];
    if (before.objectToWorld[0] == now.objectToWorld[0] && before.objectToWorld[1] == now.objectToWorld[1] &&
        before.objectToWorld[2] == now.objectToWorld[2])
        return p;
    vec4 local = vec4(toInstancePoint(instance, p), 1.0);
    return vec3(dot(before.objectToWorld[0], local), dot(before.objectToWorld[1], local),
                dot(before.objectToWorld[2], local));
}

// Does the camera see this surface emit (light_sampler.glsl's emittedRadiance for a camera ray):
// a lamp or a glowing texel, or a window onto the sky; not Doom's sector light, whose floors and
// ceilings emit unseen (PN_MATERIAL_HIDDEN_EMISSION) and are lit surfaces like any other.
bool seenEmitting(Material m, Surface s) {
    if ((m.flags & PN_MATERIAL_EMISSIVE) == 0u || !s.frontFace) return false;
    if (PN_HAS(PN_FEATURE_SKY_PORTALS) && (m.flags & PN_MATERIAL_SKY_PORTAL) != 0u) return true;
    if ((m.flags & PN_MATERIAL_HIDDEN_EMISSION) != 0u) return false;
    vec3 e = materialEmission(m, s.uv);
    return max(e.r, max(e.g, e.b)) > 0.0;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (!insideImage(p)) return;
    vec2 centre = vec2(p) + 0.5;
    if ((push.mode & PN_GBUFFER_SUBPIXEL) != 0u)
        centre = vec2(p) + (vec2(float(push.passIndex % 4u), float(push.passIndex / 4u % 4u)) + 0.5) * 0.25;
    vec3 direction = viewDirection(centre);
    Hit hit = traceClosest(frame.cameraPosition, direction, PN_INFINITY);
    GBufferTexel g;
    g.prevDepth = 0.0;
    g.flags = 0u;
    if (hit.triangle == PN_NO_HIT) {
        g.normal = vec3(0.0);
        g.depth = 0.0;
        g.albedo = vec3(0.0);
        g.surfaceId = 0u;
        // The background is at infinity: only the camera's rotation moves it.
        g.motion = projectDirectionPrev(direction) - centre;
    } else {
        Surface s = surfaceAt(hit, frame.cameraPosition, direction);
        Material m = materials[s.material];
        g.normal = s.shadingNormal;
        g.depth = hit.t * dot(direction, frame.cameraForward);
        g.albedo = materialBaseColor(m, s.uv).rgb;
        g.surfaceId = s.material + 1u;
        if (seenEmitting(m, s) || (PN_HAS(PN_FEATURE_SPRITES) && (triVerts[hit.triangle].flags & PN_TRI_SPRITE) != 0u))
            g.flags |= PN_GBUFFER_UNFILTERED;
        vec3 previous = previousPosition(hit.instance, s.position);
        g.motion = projectPointPrev(previous) - centre;
        g.prevDepth = dot(previous - viewer.prevCameraPosition, viewer.prevCameraForward);
    }
    gbuffer[pixelIndex(p)] = g;
}
