#include "scene/io/wad/sprites.h"

#include <algorithm>
#include <array>
#include <limits>

#include "core/log.h"

namespace penumbra::wad {

SpriteLibrary::SpriteLibrary(const WadFile& wad, TextureLibrary& textures)
    : wad_(wad), textures_(textures) {
    for (auto [begin, end] : wad.markerRanges("S_START", "S_END", "SS_START", "SS_END"))
        for (std::size_t i = begin; i < end; ++i) {
            const std::string& name = wad.lumps()[i].name;
            if (name.size() == 6 || name.size() == 8)
                lumpsBySprite_[name.substr(0, 4)].push_back(i);
        }
}

std::optional<SpriteViews> SpriteLibrary::views(const std::string& sprite, char frame) {
    const std::string label = "sprite " + sprite + " frame " + std::string(1, frame);
    // View digit -> lump; later lumps replace earlier ones, as a PWAD's replace the IWAD's.
    std::array<View, 9> found{};
    auto it = lumpsBySprite_.find(sprite);
    if (it != lumpsBySprite_.end())
        for (std::size_t lump : it->second) {
            const std::string& name = wad_.lumps()[lump].name;
            for (std::size_t pair = 4; pair + 1 < name.size(); pair += 2) {
                const int view = name[pair + 1] - '0';
                if (name[pair] == frame && view >= 0 && view <= 8)
                    found[std::size_t(view)] = {long(lump), pair == 6};
            }
        }
    std::vector<View> views;
    if (std::any_of(found.begin() + 1, found.end(), [](const View& v) { return v.lump >= 0; })) {
        const View any = *std::find_if(found.begin() + 1, found.end(),
                                       [](const View& v) { return v.lump >= 0; });
        for (int r = 1; r <= 8; ++r)
            views.push_back(found[std::size_t(r)].lump >= 0 ? found[std::size_t(r)] : any);
    } else if (found[0].lump >= 0) {
        views.push_back(found[0]);
    } else {
        logWarning(wad_.fileName() + ": " + label +
                   " is not in the WAD; the thing is drawn without it");
        return std::nullopt;
    }

    std::vector<TextureLibrary::Picture> pictures;
    for (const View& v : views) {
        std::optional<TextureLibrary::Picture> pic = textures_.picture(std::size_t(v.lump), label);
        if (!pic) return std::nullopt;
        pictures.push_back(std::move(*pic));
    }
    // The union of the views around the origin: x from -leftOffset, y down from topOffset.
    SpriteViews out;
    out.rotations = int(views.size());
    out.left = out.bottom = std::numeric_limits<int>::max();
    out.right = out.top = std::numeric_limits<int>::min();
    for (const auto& p : pictures) {
        out.left = std::min(out.left, -p.leftOffset);
        out.right = std::max(out.right, p.texture.width - p.leftOffset);
        out.top = std::max(out.top, p.topOffset);
        out.bottom = std::min(out.bottom, p.topOffset - p.texture.height);
    }
    out.left -= 1, out.right += 1, out.bottom -= 1, out.top += 1;  // the transparent border
    const long cellWidth = long(out.right) - out.left, cellHeight = long(out.top) - out.bottom;
    if (cellWidth * out.rotations > kMaxTextureSize || cellHeight > kMaxTextureSize ||
        !textures_.spendTexels(std::int64_t(cellWidth) * out.rotations * cellHeight)) {
        logWarning(wad_.fileName() + ": " + label +
                   "'s views do not fit one texture (or the texture budget); " +
                   "the thing is drawn without it");
        return std::nullopt;
    }
    Texture& atlas = out.atlas;
    atlas.name = sprite + std::string(1, frame);
    atlas.width = int(cellWidth) * out.rotations;
    atlas.height = int(cellHeight);
    atlas.rgba.assign(std::size_t(atlas.width) * std::size_t(atlas.height) * 4, 0);
    for (int k = 0; k < out.rotations; ++k) {
        const Texture& pic = pictures[std::size_t(k)].texture;
        const int x0 = k * int(cellWidth) + (-pictures[std::size_t(k)].leftOffset - out.left);
        const int y0 = out.top - pictures[std::size_t(k)].topOffset;
        for (int y = 0; y < pic.height; ++y)
            for (int x = 0; x < pic.width; ++x) {
                const int sx = views[std::size_t(k)].mirrored ? pic.width - 1 - x : x;
                const std::uint8_t* s =
                    &pic.rgba[(std::size_t(y) * std::size_t(pic.width) + std::size_t(sx)) * 4];
                std::uint8_t* d = &atlas.rgba[(std::size_t(y0 + y) * std::size_t(atlas.width) +
                                               std::size_t(x0 + x)) *
                                              4];
                std::copy(s, s + 4, d);
            }
    }
    return out;
}

}  // namespace penumbra::wad
