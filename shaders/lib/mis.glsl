// The weights that combine light sampling and BSDF sampling, per FrameUniforms.misMode. Tests
// render with one estimator at a time and check that each gives the same answer.
#ifndef PN_MIS_GLSL
#define PN_MIS_GLSL

#include "lib/sampling.glsl"

// A light sample whose light BSDF sampling could also have hit.
float misLightWeight(float lightPdf, float bsdfPdf) {
    if (frame.misMode == PN_MIS_LIGHT_ONLY) return 1.0;
    if (frame.misMode == PN_MIS_BSDF_ONLY) return 0.0;
    return powerHeuristic(lightPdf, bsdfPdf);
}

// A BSDF-sampled hit on an emitter that light sampling could also have chosen.
float misHitWeight(float bsdfPdf, float lightPdf) {
    if (frame.misMode == PN_MIS_LIGHT_ONLY) return 0.0;
    if (frame.misMode == PN_MIS_BSDF_ONLY) return 1.0;
    return powerHeuristic(bsdfPdf, lightPdf);
}

#endif
