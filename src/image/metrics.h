// Numbers for comparing renders: known-answer tests check meanLuminance against an analytic
// value; --compare and reference tests check rmse against a stored EXR.
#pragma once

#include "image/image.h"
#include "image/tonemap.h"

namespace penumbra {

// Mean Rec. 709 luminance over all pixels (double accumulation); 0 for an empty image.
double meanLuminance(const ImageRgb& image);

// Root mean square difference over all pixels and channels. Throws penumbra::Error if the sizes
// differ. NaN anywhere makes the result NaN, which fails any tolerance check, as it should.
double rmse(const ImageRgb& a, const ImageRgb& b);

// What a PNG of the image shows: tone mapped with `settings`, sRGB encoded, each channel in [0, 1].
ImageRgb displayedImage(const ImageRgb& image, const ToneMapSettings& settings = {});

// PSNR in dB of the displayed image against the displayed reference (peak 1): errors as people
// see them, so a few blown-out pixels on a light do not outweigh the rest. +inf when equal.
double displayedPsnr(const ImageRgb& image, const ImageRgb& reference);

// Sum over pixels of the squared luminance differences with the right and lower neighbours: the
// image's fine detail (a denoiser that blurs texture lowers it, remaining noise raises it).
double gradientEnergy(const ImageRgb& image);

}  // namespace penumbra
