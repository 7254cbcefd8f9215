#include "scene/presets/dungeon_textures.h"

#include <system_error>

#include "core/error.h"
#include "core/log.h"
#include "core/mapped_file.h"
#include "scene/io/wad/textures.h"
#include "scene/io/wad/wad_file.h"

namespace penumbra {
namespace {

// Freedoom's stand-ins for Doom's grey stone blocks, stone floor tiles and stone slabs.
constexpr const char* kWall = "STONE2";
constexpr const char* kFloor = "FLOOR4_8";
constexpr const char* kCeiling = "MFLR8_1";
constexpr float kMetresPerTexel = 1.0f / 32.0f;  // Doom's unit (scene/io/wad/units.h)

void warnFlat(const std::string& why) {
    logWarning("the dungeon is flat-coloured: " + why +
               " (its textures come from Freedoom: Debian package freedoom, which scripts/setup.sh installs)");
}

}  // namespace

const char* freedoomWadPath() { return "/usr/share/games/doom/freedoom1.wad"; }

std::optional<DungeonTextures> loadDungeonTextures(const std::filesystem::path& wad) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(wad, ec)) {
        warnFlat(wad.string() + " is missing");
        return std::nullopt;
    }
    try {
        const MappedFile file(wad, std::size_t(2) << 30, "WAD");
        const wad::WadFile lumps(file.bytes(), wad.filename().string());
        wad::TextureLibrary library(lumps);
        if (!library.hasWallTexture(kWall)) {
            warnFlat(wad.string() + " has no texture " + kWall);
            return std::nullopt;
        }
        DungeonTextures t;
        t.wall = library.wallTexture(kWall);
        t.floor = library.flat(kFloor);
        t.ceiling = library.flat(kCeiling);
        t.wallMetres = float(library.width(t.wall)) * kMetresPerTexel;
        t.wallHeightMetres = float(library.height(t.wall)) * kMetresPerTexel;
        t.flatMetres = float(library.width(t.floor)) * kMetresPerTexel;
        t.textures = std::move(library.textures());
        return t;
    } catch (const Error& e) {
        warnFlat(e.what());
        return std::nullopt;
    }
}

}  // namespace penumbra
