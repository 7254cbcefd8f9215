#include "scene/io/assimp_loader.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cctype>
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
// OFF file spends at least two bytes a number ("0 "), so the counts of a .off file are checked
// against the file size first (Assimp reads a file with the importer its extension names).
// Other formats are bounded only by the allocation failing (see readError).
void checkOffCounts(std::string_view head, std::uintmax_t fileSize, const std::string& name) {
    const std::size_t magic = head.find("OFF");
    if (magic == std::string_view::npos || head.substr(magic, 10) == "OFF BINARY") return;
    // The first two runs of digits after "OFF" (comment lines skipped) are the vertex and face
    // counts, however they are separated: Assimp reads "OFF100 1(0" as 100 vertices, 1 face.
    std::uintmax_t counts[2] = {0, 0};
    int found = 0;
    for (std::size_t i = magic + 3; i < head.size() && found < 2;) {
        if (head[i] == '#' && (i == 0 || head[i - 1] == '\n')) {
            i = head.find('\n', i);
            if (i == std::string_view::npos) break;
            continue;
        }
        if (!std::isdigit(static_cast<unsigned char>(head[i]))) {
            ++i;
            continue;
        }
        std::uintmax_t n = 0;
        for (; i < head.size() && std::isdigit(static_cast<unsigned char>(head[i])); ++i)
            n = std::min<std::uintmax_t>(n * 10 + std::uintmax_t(head[i] - '0'), std::uintmax_t(1) << 60);
        counts[found++] = n;
    }
    const double minimum = double(counts[0]) * 6.0 + double(counts[1]) * 2.0;
    if (minimum > double(fileSize))
        throw Error(name + ": the OFF header declares " + std::to_string(counts[0]) + " vertices and " +
                    std::to_string(counts[1]) + " faces, more than the file's " + std::to_string(fileSize) +
                    " bytes can hold (truncated or corrupt)");
}

// Debian's Assimp 5.2 dereferences a null pointer on a Collada array (<float_array>, ...) with
// no count attribute, which Collada requires; such files are refused before Assimp sees them.
// (Both found by fuzz_assimp; inputs in tests/fuzz/corpus/assimp.)
void checkColladaArrays(std::string_view text, const std::string& name) {
    for (std::size_t at = text.find("_array"); at != std::string_view::npos; at = text.find("_array", at + 6)) {
        const std::size_t open = text.rfind('<', at);
        if (open == std::string_view::npos || at - open > 16 || text[open + 1] == '/') continue;
        const std::string_view tag = text.substr(open + 1, at - open - 1);
        if (tag.find_first_of(" \t\r\n>\"=") != std::string_view::npos) continue;  // not this element's name
        const std::size_t close = text.find('>', at);
        const std::string_view attributes = text.substr(at, close == std::string_view::npos ? close : close - at);
        if (attributes.find("count") == std::string_view::npos)
            throw Error(name + ": a Collada <" + std::string(tag) + "_array> has no count attribute (the file is damaged)");
    }
    // It also loops, allocating without end, on an index list (<p>, <v>, <vcount>) holding
    // anything but unsigned integers, which is all Collada allows there.
    for (const std::string_view open : {std::string_view("<p>"), std::string_view("<v>"), std::string_view("<vcount>")}) {
        for (std::size_t at = text.find(open); at != std::string_view::npos; at = text.find(open, at + 1)) {
            const std::size_t begin = at + open.size(), end = text.find('<', begin);
            const std::string_view list = text.substr(begin, end == std::string_view::npos ? end : end - begin);
            if (list.find_first_not_of("0123456789 \t\r\n") != std::string_view::npos)
                throw Error(name + ": a Collada " + std::string(open) + " index list holds something other than "
                                   "unsigned integers (the file is damaged)");
        }
    }
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
    if (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE)
        throw Error(name + ": the file holds no complete model (no meshes, or damaged)");
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
    const auto size = checkedFileSize(path, kMaxModelBytes);
    if (size == 0) throw Error("'" + path.string() + "' is empty");
    std::string ext = path.extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".off") checkOffCounts(readHead(path, 4096), size, path.string());
    if (ext == ".dae") checkColladaArrays(readFileBytes(path, kMaxModelBytes), path.string());
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
    if (extensionHint == "off") checkOffCounts(bytes.substr(0, 4096), bytes.size(), name);
    if (extensionHint == "dae") checkColladaArrays(bytes, name);
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
