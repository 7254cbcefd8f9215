// Assimp materials and textures onto Penumbra's principled material (internal to the Assimp
// importer, assimp_loader.cpp).
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "scene/scene.h"

struct aiMaterial;
struct aiScene;

namespace penumbra {

// Turns an Assimp material into a Material, adding the textures it uses to scene.textures once
// each. External texture files are looked up next to the model (baseDir); without a baseDir
// (in-memory loads) only textures embedded in the file are read. A texture that cannot be read
// becomes the missing-texture checker, with a warning.
class AssimpMaterialConverter {
public:
    AssimpMaterialConverter(const aiScene& ai, Scene& scene, std::optional<std::filesystem::path> baseDir,
                            std::string modelName);

    Material convert(const aiMaterial& in);

private:
    TextureRef texture(const aiMaterial& in, int type, bool srgb);
    std::optional<Texture> embedded(const std::string& reference, bool srgb, std::string* why) const;
    std::optional<Texture> external(const std::string& reference, bool srgb, std::string* why) const;

    const aiScene& ai_;
    Scene& scene_;
    std::optional<std::filesystem::path> baseDir_;
    std::string modelName_;
    std::map<std::pair<std::string, bool>, int> cache_;  // (reference, srgb) -> scene texture
};

}  // namespace penumbra
