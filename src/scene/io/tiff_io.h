// TIFF images through libtiff (Debian libtiff-dev), for textures and environment maps: every
// integer layout libtiff can convert (1 to 16 bits, palette, greyscale, YCbCr, tiled or strips,
// any compression it was built with) as 8-bit RGBA, and 32-bit floating-point RGB(A) or grey
// strips (HDR panoramas) as linear float.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra {

struct TiffPixels {
    int width = 0, height = 0;         // top row first
    bool isFloat = false;
    std::vector<std::uint8_t> rgba8;   // integer images: width * height * 4
    std::vector<float> rgbaFloat;      // float images: width * height * 4, alpha 1 when absent
};

// True when the bytes start like a TIFF file (either byte order, classic or BigTIFF).
bool isTiff(std::string_view bytes);

// Throws Error naming `name`: unreadable data, a layout libtiff cannot convert, or a size beyond
// maxSide per side or maxPixelsPerByte times the file's size (refused before pixels are
// allocated).
TiffPixels decodeTiff(std::string_view bytes, const std::string& name, int maxSide, double maxPixelsPerByte);

}  // namespace penumbra
