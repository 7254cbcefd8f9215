// Converting the Phong/Blinn-Phong parameters older formats carry (OBJ/MTL Ns, Assimp's
// shininess) to the principled model's perceptual roughness. One place, so every importer agrees.
#pragma once

#include <algorithm>
#include <cmath>

namespace penumbra {

// Blinn-Phong exponent Ns to perceptual roughness: sqrt(2 / (Ns + 2)), the width at which a
// Beckmann lobe matches a Blinn-Phong one (Walter et al. 2007, "Microfacet models for refraction").
// Ns = 0 gives 1 (diffuse-like), large exponents approach 0 (a mirror). Non-finite or negative Ns
// counts as 0.
inline float roughnessFromPhongExponent(float ns) {
    if (!std::isfinite(ns) || ns < 0.0f) ns = 0.0f;
    return std::clamp(std::sqrt(2.0f / (ns + 2.0f)), 0.0f, 1.0f);
}

}  // namespace penumbra
