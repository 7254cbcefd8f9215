// Numbers for comparing renders: known-answer tests check meanLuminance against an analytic
// value; --compare and reference tests check rmse against a stored EXR.
#pragma once

#include "image/image.h"

namespace penumbra {

// Mean Rec. 709 luminance over all pixels (double accumulation); 0 for an empty image.
double meanLuminance(const ImageRgb& image);

// Root mean square difference over all pixels and channels. Throws penumbra::Error if the sizes
// differ. NaN anywhere makes the result NaN, which fails any tolerance check, as it should.
double rmse(const ImageRgb& a, const ImageRgb& b);

}  // namespace penumbra
