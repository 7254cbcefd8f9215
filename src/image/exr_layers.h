// Multi-layer OpenEXR files (through the OpenEXR library, Debian libopenexr-dev): one part,
// float32 channels named the way compositors expect, "layer.channel" (albedo.R, N.X, ...), the
// beauty in the unprefixed R, G, B. docs/RENDERING.md lists the layers `penumbra render --aov`
// writes.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "image/image.h"

namespace penumbra {

struct ExrChannel {
    std::string name;           // full channel name, e.g. "albedo.R"
    std::vector<float> values;  // width * height, top row first
};

// The image's R, G, B channels, under `layer` ("" for the beauty, else "layer.R" ...).
void appendRgbChannels(std::vector<ExrChannel>& channels, const ImageRgb& image, const std::string& layer = "",
                       const char* names = "RGB");

// Writes float32 channels, ZIP-compressed (lossless), atomically. Names must be unique.
void writeExrChannels(const std::filesystem::path& path, int width, int height, const std::vector<ExrChannel>& channels);

// Every channel of a single-part scanline or tiled EXR, converted to float. Throws Error naming
// the file on anything unreadable.
struct ExrChannels {
    int width = 0, height = 0;
    std::map<std::string, std::vector<float>> channels;
};
ExrChannels readExrChannels(const std::filesystem::path& path);

}  // namespace penumbra
