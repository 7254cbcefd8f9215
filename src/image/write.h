// Image files: PNG, JPEG, TGA and BMP (tone-mapped sRGB, for looking at), EXR (linear float32,
// for comparing and compositing) and Radiance HDR (linear RGBE, for tools that read no EXR).
// Every write goes through writeFileAtomically, so a failed write leaves no partial file and
// never damages an existing one.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "image/image.h"
#include "image/tonemap.h"

namespace penumbra {

enum class ImageFormat { Png, Exr, Jpeg, Tga, Bmp, Hdr };

// By extension, case-insensitive. Anything else throws UsageError.
ImageFormat formatFromPath(const std::filesystem::path& path);
bool isLinearFormat(ImageFormat format);  // EXR and HDR

// PNG, JPEG (quality 95), TGA, BMP: tone mapped with settings, RGB8. EXR: linear RGB float32,
// ZIP-compressed; HDR: linear RGBE (8-bit mantissas sharing an exponent, about 1% precision).
// The linear formats ignore settings (they keep the radiance the renderer computed; exposure is
// a viewing choice).
void writeImage(const std::filesystem::path& path, const ImageRgb& image,
                const ToneMapSettings& settings);

// A PNG of display-ready 8-bit sRGB pixels (RGB, row-major, top row first), written atomically:
// the viewer's screenshots, which must hold exactly what the window showed.
void writePngRgb8(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgb);

// Reads the beauty of an EXR (beautyChannels in exr_layers.h: R, G, B; a Y-only file becomes
// grey; the multi-layer files `render --aov` writes give their unprefixed beauty), any
// compression, DWA included. Alpha and other layers are dropped.
ImageRgb readExr(const std::filesystem::path& path);

}  // namespace penumbra
