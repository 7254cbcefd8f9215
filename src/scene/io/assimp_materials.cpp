#include "scene/io/assimp_materials.h"

#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/texture.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "core/log.h"
#include "scene/io/phong.h"
#include "scene/io/texture_io.h"

namespace penumbra {
namespace {

float clamp01(float v) { return std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f; }
Vec3 clamp01(const aiColor4D& c) { return {clamp01(c.r), clamp01(c.g), clamp01(c.b)}; }
Vec3 nonNegative(const aiColor4D& c) {
    auto f = [](float v) { return std::isfinite(v) ? std::max(v, 0.0f) : 0.0f; };
    return {f(c.r), f(c.g), f(c.b)};
}

bool getColor(const aiMaterial& m, const char* key, unsigned type, unsigned index, Vec3* out, bool clamp = true) {
    aiColor4D c;
    if (m.Get(key, type, index, c) != aiReturn_SUCCESS) return false;
    *out = clamp ? clamp01(c) : nonNegative(c);
    return true;
}

bool getFloat(const aiMaterial& m, const char* key, unsigned type, unsigned index, float* out) {
    float v = 0.0f;
    if (m.Get(key, type, index, v) != aiReturn_SUCCESS || !std::isfinite(v)) return false;
    *out = v;
    return true;
}

Wrap wrapFrom(aiTextureMapMode mode) {
    switch (mode) {
        case aiTextureMapMode_Clamp:
        case aiTextureMapMode_Decal: return Wrap::ClampToEdge;
        case aiTextureMapMode_Mirror: return Wrap::MirroredRepeat;
        default: return Wrap::Repeat;
    }
}

// Texture names in messages stay short even when a hostile file makes them long.
std::string shortName(const std::string& s) { return s.size() > 80 ? s.substr(0, 77) + "..." : s; }

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// A file in `dir` whose name equals `name` ignoring case (the first few thousand entries only).
std::optional<std::filesystem::path> findIgnoringCase(const std::filesystem::path& dir, const std::string& name) {
    std::error_code ec;
    const std::string wanted = lower(name);
    std::filesystem::directory_iterator it(dir, ec), end;
    for (int seen = 0; !ec && it != end && seen < 4096; it.increment(ec), ++seen)
        if (lower(it->path().filename().string()) == wanted && it->is_regular_file(ec)) return it->path();
    return std::nullopt;
}

}  // namespace

AssimpMaterialConverter::AssimpMaterialConverter(const aiScene& ai, Scene& scene,
                                                 std::optional<std::filesystem::path> baseDir, std::string modelName)
    : ai_(ai), scene_(scene), baseDir_(std::move(baseDir)), modelName_(std::move(modelName)) {}

Material AssimpMaterialConverter::convert(const aiMaterial& in) {
    Material m;
    aiString name;
    if (in.Get(AI_MATKEY_NAME, name) == aiReturn_SUCCESS) m.name = shortName(name.C_Str());
    if (!getColor(in, AI_MATKEY_BASE_COLOR, &m.albedo)) getColor(in, AI_MATKEY_COLOR_DIFFUSE, &m.albedo);
    float opacity = 1.0f;
    if (getFloat(in, AI_MATKEY_OPACITY, &opacity)) m.opacity = clamp01(opacity);

    Vec3 emission{0.0f};
    if (getColor(in, AI_MATKEY_COLOR_EMISSIVE, &emission, false)) {
        float intensity = 1.0f;
        if (getFloat(in, AI_MATKEY_EMISSIVE_INTENSITY, &intensity)) emission = emission * std::max(intensity, 0.0f);
        m.emission = emission;
    }

    float metallic = 0.0f, roughness = 1.0f, gloss = 0.0f, shininess = 0.0f, strength = 1.0f;
    Vec3 ks{0.0f};
    getColor(in, AI_MATKEY_COLOR_SPECULAR, &ks);
    if (getFloat(in, AI_MATKEY_SHININESS_STRENGTH, &strength)) ks = ks * clamp01(strength);
    if (getFloat(in, AI_MATKEY_METALLIC_FACTOR, &metallic)) {
        // Metallic-roughness (glTF-like PBR from FBX/3ds Max physical materials).
        m.metallic = clamp01(metallic);
        if (getFloat(in, AI_MATKEY_ROUGHNESS_FACTOR, &roughness)) m.roughness = clamp01(roughness);
        m.specular = 1.0f;
    } else if (getFloat(in, AI_MATKEY_GLOSSINESS_FACTOR, &gloss)) {
        // Specular-glossiness: glossiness is one minus roughness; the specular colour only says
        // whether there is a coat (the principled model has no coloured dielectric specular).
        m.roughness = 1.0f - clamp01(gloss);
        m.specular = maxComponent(ks) > 0 ? 1.0f : 0.0f;
    } else {
        // Phong/Blinn (3DS, Collada, X, older FBX): as for OBJ/MTL.
        getFloat(in, AI_MATKEY_SHININESS, &shininess);
        int model = 0;
        const bool diffuseOnly = in.Get(AI_MATKEY_SHADING_MODEL, model) == aiReturn_SUCCESS &&
                                 (model == aiShadingMode_Flat || model == aiShadingMode_Gouraud ||
                                  model == aiShadingMode_OrenNayar || model == aiShadingMode_NoShading);
        const bool coat = !diffuseOnly && maxComponent(ks) > 0;
        m.roughness = coat ? roughnessFromPhongExponent(shininess) : 1.0f;
        m.specular = coat ? 1.0f : 0.0f;
    }
    float ior = 0.0f, transmission = 0.0f;
    if (getFloat(in, AI_MATKEY_REFRACTI, &ior) && ior > 1.0f) m.ior = std::min(ior, 4.0f);
    if (getFloat(in, AI_MATKEY_TRANSMISSION_FACTOR, &transmission)) m.transmission = clamp01(transmission);

    m.albedoTexture = texture(in, aiTextureType_BASE_COLOR, true);
    if (!m.albedoTexture.present()) m.albedoTexture = texture(in, aiTextureType_DIFFUSE, true);
    m.emissionTexture = texture(in, aiTextureType_EMISSION_COLOR, true);
    if (!m.emissionTexture.present()) m.emissionTexture = texture(in, aiTextureType_EMISSIVE, true);
    if (m.emissionTexture.present() && !m.isEmissive()) m.emission = Vec3{1.0f};
    m.normalTexture = texture(in, aiTextureType_NORMALS, false);
    return m;
}

TextureRef AssimpMaterialConverter::texture(const aiMaterial& in, int type, bool srgb) {
    const auto textureType = static_cast<aiTextureType>(type);
    if (in.GetTextureCount(textureType) == 0) return {};
    aiString path;
    aiTextureMapMode modes[2] = {aiTextureMapMode_Wrap, aiTextureMapMode_Wrap};
    if (in.GetTexture(textureType, 0, &path, nullptr, nullptr, nullptr, nullptr, modes) != aiReturn_SUCCESS)
        return {};
    const std::string reference = path.C_Str();
    if (reference.empty()) return {};
    TextureRef ref;
    ref.wrapU = wrapFrom(modes[0]);
    ref.wrapV = wrapFrom(modes[1]);
    const auto key = std::make_pair(reference, srgb);
    if (auto it = cache_.find(key); it != cache_.end()) {
        ref.texture = it->second;
        return ref;
    }
    std::string why;
    std::optional<Texture> tex = ai_.GetEmbeddedTexture(reference.c_str()) ? embedded(reference, srgb, &why)
                                                                           : external(reference, srgb, &why);
    if (!tex) {
        logWarning(modelName_ + ": texture '" + shortName(reference) + "': " + why + "; using a checker");
        tex = missingTexture(reference);
    }
    tex->name = shortName(reference);
    tex->srgb = srgb;
    ref.texture = static_cast<int>(scene_.textures.size());
    scene_.textures.push_back(std::move(*tex));
    cache_.emplace(key, ref.texture);
    return ref;
}

std::optional<Texture> AssimpMaterialConverter::embedded(const std::string& reference, bool srgb,
                                                         std::string* why) const {
    const aiTexture* t = ai_.GetEmbeddedTexture(reference.c_str());
    if (t->mHeight == 0) {  // compressed (PNG, JPEG, ...): mWidth is the byte count
        return decodeTexture(std::string_view(reinterpret_cast<const char*>(t->pcData), t->mWidth), reference, srgb, why);
    }
    const std::size_t w = t->mWidth, h = t->mHeight;
    if (w > std::size_t(kMaxTextureSide) || h > std::size_t(kMaxTextureSide)) {
        *why = "embedded image is " + std::to_string(w) + "x" + std::to_string(h) + "; sides must be at most " +
               std::to_string(kMaxTextureSide);
        return std::nullopt;
    }
    Texture tex;
    tex.width = int(w);
    tex.height = int(h);
    tex.rgba.resize(w * h * 4);
    for (std::size_t i = 0; i < w * h; ++i) {  // aiTexel is BGRA
        const aiTexel& p = t->pcData[i];
        tex.rgba[4 * i + 0] = p.r;
        tex.rgba[4 * i + 1] = p.g;
        tex.rgba[4 * i + 2] = p.b;
        tex.rgba[4 * i + 3] = p.a;
    }
    tex.srgb = srgb;
    return tex;
}

std::optional<Texture> AssimpMaterialConverter::external(const std::string& reference, bool srgb,
                                                         std::string* why) const {
    if (!baseDir_) {
        *why = "external textures are not read from memory";
        return std::nullopt;
    }
    std::string relative = reference;
    std::replace(relative.begin(), relative.end(), '\\', '/');
    std::filesystem::path path = std::filesystem::path(relative);
    if (path.is_relative()) path = *baseDir_ / path;
    std::error_code ec;
    // Models made on another machine often name a folder that exists only there: then the file
    // name alone, next to the model, is what the artist shipped.
    // Formats from DOS and Windows (3DS, X, ASE) name files in any case: "TEST.PNG" for test.png.
    if (!std::filesystem::is_regular_file(path, ec)) {
        const std::filesystem::path beside = *baseDir_ / std::filesystem::path(relative).filename();
        if (std::filesystem::is_regular_file(beside, ec))
            path = beside;
        else if (auto match = findIgnoringCase(*baseDir_, beside.filename().string()))
            path = *match;
    }
    return loadTextureFile(path, srgb, why);
}

}  // namespace penumbra
