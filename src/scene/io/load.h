// Opening scene files: the format is chosen by extension and checked against the content.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "scene/io/wad/wad_loader.h"
#include "scene/scene.h"

namespace penumbra {

struct LoadOptions {
    std::string map;  // WAD: E1M1, MAP01, ...; empty picks the first map in the file
    WadOptions wad;   // WAD: glow, sector light and filtering
};

// The scene file formats loadSceneFile reads, for messages and help: ".obj, .ply, ..., or .json".
std::string sceneFileExtensions();

// Loads .obj, .ply (.ply.gz), .gltf, .glb, .wad, .json, or a format Assimp reads (FBX, Collada,
// 3DS, STL, ...: assimpExtensions()). Throws Error naming the file and the problem.
Scene loadSceneFile(const std::filesystem::path& path, const LoadOptions& options = {});

// A built-in preset name, or a path to a file.
Scene loadSceneByName(const std::string& nameOrPath, const LoadOptions& options = {});

// Reads a whole file, refusing files over `maxBytes` (so hostile inputs cannot exhaust memory).
std::string readFileBytes(const std::filesystem::path& path, std::size_t maxBytes = std::size_t(2) << 30);

// The size of a regular file of at most maxBytes; one clear error otherwise (missing, not a
// regular file, unreadable, too large).
std::uintmax_t checkedFileSize(const std::filesystem::path& path, std::uintmax_t maxBytes);

}  // namespace penumbra
