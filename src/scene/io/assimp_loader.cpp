#include "scene/io/assimp_loader.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cinttypes>
#include <cmath>
#include <fstream>
#include <sstream>
#include <limits>
#include <optional>
#include <vector>

#include "core/error.h"
#include "scene/io/assimp_materials.h"
#include "scene/io/load.h"
#include "scene/io/normals.h"

namespace penumbra {
namespace {

// The extensions Assimp 5.2 reads well enough to promise (its test models load with sensible
// geometry). .obj, .gltf/.glb and .ply stay with Penumbra's own importers.
constexpr std::array<const char*, 19> kExtensions = {
    ".fbx", ".dae", ".3ds", ".stl", ".x",   ".off", ".ase", ".lwo", ".ms3d", ".ac",
    ".3mf", ".b3d", ".dxf", ".md2", ".md3", ".md5mesh", ".smd", ".nff", ".ogex"};

constexpr std::size_t kMaxModelBytes = std::size_t(1) << 30;
// After node instancing: a small file may place one mesh a million times; refuse before copying.
constexpr std::size_t kMaxTriangles = std::size_t(1) << 26;
constexpr std::size_t kMaxNodeDepth = 1024;
constexpr float kCreaseDegrees = 60.0f;

unsigned postProcessFlags() {
    return aiProcess_ValidateDataStructure | aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
           aiProcess_SortByPType | aiProcess_FindDegenerates | aiProcess_FindInvalidData;
}

void configure(Assimp::Importer& importer) {
    // Points and lines (and triangles FindDegenerates collapses into them) are dropped.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    importer.SetPropertyBool(AI_CONFIG_PP_FD_REMOVE, true);
    // FBX files are often in centimetres; the scene model is in metres.
    importer.SetPropertyBool(AI_CONFIG_FBX_CONVERT_TO_M, true);
    importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_READ_ANIMATIONS, false);
}

// Assimp's messages can span lines; the user gets one.
std::string readHead(const std::filesystem::path& path, std::size_t n) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes(n, '\0');
    in.read(bytes.data(), std::streamsize(n));
    bytes.resize(std::size_t(in.gcount()));
    return bytes;
}

std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    std::replace(text.begin(), text.end(), '\r', ' ');
    while (!text.empty() && text.back() == ' ') text.pop_back();
    if (text.size() > 300) text = text.substr(0, 297) + "...";
    return text.empty() ? "unknown error" : text;
}

// Assimp believes the counts some formats declare up front and allocates for them before
// reading on; a small OFF file claiming 10^8 vertices costs gigabytes and many seconds. An ASCII
// OFF file spends at least two bytes a number ("0 "), so the counts are checked against the file
// size first. (Other formats Assimp reads are bounded by the allocation failing, see readError.)
void checkOffCounts(std::string_view head, std::uintmax_t fileSize, const std::string& name) {
    std::istringstream in{std::string(head)};
    std::string magic;
    if (!(in >> magic) || magic.size() < 3 || magic.compare(magic.size() - 3, 3, "OFF") != 0) return;
    std::string word;
    std::uintmax_t counts[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
        while (in >> word && word[0] == '#') std::getline(in, word);  // comments
        if (!in || word == "BINARY") return;                             // binary OFF: Assimp refuses it
        char* end = nullptr;
        counts[k] = std::strtoumax(word.c_str(), &end, 10);
        if (*end != '\0') return;  // not a count: Assimp will say what is wrong
    }
    const double minimum = double(counts[0]) * 6.0 + double(counts[1]) * 2.0;
    if (minimum > double(fileSize))
        throw Error(name + ": the OFF header declares " + std::to_string(counts[0]) + " vertices and " +
                    std::to_string(counts[1]) + " faces, more than the file's " + std::to_string(fileSize) +
                    " bytes can hold (truncated or corrupt)");
}

// What Assimp said, as one line; an allocation failure (a count in the file Assimp believed)
// becomes a sentence the user can act on.
std::string readError(const std::string& name, std::string what) {
    if (what.find("bad_alloc") != std::string::npos || what.find("bad_array_new_length") != std::string::npos)
        return name + ": cannot read the model: it needs more memory than is available (a count in the file is "
                      "probably corrupt)";
    if (what.find("No meshes remaining") != std::string::npos)  // all dropped as points, lines, NaN or degenerate
        return name + ": the file has no triangles to render (every face was a point, a line, degenerate or not finite)";
    return name + ": cannot read the model (" + oneLine(std::move(what)) + ")";
}

Vec3 toVec3(const aiVector3D& v) { return {v.x, v.y, v.z}; }

class SceneBuilder {
public:
    SceneBuilder(const aiScene& ai, std::string name, std::optional<std::filesystem::path> baseDir)
        : ai_(ai), name_(std::move(name)), materials_(ai, scene_, std::move(baseDir), name_) {}

    Scene build() {
        if (!ai_.mRootNode) throw Error(name_ + ": the file has no scene graph");
        scene_.name = name_;
        for (unsigned i = 0; i < ai_.mNumMaterials; ++i) scene_.materials.push_back(materials_.convert(*ai_.mMaterials[i]));
        if (scene_.materials.empty()) scene_.materials.push_back(Material{});
        walk();
        if (scene_.meshes.empty()) throw Error(name_ + ": the file has no triangles to render");
        scene_.camera = cameraFittingBounds(scene_.bounds());
        scene_.validate();
        return std::move(scene_);
    }

private:
    // Depth first over the node tree with accumulated transforms (no recursion: depth is the file's).
    void walk() {
        struct Item {
            const aiNode* node;
            aiMatrix4x4 transform;
            std::size_t depth;
        };
        std::vector<Item> stack{{ai_.mRootNode, ai_.mRootNode->mTransformation, 0}};
        while (!stack.empty()) {
            const Item item = stack.back();
            stack.pop_back();
            if (item.depth > kMaxNodeDepth)
                throw Error(name_ + ": the node tree is deeper than " + std::to_string(kMaxNodeDepth) + " levels");
            for (unsigned i = 0; i < item.node->mNumMeshes; ++i) {
                const unsigned index = item.node->mMeshes[i];
                if (index >= ai_.mNumMeshes) throw Error(name_ + ": node '" + item.node->mName.C_Str() + "' names a missing mesh");
                addMesh(*ai_.mMeshes[index], item.transform, item.node->mName.C_Str());
            }
            for (unsigned c = item.node->mNumChildren; c-- > 0;) {
                const aiNode* child = item.node->mChildren[c];
                stack.push_back({child, item.transform * child->mTransformation, item.depth + 1});
            }
        }
    }

    void addMesh(const aiMesh& in, const aiMatrix4x4& transform, const std::string& nodeName) {
        if (!(in.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || in.mNumFaces == 0 || in.mNumVertices == 0) return;
        triangles_ += in.mNumFaces;
        if (triangles_ > kMaxTriangles)
            throw Error(name_ + ": more than " + std::to_string(kMaxTriangles) +
                        " triangles once node instances are expanded");
        Mesh mesh;
        mesh.name = nodeName.empty() ? std::string(in.mName.C_Str()) : nodeName;
        mesh.material = in.mMaterialIndex < scene_.materials.size() ? in.mMaterialIndex : 0;
        const aiMatrix3x3 normalMatrix = aiMatrix3x3(transform).Inverse().Transpose();
        const bool mirrored = aiMatrix3x3(transform).Determinant() < 0;
        mesh.positions.reserve(in.mNumVertices);
        for (unsigned v = 0; v < in.mNumVertices; ++v) mesh.positions.push_back(toVec3(transform * in.mVertices[v]));
        bool goodNormals = in.mNormals != nullptr;
        if (goodNormals) {
            mesh.normals.reserve(in.mNumVertices);
            for (unsigned v = 0; v < in.mNumVertices && goodNormals; ++v) {
                const Vec3 n = normalize(toVec3(normalMatrix * in.mNormals[v]));
                goodNormals = isFinite(n) && dot(n, n) > 0;
                mesh.normals.push_back(n);
            }
        }
        if (in.mTextureCoords[0]) {
            mesh.uvs.reserve(in.mNumVertices);
            for (unsigned v = 0; v < in.mNumVertices; ++v) {
                // Assimp's origin is the bottom left, the scene model's the top left.
                Vec2 uv{in.mTextureCoords[0][v].x, 1.0f - in.mTextureCoords[0][v].y};
                if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = {};
                mesh.uvs.push_back(uv);
            }
        }
        mesh.indices.reserve(std::size_t(in.mNumFaces) * 3);
        for (unsigned f = 0; f < in.mNumFaces; ++f) {
            const aiFace& face = in.mFaces[f];
            if (face.mNumIndices != 3) continue;  // SortByPType removed these; a validated file has none
            const unsigned a = face.mIndices[0], b = face.mIndices[mirrored ? 2 : 1], c = face.mIndices[mirrored ? 1 : 2];
            if (a >= in.mNumVertices || b >= in.mNumVertices || c >= in.mNumVertices)
                throw Error(name_ + ": mesh '" + mesh.name + "' has a face with a vertex index out of range");
            mesh.indices.insert(mesh.indices.end(), {a, b, c});
        }
        if (mesh.indices.empty()) return;
        if (!goodNormals) generateCreaseNormals(mesh, kCreaseDegrees);
        scene_.meshes.push_back(std::move(mesh));
    }

    const aiScene& ai_;
    std::string name_;
    Scene scene_;
    AssimpMaterialConverter materials_;
    std::size_t triangles_ = 0;
};

Scene fromImporter(Assimp::Importer& importer, const aiScene* ai, const std::string& name,
                   std::optional<std::filesystem::path> baseDir) {
    if (!ai) throw Error(readError(name, importer.GetErrorString()));
    if (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) throw Error(name + ": the model is incomplete (the file is damaged)");
    return SceneBuilder(*ai, name, std::move(baseDir)).build();
}

}  // namespace

bool isAssimpExtension(const std::string& lowerExtension) {
    return std::find(kExtensions.begin(), kExtensions.end(), lowerExtension) != kExtensions.end();
}

std::string assimpExtensions() {
    std::string list;
    for (const char* ext : kExtensions) list += std::string(list.empty() ? "" : ", ") + ext;
    return list;
}

Scene loadAssimp(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error("cannot open '" + path.string() + "': " +
                    (std::filesystem::exists(path, ec) ? "it is not a regular file" : "no such file"));
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw Error("cannot read '" + path.string() + "': " + ec.message());
    if (size > kMaxModelBytes)
        throw Error("'" + path.string() + "' is " + std::to_string(size) + " bytes, more than the " +
                    std::to_string(kMaxModelBytes) + " this importer reads");
    if (size == 0) throw Error("'" + path.string() + "' is empty");
    checkOffCounts(readHead(path, 4096), size, path.string());
    Assimp::Importer importer;
    configure(importer);
    const aiScene* ai = nullptr;
    try {
        // From the path (not from memory) so that formats which name other files find them.
        ai = importer.ReadFile(path.string(), postProcessFlags());
    } catch (const std::exception& e) {
        throw Error(readError(path.string(), e.what()));
    }
    return fromImporter(importer, ai, path.string(), path.parent_path());
}

Scene loadAssimpFromMemory(std::string_view bytes, const std::string& name, const std::string& extensionHint) {
    if (bytes.empty()) throw Error(name + ": the file is empty");
    if (bytes.size() > kMaxModelBytes) throw Error(name + ": the file is too large");
    checkOffCounts(bytes.substr(0, 4096), bytes.size(), name);
    Assimp::Importer importer;
    configure(importer);
    const aiScene* ai = nullptr;
    try {
        ai = importer.ReadFileFromMemory(bytes.data(), bytes.size(), postProcessFlags(), extensionHint.c_str());
    } catch (const std::exception& e) {
        throw Error(readError(name, e.what()));
    }
    return fromImporter(importer, ai, name, std::nullopt);
}

}  // namespace penumbra
