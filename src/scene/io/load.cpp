#include "scene/io/load.h"

#include <algorithm>
#include <cctype>
#include <fstream>

#include "core/error.h"
#include "scene/io/assimp_loader.h"
#include "scene/io/gltf.h"
#include "scene/io/obj.h"
#include "scene/io/ply.h"
#include "scene/io/scene_json.h"
#include "scene/io/wad/wad_loader.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

// ".ply" for "x.PLY"; compressed files keep both parts: ".ply.gz".
std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".gz") return lowerExtension(path.stem()) + ext;
    return ext;
}

// The first bytes, to check that the content is what the extension claims.
std::string head(const std::filesystem::path& path, std::size_t n) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes(n, '\0');
    in.read(bytes.data(), std::streamsize(n));
    bytes.resize(std::size_t(in.gcount()));
    return bytes;
}

}  // namespace

std::string sceneFileExtensions() {
    return ".obj, .ply, .ply.gz, .gltf, .glb, .wad, .json or (through Assimp) " + assimpExtensions();
}

std::uintmax_t checkedFileSize(const std::filesystem::path& path, std::uintmax_t maxBytes) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error("cannot open '" + path.string() + "': " +
                    (std::filesystem::exists(path, ec) ? "it is not a regular file" : "no such file"));
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw Error("cannot read '" + path.string() + "': " + ec.message());
    if (size > maxBytes)
        throw Error("'" + path.string() + "' is " + std::to_string(size) + " bytes, more than the " +
                    std::to_string(maxBytes) + " this format allows");
    return size;
}

std::string readFileBytes(const std::filesystem::path& path, std::size_t maxBytes) {
    const auto size = static_cast<std::size_t>(checkedFileSize(path, maxBytes));
    std::ifstream in(path, std::ios::binary);
    std::string bytes(size, '\0');
    if (!in.read(bytes.data(), std::streamsize(size))) throw Error("cannot read '" + path.string() + "'");
    return bytes;
}

Scene loadSceneFile(const std::filesystem::path& path, const LoadOptions& options) {
    const std::string ext = lowerExtension(path);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw Error("cannot open '" + path.string() + "': no such file");
    const std::string magic = head(path, 4);
    auto mismatch = [&](const char* what) {
        throw Error("'" + path.string() + "' has the extension " + ext + " but does not look like " + what);
    };
    if (ext == ".wad") {
        if (magic != "IWAD" && magic != "PWAD") mismatch("a WAD file (no IWAD/PWAD header)");
        return loadWad(path, options.map, options.wad);
    }
    if (!options.map.empty()) throw UsageError("--map only applies to .wad files");
    if (ext == ".glb") {
        if (magic != "glTF") mismatch("a binary glTF file (no glTF header)");
        return loadGltf(path);
    }
    if (ext == ".gltf") return loadGltf(path);
    if (ext == ".obj") return loadObj(path);
    if (ext == ".ply" || ext == ".ply.gz") {
        const bool gzip = magic.size() >= 2 && magic[0] == '\x1f' && magic[1] == '\x8b';
        if (ext == ".ply.gz" && !gzip) mismatch("a gzip-compressed file (no gzip header)");
        if (ext == ".ply" && !gzip && magic.substr(0, 3) != "ply") mismatch("a PLY file (no 'ply' line)");
        return loadPly(path);
    }
    if (ext == ".json") return loadSceneJson(path);
    if (isAssimpExtension(ext)) return loadAssimp(path);
    throw UsageError("cannot tell the format of '" + path.string() + "': use a built-in scene name or a " +
                     sceneFileExtensions() + " file");
}

Scene loadSceneByName(const std::string& nameOrPath, const LoadOptions& options) {
    if (isPreset(nameOrPath)) {
        if (!options.map.empty()) throw UsageError("--map only applies to .wad files");
        return makePreset(nameOrPath);
    }
    std::error_code ec;
    if (!std::filesystem::exists(nameOrPath, ec) && std::filesystem::path(nameOrPath).extension().empty())
        return makePreset(nameOrPath);  // names the built-in scenes in its error
    return loadSceneFile(nameOrPath, options);
}

}  // namespace penumbra
