// Model formats read through Assimp (Debian libassimp-dev): FBX, Collada, 3DS, STL, DirectX .x,
// OFF and the others in assimpExtensions(). OBJ, glTF and PLY keep Penumbra's own importers.
// Node transforms are baked into the vertices (a mesh used by several nodes is copied once per
// node), polygons are triangulated, points and lines dropped, and missing normals generated with
// the same crease angle as the OBJ importer. Materials: see docs/SCENES.md.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace penumbra {

// True for a lower-case extension (".fbx") this importer handles.
bool isAssimpExtension(const std::string& lowerExtension);
// ".fbx, .dae, ...", for messages and help.
std::string assimpExtensions();

// Throws Error naming the file and what Assimp said went wrong.
Scene loadAssimp(const std::filesystem::path& path);
// For fuzzing and tests: a model's bytes; `extensionHint` ("stl", "dae", ...) picks the reader
// the way the file name would. Only textures embedded in the file are read.
Scene loadAssimpFromMemory(std::string_view bytes, const std::string& name, const std::string& extensionHint);

}  // namespace penumbra
