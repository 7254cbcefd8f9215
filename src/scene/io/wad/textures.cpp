#include "scene/io/wad/textures.h"

#include <algorithm>

#include "core/error.h"
#include "core/log.h"
#include "scene/io/wad/animation.h"

namespace penumbra::wad {
namespace {
const unsigned char* bytesOf(std::string_view s) {
    return reinterpret_cast<const unsigned char*>(s.data());
}
}  // namespace

TextureLibrary::TextureLibrary(const WadFile& wad) : wad_(wad) {
    long playpal = wad.findLast("PLAYPAL");
    if (playpal >= 0) {
        std::string_view pal = wad.lumpData(std::size_t(playpal));
        if (pal.size() < 768)
            throw Error(wad.where(std::size_t(playpal)) + " is " + std::to_string(pal.size()) +
                        " bytes, shorter than one 768-byte palette");
        for (int i = 0; i < 256; ++i)
            for (int c = 0; c < 3; ++c) palette_[i][c] = bytesOf(pal)[3 * i + c];
    } else {
        logWarning(wad.fileName() + ": no PLAYPAL lump; textures use a grey ramp");
        for (int i = 0; i < 256; ++i) palette_[i] = {std::uint8_t(i), std::uint8_t(i), std::uint8_t(i)};
    }

    long pnames = wad.findLast("PNAMES");
    if (pnames >= 0) {
        std::string_view p = wad.lumpData(std::size_t(pnames));
        if (p.size() < 4) throw Error(wad.where(std::size_t(pnames)) + " is shorter than its count");
        std::int64_t count = readI32(bytesOf(p));
        if (count < 0 || count > std::int64_t(p.size() - 4) / 8)
            throw Error(wad.where(std::size_t(pnames)) + " claims " + std::to_string(count) +
                        " patch names, more than its " + std::to_string(p.size()) +
                        " bytes can hold");
        patchNames_.reserve(std::size_t(count));
        for (std::int64_t i = 0; i < count; ++i) patchNames_.push_back(readName8(bytesOf(p) + 4 + 8 * i));
    }
    readTextureLump("TEXTURE1");
    readTextureLump("TEXTURE2");

    for (auto [begin, end] : wad.markerRanges("F_START", "F_END", "FF_START", "FF_END"))
        for (std::size_t i = begin; i < end; ++i) flatLumps_[wad.lumps()[i].name] = i;
    patchRanges_ = wad.markerRanges("P_START", "P_END", "PP_START", "PP_END");

    // Animation cycles: flats in the directory order of the lumps that define them.
    std::vector<std::pair<std::size_t, std::string>> flatsByLump;
    for (const auto& [flatName, lump] : flatLumps_) flatsByLump.emplace_back(lump, flatName);
    std::sort(flatsByLump.begin(), flatsByLump.end());
    std::vector<std::string> flatOrder;
    for (auto& entry : flatsByLump) flatOrder.push_back(std::move(entry.second));
    for (const auto& cycle : findCycles(flatOrder, false))
        for (const std::string& frame : cycle) flatCycles_.try_emplace(frame, cycle);
    for (const auto& cycle : findCycles(textureOrder_, true))
        for (const std::string& frame : cycle) wallCycles_.try_emplace(frame, cycle);
}

void TextureLibrary::readTextureLump(const char* name) {
    long index = wad_.findLast(name);
    if (index < 0) return;
    std::string_view t = wad_.lumpData(std::size_t(index));
    const std::string where = wad_.where(std::size_t(index));
    if (t.size() < 4) throw Error(where + " is shorter than its count");
    std::int64_t count = readI32(bytesOf(t));
    if (count < 0 || count > std::int64_t(t.size() - 4) / 4)
        throw Error(where + " claims " + std::to_string(count) + " textures, more than its " +
                    std::to_string(t.size()) + " bytes can hold");
    for (std::int64_t i = 0; i < count; ++i) {
        std::int64_t offset = readI32(bytesOf(t) + 4 + 4 * i);
        if (offset < 0 || offset + 22 > std::int64_t(t.size()))
            throw Error(where + ": texture " + std::to_string(i) + " starts at offset " +
                        std::to_string(offset) + ", past the end of the lump");
        std::string texName = readName8(bytesOf(t) + offset);
        if (defs_.try_emplace(texName, TextureDef{std::size_t(index), std::size_t(offset)}).second)  // first wins
            textureOrder_.push_back(texName);
    }
}

long TextureLibrary::findPatch(const std::string& name) const {
    for (auto it = patchRanges_.rbegin(); it != patchRanges_.rend(); ++it) {
        long i = wad_.findLast(name, it->first, it->second);
        if (i >= 0) return i;
    }
    return wad_.findLast(name);
}

int TextureLibrary::checker(const std::string& name, const char* kind) {
    logWarning(wad_.fileName() + ": " + kind + " '" + name +
               "' is missing or unusable; using a checker texture");
    Texture tex;
    tex.name = name + " (missing)";
    tex.width = tex.height = 64;
    tex.rgba.resize(64 * 64 * 4);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            bool on = ((x / 8) + (y / 8)) % 2 == 0;
            std::uint8_t* p = &tex.rgba[std::size_t(y * 64 + x) * 4];
            p[0] = on ? 255 : 0, p[1] = 0, p[2] = on ? 255 : 0, p[3] = 255;
        }
    textures_.push_back(std::move(tex));
    return int(textures_.size() - 1);
}

int TextureLibrary::wallTexture(const std::string& name) {
    if (auto it = wallCache_.find(name); it != wallCache_.end()) return it->second;
    if (auto cycle = wallCycles_.find(name); cycle != wallCycles_.end()) return loadCycle(cycle->second, false, name);
    const int index = decodeWall(name);
    wallCache_[name] = index;
    return index;
}

int TextureLibrary::flat(const std::string& name) {
    if (auto it = flatCache_.find(name); it != flatCache_.end()) return it->second;
    if (auto cycle = flatCycles_.find(name); cycle != flatCycles_.end()) return loadCycle(cycle->second, true, name);
    const int index = decodeFlat(name);
    flatCache_[name] = index;
    return index;
}

int TextureLibrary::loadCycle(const std::vector<std::string>& cycle, bool isFlat, const std::string& name) {
    const std::size_t first = textures_.size();
    int wanted = -1;
    for (std::size_t k = 0; k < cycle.size(); ++k) {
        // Each frame pushes exactly one texture (the frame or a checker), so they stay consecutive.
        const int index = isFlat ? decodeFlat(cycle[k]) : decodeWall(cycle[k]);
        Texture& tex = textures_[std::size_t(index)];
        tex.animation = {int(cycle.size()), int(k), kSecondsPerAnimationFrame};
        // A frame that is also in an earlier cycle (a WAD with interleaved cycles) keeps that one.
        (isFlat ? flatCache_ : wallCache_).try_emplace(cycle[k], index);
        if (cycle[k] == name) wanted = index;
    }
    return wanted >= 0 ? wanted : int(first);
}

int TextureLibrary::decodeWall(const std::string& name) {
    int index = -1;
    auto def = defs_.find(name);
    if (def != defs_.end()) {
        Texture tex = compose(name, def->second);
        if (tex.width > 0) {
            textures_.push_back(std::move(tex));
            index = int(textures_.size() - 1);
        }
    }
    if (index < 0) index = checker(name, "wall texture");
    return index;
}

int TextureLibrary::decodeFlat(const std::string& name) {
    int index = -1;
    auto lump = flatLumps_.find(name);
    if (lump != flatLumps_.end()) {
        std::string_view data = wad_.lumpData(lump->second);
        if (data.size() >= 4096) {
            Texture tex;
            tex.name = name;
            tex.width = tex.height = 64;
            tex.rgba.resize(64 * 64 * 4);
            for (std::size_t i = 0; i < 4096; ++i) {
                const auto& c = palette_[bytesOf(data)[i]];
                tex.rgba[4 * i] = c[0], tex.rgba[4 * i + 1] = c[1], tex.rgba[4 * i + 2] = c[2];
                tex.rgba[4 * i + 3] = 255;
            }
            textures_.push_back(std::move(tex));
            index = int(textures_.size() - 1);
        }
    }
    if (index < 0) index = checker(name, "flat");
    return index;
}

std::optional<Texture> TextureLibrary::composeWall(const std::string& name) {
    auto def = defs_.find(name);
    if (def == defs_.end()) return std::nullopt;
    Texture tex = compose(name, def->second);
    if (tex.width <= 0) return std::nullopt;
    return tex;
}

bool TextureLibrary::spendTexels(std::int64_t texels) {
    if (texels < 0 || texels > texelBudget_) return false;
    texelBudget_ -= texels;
    return true;
}

std::optional<TextureLibrary::Picture> TextureLibrary::picture(std::size_t lump, const std::string& context) {
    std::string_view data = wad_.lumpData(lump);
    const std::string where = wad_.where(lump) + " (" + context + ")";
    if (data.size() < 8) throw Error(where + " is too short for a picture header");
    const unsigned char* d = bytesOf(data);
    const int width = readI16(d), height = readI16(d + 2);
    if (width <= 0 || height <= 0 || width > kMaxTextureSize || height > kMaxTextureSize) {
        logWarning(where + " has unusable size " + std::to_string(width) + "x" + std::to_string(height));
        return std::nullopt;
    }
    const std::int64_t texels = std::int64_t(width) * height;
    if (texels > texelBudget_) {
        logWarning(where + ": texture memory budget exhausted");
        return std::nullopt;
    }
    texelBudget_ -= texels;
    Picture pic;
    pic.leftOffset = readI16(d + 4);
    pic.topOffset = readI16(d + 6);
    pic.texture.name = wad_.lumps()[lump].name;
    pic.texture.width = width;
    pic.texture.height = height;
    pic.texture.rgba.assign(std::size_t(texels) * 4, 0);
    drawPatch(pic.texture, context, long(lump), 0, 0);
    return pic;
}

Texture TextureLibrary::compose(const std::string& name, const TextureDef& def) {
    std::string_view lump = wad_.lumpData(def.lump);
    const unsigned char* d = bytesOf(lump) + def.offset;
    const std::size_t avail = lump.size() - def.offset;  // >= 22, checked when read
    const std::string where = wad_.where(def.lump) + ": texture " + name;
    int width = readI16(d + 12), height = readI16(d + 14);
    int patchCount = readI16(d + 20);
    if (width <= 0 || height <= 0 || width > kMaxTextureSize || height > kMaxTextureSize) {
        logWarning(where + " has unusable size " + std::to_string(width) + "x" +
                   std::to_string(height) + " (limit " + std::to_string(kMaxTextureSize) + ")");
        return {};
    }
    if (patchCount < 0 || std::size_t(22 + 10 * std::size_t(patchCount)) > avail)
        throw Error(where + " has " + std::to_string(patchCount) +
                    " patches, which run past the end of the lump");
    std::int64_t texels = std::int64_t(width) * height;
    if (texels > texelBudget_) {
        logWarning(where + ": texture memory budget exhausted");
        return {};
    }
    texelBudget_ -= texels;
    Texture tex;
    tex.name = name;
    tex.width = width;
    tex.height = height;
    tex.rgba.assign(std::size_t(texels) * 4, 0);  // unpainted texels are transparent
    for (int p = 0; p < patchCount; ++p) {
        const unsigned char* pp = d + 22 + 10 * p;
        int originX = readI16(pp), originY = readI16(pp + 2);
        int patch = readI16(pp + 4);
        if (patch < 0 || std::size_t(patch) >= patchNames_.size()) {
            logWarning(where + ": patch " + std::to_string(patch) + " is not in PNAMES (" +
                       std::to_string(patchNames_.size()) + " names)");
            continue;
        }
        long patchLump = findPatch(patchNames_[std::size_t(patch)]);
        if (patchLump < 0) {
            logWarning(where + ": patch " + patchNames_[std::size_t(patch)] + " is missing");
            continue;
        }
        drawPatch(tex, name, patchLump, originX, originY);
    }
    return tex;
}

void TextureLibrary::drawPatch(Texture& tex, const std::string& texName, long patchLump,
                               int originX, int originY) {
    std::string_view data = wad_.lumpData(std::size_t(patchLump));
    const std::string where = wad_.where(std::size_t(patchLump)) + " (in texture " + texName + ")";
    if (std::int64_t(data.size()) > patchBytesBudget_) {
        logWarning(where + ": patch drawing budget exhausted");
        return;
    }
    patchBytesBudget_ -= std::int64_t(data.size()) + 64;
    const unsigned char* d = bytesOf(data);
    const std::size_t size = data.size();
    if (size < 8) throw Error(where + " is too short for a picture header");
    int width = readI16(d);
    if (width < 0 || 8 + 4 * std::size_t(width) > size)
        throw Error(where + ": its " + std::to_string(width) +
                    " column offsets run past the end of the lump");
    for (int x = 0; x < width; ++x) {
        int tx = originX + x;
        std::int64_t col = readI32(d + 8 + 4 * x);
        if (col < 0 || std::uint64_t(col) >= size)
            throw Error(where + ": column " + std::to_string(x) + " starts past the end of the lump");
        if (tx < 0 || tx >= tex.width) continue;
        std::size_t pos = std::size_t(col);
        int lastTop = -1;
        // Each post takes at least 4 bytes, so the walk ends within the lump.
        while (pos < size && d[pos] != 0xFF) {
            if (pos + 4 > size)
                throw Error(where + ": column " + std::to_string(x) + " runs past the end of the lump");
            int top = d[pos];
            if (top <= lastTop) top += lastTop;  // tall patches: offsets become relative
            lastTop = top;
            std::size_t length = d[pos + 1];
            if (pos + 3 + length + 1 > size)
                throw Error(where + ": a post in column " + std::to_string(x) +
                            " runs past the end of the lump");
            const unsigned char* pixels = d + pos + 3;
            for (std::size_t k = 0; k < length; ++k) {
                int ty = originY + top + int(k);
                if (ty < 0 || ty >= tex.height) continue;
                const auto& c = palette_[pixels[k]];
                std::uint8_t* o = &tex.rgba[(std::size_t(ty) * tex.width + tx) * 4];
                o[0] = c[0], o[1] = c[1], o[2] = c[2], o[3] = 255;
            }
            pos += 4 + length;
            // Columns may share posts, so charge the work, not just the lump size.
            patchBytesBudget_ -= std::int64_t(length) + 4;
            if (patchBytesBudget_ < 0) {
                logWarning(where + ": patch drawing budget exhausted");
                return;
            }
        }
    }
}

}  // namespace penumbra::wad
