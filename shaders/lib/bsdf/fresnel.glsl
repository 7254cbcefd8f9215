// Fresnel reflectance: Schlick's approximation for conductors (tinted by the base colour) and the
// exact unpolarised formula for dielectrics.
#ifndef PN_BSDF_FRESNEL_GLSL
#define PN_BSDF_FRESNEL_GLSL

vec3 fresnelSchlick(vec3 f0, float cosTheta) {
    float m = clamp(1.0 - cosTheta, 0.0, 1.0);
    float m2 = m * m;
    return f0 + (1.0 - f0) * (m2 * m2 * m);
}

// Reflectance of a smooth dielectric boundary seen at cosThetaI (> 0, on the incident side),
// eta = ior of the far side / ior of the incident side. Total internal reflection gives 1.
float fresnelDielectric(float cosThetaI, float eta) {
    cosThetaI = clamp(cosThetaI, 0.0, 1.0);
    float sin2T = (1.0 - cosThetaI * cosThetaI) / (eta * eta);
    if (sin2T >= 1.0) return 1.0;
    float cosThetaT = sqrt(1.0 - sin2T);
    float rParallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
    float rPerpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
    return 0.5 * (rParallel * rParallel + rPerpendicular * rPerpendicular);
}

// The refracted direction of w (pointing away from the surface, on n's side, dot(w, n) > 0) through
// a boundary with relative ior eta (far side / w's side); false on total internal reflection.
bool refractDirection(vec3 w, vec3 n, float eta, out vec3 wt) {
    float cosI = dot(w, n);
    float sin2T = max(0.0, 1.0 - cosI * cosI) / (eta * eta);
    wt = vec3(0.0);
    if (sin2T >= 1.0) return false;
    float cosT = sqrt(1.0 - sin2T);
    wt = -w / eta + (cosI / eta - cosT) * n;
    return true;
}

#endif
