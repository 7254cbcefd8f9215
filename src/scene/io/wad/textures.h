// Doom graphics: PLAYPAL (palette 0), PNAMES + TEXTURE1/TEXTURE2 wall textures composed from
// picture-format patches, and 64x64 flats between F_START and F_END. Textures are decoded on
// first use and cached; names that do not resolve get one warning and a magenta/black checker.
// A texture or flat of one of Doom's animation cycles (animation.h) brings all its frames, as
// consecutive textures that carry their TextureAnimation.
#pragma once

#include <array>
#include <optional>
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
    // A picture-format lump (a patch or sprite frame) on its own: size and offsets from its
    // header, unpainted texels transparent. nullopt (with a warning) when its size is unusable
    // or the texture budget is spent; throws Error for a lump that runs past its end.
    struct Picture {
        Texture texture;
        int leftOffset = 0, topOffset = 0;  // where the picture's origin is, from its top-left corner
    };
    std::optional<Picture> picture(std::size_t lump, const std::string& context);
    // Takes `texels` from the budget every decoded texture draws on; false (nothing taken) when
    // too few are left. For textures made from decoded ones (sprite views).
    bool spendTexels(std::int64_t texels);
    bool hasWallTexture(const std::string& name) const { return defs_.count(name) != 0; }
    // A wall texture composed on its own, not added to the list (the sky, which becomes the
    // environment); nullopt when it is not defined or unusable.
    std::optional<Texture> composeWall(const std::string& name);
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
    int decodeWall(const std::string& name);
    int decodeFlat(const std::string& name);
    // Loads the cycle holding `name`, frames in order; returns the index of `name`'s frame.
    int loadCycle(const std::vector<std::string>& cycle, bool flat, const std::string& name);
    Texture compose(const std::string& name, const TextureDef& def);
    void drawPatch(Texture& tex, const std::string& texName, long patchLump, int originX,
                   int originY);
    int checker(const std::string& name, const char* kind);
    long findPatch(const std::string& name) const;

    const WadFile& wad_;
    std::array<std::array<std::uint8_t, 3>, 256> palette_{};
    std::vector<std::string> patchNames_;
    std::unordered_map<std::string, TextureDef> defs_;
    std::vector<std::string> textureOrder_;  // definition order, each name once
    std::unordered_map<std::string, std::vector<std::string>> wallCycles_, flatCycles_;  // by member name
    std::unordered_map<std::string, std::size_t> flatLumps_;
    std::vector<std::pair<std::size_t, std::size_t>> patchRanges_;
    std::unordered_map<std::string, int> wallCache_, flatCache_;
    std::vector<Texture> textures_;
    std::int64_t texelBudget_ = std::int64_t(32) << 20;       // all textures together
    std::int64_t patchBytesBudget_ = std::int64_t(256) << 20;  // patch bytes drawn
};

}  // namespace penumbra::wad
