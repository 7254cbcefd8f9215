// Sprite frames: picture lumps between S_START and S_END (also SS_START/SS_END) named by a
// 4-letter sprite, a frame letter and a view digit (0: the same from every side; 1 to 8: seen
// from the thing's front, then in 45-degree steps as Doom's R_ProjectSprite numbers them), with
// an optional second frame-view pair naming the mirror image of the same picture (TROOA2A8).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/io/wad/textures.h"
#include "scene/io/wad/wad_file.h"

namespace penumbra::wad {

// One frame's views side by side in one texture. Every view gets a cell of the same size that
// puts the thing's origin at the same place (with a 1-texel transparent border, so neither
// filtering nor rounding bleeds one view into the next); mirrored views are stored mirrored, as
// Doom draws them: within the same screen span, columns reversed.
struct SpriteViews {
    Texture atlas;
    int rotations = 1;  // 1 or 8
    // The cell around the thing's origin, in Doom units: x toward the viewer's right, y up.
    int left = 0, right = 0, bottom = 0, top = 0;
};

class SpriteLibrary {
public:
    SpriteLibrary(const WadFile& wad, TextureLibrary& textures);

    // The views of `sprite` (4 letters) in `frame`, or nullopt (with one warning) when the WAD
    // has none that can be drawn. Missing views of an 8-view frame are filled with one it has.
    std::optional<SpriteViews> views(const std::string& sprite, char frame);

private:
    struct View {
        long lump = -1;
        bool mirrored = false;
    };

    const WadFile& wad_;
    TextureLibrary& textures_;
    std::map<std::string, std::vector<std::size_t>> lumpsBySprite_;  // directory order
};

}  // namespace penumbra::wad
