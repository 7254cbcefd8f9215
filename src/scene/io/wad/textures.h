// Doom graphics: PLAYPAL (palette 0), PNAMES + TEXTURE1/TEXTURE2 wall textures composed from
// picture-format patches, and 64x64 flats between F_START and F_END. Textures are decoded on
// first use and cached; names that do not resolve get one warning and a magenta/black checker.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "scene/io/wad/wad_file.h"
#include "scene/scene.h"

namespace penumbra::wad {

constexpr int kMaxTextureSize = 4096;

class TextureLibrary {
public:
    // Reads the palette and the texture directories; throws Error naming the lump when one of
    // them is malformed. A WAD without PLAYPAL gets a grey ramp (warning).
    explicit TextureLibrary(const WadFile& wad);

    // Index into `textures` of a wall texture or flat; the checker when the name is unknown.
    int wallTexture(const std::string& name);
    int flat(const std::string& name);
    // Size of a texture index returned above.
    int width(int texture) const { return textures_[std::size_t(texture)].width; }
    int height(int texture) const { return textures_[std::size_t(texture)].height; }

    // The decoded textures, in the order their indices were handed out.
    std::vector<Texture>& textures() { return textures_; }

private:
    struct TextureDef {
        std::size_t lump;    // TEXTURE1 or TEXTURE2
        std::size_t offset;  // of the definition inside the lump
    };
    void readTextureLump(const char* name);
    Texture compose(const std::string& name, const TextureDef& def);
    void drawPatch(Texture& tex, const std::string& texName, long patchLump, int originX,
                   int originY);
    int checker(const std::string& name, const char* kind);
    long findPatch(const std::string& name) const;

    const WadFile& wad_;
    std::array<std::array<std::uint8_t, 3>, 256> palette_{};
    std::vector<std::string> patchNames_;
    std::unordered_map<std::string, TextureDef> defs_;
    std::unordered_map<std::string, std::size_t> flatLumps_;
    std::vector<std::pair<std::size_t, std::size_t>> patchRanges_;
    std::unordered_map<std::string, int> wallCache_, flatCache_;
    std::vector<Texture> textures_;
    std::int64_t texelBudget_ = std::int64_t(32) << 20;       // all textures together
    std::int64_t patchBytesBudget_ = std::int64_t(256) << 20;  // patch bytes drawn
};

}  // namespace penumbra::wad
