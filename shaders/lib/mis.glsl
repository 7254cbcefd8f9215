// How the integrator combines light sampling (next event estimation) and BSDF sampling, per
// FrameUniforms.misMode. Every light class calls these, so the three modes stay consistent:
//   PN_MIS_BOTH:       both estimators, power heuristic.
//   PN_MIS_LIGHT_ONLY: light sampling only; emitters hit by BSDF-sampled rays count only where
//                      light sampling cannot reach them (after a delta bounce, or not sampleable).
//   PN_MIS_BSDF_ONLY:  emitters count only when hit; no light sampling for lights that can be hit.
// Delta (punctual) lights can never be hit, so they are always light-sampled with weight 1.
#ifndef PN_MIS_GLSL
#define PN_MIS_GLSL

#include "lib/sampling.glsl"

// Should lights that BSDF sampling can also hit (area, sphere, environment) be light-sampled?
bool misSamplesLights() { return frame.misMode != PN_MIS_BSDF_ONLY; }

// Weight of a light sample with densities lightPdf (of the light sampler) and bsdfPdf (of BSDF
// sampling, 0 for a delta BSDF lobe or a direction it cannot produce).
float misWeightLight(float lightPdf, float bsdfPdf) {
    if (frame.misMode == PN_MIS_LIGHT_ONLY) return 1.0;
    if (frame.misMode == PN_MIS_BSDF_ONLY) return 0.0;
    return powerHeuristic(lightPdf, bsdfPdf);
}

// Weight of emission found by a BSDF-sampled ray. lightPdf: the density with which light sampling
// would have chosen that direction (0: it cannot); afterDelta: the ray left a delta lobe (or the
// camera), where light sampling had no chance.
float misWeightHit(float bsdfPdf, float lightPdf, bool afterDelta) {
    if (afterDelta || !(lightPdf > 0.0)) return 1.0;
    if (frame.misMode == PN_MIS_LIGHT_ONLY) return 0.0;
    if (frame.misMode == PN_MIS_BSDF_ONLY) return 1.0;
    return powerHeuristic(bsdfPdf, lightPdf);
}

#endif
