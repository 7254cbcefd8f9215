// Multi-layer OpenEXR files (through the OpenEXR library, Debian libopenexr-dev): one part,
// float32 channels named the way compositors expect, "layer.channel" (albedo.R, N.X, ...), the
// beauty in the unprefixed R, G, B. docs/RENDERING.md lists the layers `penumbra render --aov`
// writes.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
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

// Every channel of a scanline or tiled EXR (the first part of a multi-part file), converted to
// float, whatever its compression (ZIP, PIZ, DWAA/DWAB, ...). Throws Error naming the file on
// anything unreadable.
struct ExrChannels {
    int width = 0, height = 0;
    std::map<std::string, std::vector<float>> channels;
};
ExrChannels readExrChannels(const std::filesystem::path& path);

// An EXR's size and channel names from its header alone, so a caller can refuse a size before
// anything is allocated for the pixels. Throws Error naming `name`.
struct ExrHeaderInfo {
    long long width = 0, height = 0;
    std::vector<std::string> channels;
};
ExrHeaderInfo readExrHeader(std::string_view bytes, const std::string& name);

// The channels listed in `only` (every channel when it is empty) of an EXR held in memory.
ExrChannels decodeExrChannels(std::string_view bytes, const std::string& name,
                              const std::vector<std::string>& only = {});

// The three channels that hold the beauty image: R, G, B; else Y three times (a grey image);
// else the R, G, B of a layer ("Combined.R", ... from Blender; the first such layer by name).
// nullopt when there is none.
std::optional<std::array<std::string, 3>> beautyChannels(const std::vector<std::string>& names);

}  // namespace penumbra
