// The ray benchmark's rays, one kind per dispatch (raybench.comp times them; raybench_count.comp
// counts the walk's steps for the same rays):
//   PRIMARY: a camera ray per pixel (closest hit), keeping the hit point for the next two;
//   SHADOW:  from each kept point, an any-hit ray to a sample of a light the light sampler picked
//            (results: 1 lit, 0 occluded, -1 no ray: no light reaches the point);
//   DIFFUSE: from each kept point, a cosine-sampled bounce ray (closest hit).
// Include after shared/types.h and the workgroup size.
#ifndef PN_RAYBENCH_RAYS_GLSL
#define PN_RAYBENCH_RAYS_GLSL

#include "lib/scene_bindings.glsl"
#include "lib/rng.glsl"
#include "lib/sampling.glsl"
#include "lib/offset.glsl"
#include "lib/bvh.glsl"
#include "lib/camera.glsl"
#include "lib/surface.glsl"
#include "lib/light_sampler.glsl"

layout(std430, set = 0, binding = PN_BINDING_SCRATCH) buffer PointBuffer { SurfacePoint points[]; };
// One word per pixel so the compiler cannot drop the traversal as dead code.
layout(std430, set = 0, binding = PN_BINDING_SCRATCH2) buffer ResultBuffer { float results[]; };

// The ray of push.mode for the pixel `index`.
void benchRay(uvec2 pixel, uint index) {
    uint rng = rngSeed(index, push.passIndex, frame.seed);

    if (push.mode == PN_RAYBENCH_PRIMARY) {
        vec3 d = cameraRayDirection(vec2(pixel) + rngNext2(rng));
        Hit hit = traceClosest(frame.cameraPosition, d, PN_INFINITY);
        SurfacePoint p;
        p.valid = hit.triangle == PN_NO_HIT ? 0u : 1u;
        p.pad = 0.0;
        if (p.valid != 0u) {
            Surface s = surfaceAt(hit, frame.cameraPosition, d);
            p.position = s.position;
            p.normal = s.geometricNormal;
        } else {
            p.position = vec3(0.0);
            p.normal = vec3(0.0, 0.0, 1.0);
        }
        points[index] = p;
        results[index] = hit.t;
        return;
    }

    SurfacePoint p = points[index];
    if (p.valid == 0u) return;
    vec3 origin = offsetRayOrigin(p.position, p.normal);
    if (push.mode == PN_RAYBENCH_SHADOW) {
        results[index] = -1.0;
        LightPick pick = pickLight(p.position, p.normal, rngNext(rng), rng);
        if (pick.ref == PN_NO_LIGHT) return;
        LightSample ls = sampleChosenLight(pick, p.position, p.normal, rng);
        if (!(ls.pdf > 0.0)) return;
        results[index] = shadowRayBlocked(origin, ls) ? 0.0 : 1.0;
    } else {
        vec3 d = sampleCosineHemisphere(p.normal, rngNext2(rng));
        results[index] = traceClosest(origin, d, PN_INFINITY).t;
    }
}

#endif
