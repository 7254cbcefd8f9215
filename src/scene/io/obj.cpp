// Wavefront OBJ + MTL. The OBJ text is parsed on every thread (obj_parse.cpp), which checks
// every number and index as it reads them; MTL libraries go through tinyobjloader's MTL
// reader. Polygons are triangulated here, faces are grouped into one Mesh per material, and
// missing normals are generated with a crease angle.
#include "scene/io/obj.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <streambuf>
#include <system_error>

#include "core/error.h"
#include "core/big_buffer.h"
#include "core/log.h"
#include "core/mapped_file.h"
#include "scene/face_check.h"
#include "scene/io/normals.h"
#include "scene/io/obj_parse.h"
#include "scene/io/phong.h"
#include "scene/io/texture_io.h"

namespace penumbra {
namespace {

constexpr std::uintmax_t kMaxObjBytes = std::uintmax_t(4) << 30;
constexpr std::uintmax_t kMaxMtlBytes = std::uintmax_t(64) << 20;
constexpr float kCreaseDegrees = 60.0f;
// Polygons with more corners than this are fan-triangulated (ear clipping is quadratic).
constexpr std::size_t kMaxEarClipCorners = 64;
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

std::string readWholeFile(const std::filesystem::path& path, std::uintmax_t maxBytes, const char* what) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error("cannot open " + std::string(what) + " '" + path.string() + "': no such file");
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw Error("cannot read '" + path.string() + "': " + ec.message());
    if (size > maxBytes)
        throw Error("'" + path.string() + "' is too large (" + std::to_string(size >> 20) + " MiB; the limit is " +
                    std::to_string(maxBytes >> 20) + " MiB)");
    std::ifstream in(path, std::ios::binary);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    if (!in || !in.read(bytes.data(), static_cast<std::streamsize>(size)))
        throw Error("cannot read '" + path.string() + "'");
    return bytes;
}

// An istream over memory we already hold, without copying it.
struct MemoryBuf : std::streambuf {
    MemoryBuf(const char* data, std::size_t size) {
        char* p = const_cast<char*>(data);  // streambuf wants char*; we never write through it
        setg(p, p, p + size);
    }
};

// Supplies MTL text to tinyobjloader: from `text` (in-memory loads) or from files next to the
// OBJ. Remembers which libraries were missing so the warning can say so once.
class MtlReader : public tinyobj::MaterialReader {
public:
    MtlReader(std::filesystem::path baseDir, std::optional<std::string_view> text)
        : baseDir_(std::move(baseDir)), text_(text) {}

    bool operator()(const std::string& matId, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* matMap, std::string* warn, std::string* err) override {
        std::string bytes;
        if (text_) {
            if (text_->empty()) {
                missing_.push_back(matId);
                return false;
            }
            bytes.assign(text_->data(), text_->size());
        } else {
            std::string name = matId;
            std::replace(name.begin(), name.end(), '\\', '/');
            std::filesystem::path path = baseDir_ / name;
            std::error_code ec;
            if (!std::filesystem::is_regular_file(path, ec)) {
                missing_.push_back(matId);
                return false;
            }
            bytes = readWholeFile(path, kMaxMtlBytes, "material library");
        }
        MemoryBuf buf(bytes.data(), bytes.size());
        std::istream in(&buf);
        tinyobj::LoadMtl(matMap, materials, &in, warn, err);
        return true;
    }

    const std::vector<std::string>& missing() const { return missing_; }

private:
    std::filesystem::path baseDir_;
    std::optional<std::string_view> text_;
    std::vector<std::string> missing_;
};

std::string clampName(std::string s) {
    if (s.size() > 80) s = s.substr(0, 77) + "...";
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 32) c = '?';
    return s;
}

// Passes tinyobjloader's warnings on, once each and at most a few, prefixed with the file.
void forwardWarnings(const std::string& name, const std::string& warn) {
    std::istringstream lines(warn);
    std::string line;
    std::vector<std::string> seen;
    std::size_t extra = 0;
    while (std::getline(lines, line)) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '.')) line.pop_back();
        if (line.empty() || line.starts_with("Material file [") || line.starts_with("Failed to load material file"))
            continue;  // reported by the loader itself, more plainly
        if (std::find(seen.begin(), seen.end(), line) != seen.end()) continue;
        if (seen.size() >= 8) {
            ++extra;
            continue;
        }
        seen.push_back(line);
        logWarning(name + ": " + clampName(line));
    }
    if (extra > 0) logWarning(name + ": " + std::to_string(extra) + " more warnings");
}

float clamp01(float v) { return std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f; }
Vec3 clamp01(const float* v) { return {clamp01(v[0]), clamp01(v[1]), clamp01(v[2])}; }

class ObjImporter {
public:
    ObjImporter(std::string_view text, std::filesystem::path baseDir, std::string name)
        : text_(text), baseDir_(std::move(baseDir)), name_(std::move(name)) {}

    Scene run(MtlReader& mtl) {
        const obj::Parsed parsed = obj::parse(text_, name_);
        std::vector<tinyobj::material_t> materials;
        std::map<std::string, int> materialIndex;
        std::string warn;
        loadLibraries(parsed.libraries, mtl, materials, materialIndex, warn);
        forwardWarnings(name_, warn);
        for (const std::string& lib : mtl.missing())
            logWarning(name_ + ": material library '" + clampName(lib) +
                       "' not found; its materials are replaced by grey (0.8)");

        scene_.name = name_;
        convertMaterials(materials);
        collectFaces(parsed, materialIds(parsed, materialIndex), materials.size());
        const bool anyFace = std::any_of(builders_.begin(), builders_.end(),
                                         [](const Builder& b) { return !b.mesh.indices.empty(); });
        if (!anyFace && skipped_.total() > 0)
            throw Error(name_ + ": no face can be rendered: the file has " + skipped_.describe());
        skipped_.warn(name_);

        for (Builder& b : builders_) {
            if (b.mesh.indices.empty()) continue;
            if (!b.allNormals) generateCreaseNormals(b.mesh, kCreaseDegrees);
            if (!b.anyUv) b.mesh.uvs.clear();
            scene_.meshes.push_back(std::move(b.mesh));
        }
        if (scene_.meshes.empty()) throw Error(name_ + ": the file has no faces (triangles or polygons)");
        if (scene_.materials.empty()) scene_.materials.push_back(greyMaterial());
        scene_.camera = cameraFittingBounds(scene_.bounds());
        scene_.validate();
        return std::move(scene_);
    }

private:
    struct Builder {
        Mesh mesh;
        bool allNormals = true;
        bool anyUv = false;
    };
    // Chained entries of the (position, uv, normal) -> vertex map, one chain per OBJ position.
    struct VertexKey {
        int vt, vn;
        std::uint32_t builder, vertex, next;
    };

    static Material greyMaterial() {
        Material m;
        m.name = "default";
        m.albedo = Vec3{0.8f};
        return m;
    }

    // Each library once, in the order the file names them; tinyobjloader's MTL reader keeps the
    // first material of each name.
    static void loadLibraries(const std::vector<std::string>& libraries, MtlReader& mtl,
                              std::vector<tinyobj::material_t>& materials, std::map<std::string, int>& index,
                              std::string& warn) {
        std::vector<std::string> done;
        for (const std::string& lib : libraries) {
            if (std::find(done.begin(), done.end(), lib) != done.end()) continue;
            done.push_back(lib);
            std::string err;
            mtl(lib, &materials, &index, &warn, &err);
            if (!err.empty()) warn += err;
        }
    }

    // The material of each `usemtl` run: an index into the MTL materials, or -1 (grey) for a
    // name no library defines (warned about once per name).
    std::vector<int> materialIds(const obj::Parsed& parsed, const std::map<std::string, int>& index) {
        std::vector<int> ids;
        std::vector<std::string> unknown;
        for (const obj::MaterialUse& use : parsed.materials) {
            auto it = index.find(use.name);
            ids.push_back(it == index.end() ? -1 : it->second);
            if (it == index.end() && !use.name.empty() &&
                std::find(unknown.begin(), unknown.end(), use.name) == unknown.end()) {
                unknown.push_back(use.name);
                logWarning(name_ + ": material '" + clampName(use.name) + "' is not defined; using grey (0.8)");
            }
        }
        return ids;
    }

    TextureRef texture(const std::string& file, const tinyobj::texture_option_t& opt, bool srgb) {
        if (file.empty()) return {};
        std::string rel = file;
        std::replace(rel.begin(), rel.end(), '\\', '/');
        const std::string key = rel + (srgb ? "|s" : "|l");
        auto it = textureCache_.find(key);
        int index;
        if (it != textureCache_.end()) {
            index = it->second;
        } else {
            std::string why;
            std::optional<Texture> tex = loadTextureFile(baseDir_ / rel, srgb, &why);
            if (!tex) {
                logWarning(name_ + ": texture '" + clampName(rel) + "': " + why + "; using a checker");
                tex = missingTexture(rel);
                tex->srgb = srgb;
            }
            tex->name = rel;
            index = static_cast<int>(scene_.textures.size());
            scene_.textures.push_back(std::move(*tex));
            textureCache_.emplace(key, index);
        }
        TextureRef ref;
        ref.texture = index;
        ref.wrapU = ref.wrapV = opt.clamp ? Wrap::ClampToEdge : Wrap::Repeat;
        return ref;
    }

    void convertMaterials(const std::vector<tinyobj::material_t>& in) {
        for (const tinyobj::material_t& t : in) {
            Material m;
            m.name = t.name;
            m.albedo = clamp01(t.diffuse);
            for (int k = 0; k < 3; ++k)
                m.emission[k] = std::isfinite(t.emission[k]) ? std::max(0.0f, float(t.emission[k])) : 0.0f;
            const Vec3 ks = clamp01(t.specular);
            const float ns = std::isfinite(t.shininess) ? std::max(0.0f, float(t.shininess)) : 0.0f;
            // Blinn-Phong exponent to perceptual roughness (alpha = sqrt(2 / (Ns + 2))); no
            // specular colour means a purely diffuse surface.
            m.roughness = maxComponent(ks) > 0 ? roughnessFromPhongExponent(ns) : 1.0f;
            m.metallic = 0.0f;
            m.specular = maxComponent(ks) > 0 ? 1.0f : 0.0f;  // a clear coat over Kd
            const float ni = float(t.ior);
            m.ior = (std::isfinite(ni) && ni > 1.0f) ? std::min(ni, 4.0f) : 1.5f;
            m.opacity = std::isfinite(t.dissolve) ? clamp01(float(t.dissolve)) : 1.0f;
            const int illum = t.illum;
            if (illum == 5 && maxComponent(ks) > 0) {  // Fresnel mirror
                m.metallic = 1.0f;
                m.albedo = ks;
            }
            if (illum == 7 || ((illum == 4 || illum == 6 || illum == 9) && m.opacity < 1.0f)) {  // glass
                m.transmission = 1.0f;
                m.opacity = 1.0f;  // refraction, not a cut-out
                const Vec3 tf = clamp01(t.transmittance);
                m.albedo = maxComponent(tf) > 0 ? tf : Vec3{1.0f};
                if (!(std::isfinite(ni) && ni > 1.0f)) m.ior = 1.5f;
            }
            m.albedoTexture = texture(t.diffuse_texname, t.diffuse_texopt, true);
            m.emissionTexture = texture(t.emissive_texname, t.emissive_texopt, true);
            m.normalTexture = texture(t.normal_texname, t.normal_texopt, false);
            if (m.emissionTexture.present() && !m.isEmissive()) m.emission = Vec3{1.0f};
            scene_.materials.push_back(std::move(m));
        }
    }

    std::uint32_t builderFor(int materialId, std::size_t materialCount) {
        std::uint32_t material;
        if (materialId >= 0 && std::size_t(materialId) < materialCount) {
            material = static_cast<std::uint32_t>(materialId);
        } else {
            if (greyIndex_ == kNone) {
                greyIndex_ = static_cast<std::uint32_t>(scene_.materials.size());
                scene_.materials.push_back(greyMaterial());
            }
            material = greyIndex_;
        }
        if (builderOfMaterial_.size() <= material) builderOfMaterial_.resize(material + 1, kNone);
        if (builderOfMaterial_[material] == kNone) {
            builderOfMaterial_[material] = static_cast<std::uint32_t>(builders_.size());
            Builder b;
            b.mesh.name = scene_.materials[material].name;
            b.mesh.material = material;
            reserveFor(b.mesh, material);
            builders_.push_back(std::move(b));
        }
        return builderOfMaterial_[material];
    }

    // Room for a material's mesh before it grows: its share of the file's triangles and of its
    // positions (a little more, for vertices split by UV seams), so a million-triangle mesh
    // is not copied a dozen times on the way up.
    void reserveFor(Mesh& mesh, std::uint32_t material) {
        const std::size_t tris = material < trianglesOfMaterial_.size() ? trianglesOfMaterial_[material] : 0;
        if (tris == 0 || totalTriangles_ == 0) return;
        const double share = double(tris) / double(totalTriangles_);
        const std::size_t vertices =
            std::min<std::size_t>(3 * tris, std::size_t(double(positionCount_) * share * 1.25) + 64);
        reserveHuge(mesh.indices, 3 * tris);
        reserveHuge(mesh.positions, vertices);
        reserveHuge(mesh.normals, vertices);
        reserveHuge(mesh.uvs, vertices);
    }

    // Triangles per material (before triangulation drops any), for reserveFor.
    void countTriangles(const obj::Parsed& a, const std::vector<int>& materialIds, std::size_t materialCount) {
        trianglesOfMaterial_.assign(materialCount + 1, 0);
        positionCount_ = a.positions.size() / 3;
        std::size_t use = 0;
        int materialId = -1;
        for (std::size_t f = 0; f < a.faceCount(); ++f) {
            while (use < a.materials.size() && a.materials[use].firstFace <= f) materialId = materialIds[use++];
            const std::size_t count = a.faceStart[f + 1] - a.faceStart[f];
            if (count < 3) continue;
            const std::size_t m = materialId >= 0 && std::size_t(materialId) < materialCount ? std::size_t(materialId)
                                                                                            : materialCount;
            trianglesOfMaterial_[m] += count - 2;
            totalTriangles_ += count - 2;
        }
    }

    std::uint32_t vertexFor(std::uint32_t builder, const obj::Corner& idx, const obj::Parsed& a) {
        const auto v = static_cast<std::uint32_t>(idx.v);
        for (std::uint32_t e = chainHead_[v]; e != kNone; e = keys_[e].next)
            if (keys_[e].builder == builder && keys_[e].vt == idx.vt && keys_[e].vn == idx.vn)
                return keys_[e].vertex;
        Builder& b = builders_[builder];
        Mesh& m = b.mesh;
        const auto vertex = static_cast<std::uint32_t>(m.positions.size());
        if (vertex == kNone) throw Error(name_ + ": too many vertices in one material");
        m.positions.push_back({a.positions[3 * v], a.positions[3 * v + 1], a.positions[3 * v + 2]});
        Vec3 n{};
        if (idx.vn >= 0) {
            const auto i = std::size_t(idx.vn);
            n = {a.normals[3 * i], a.normals[3 * i + 1], a.normals[3 * i + 2]};
        }
        if (!isFinite(n) || dot(n, n) == 0) b.allNormals = false;
        m.normals.push_back(n);
        Vec2 uv{};
        if (idx.vt >= 0) {
            const auto i = std::size_t(idx.vt);
            // OBJ's v runs up from the bottom row; the scene's (like glTF's) runs down from the top.
            uv = {a.texcoords[2 * i], 1.0f - a.texcoords[2 * i + 1]};
            if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = {};
            b.anyUv = true;
        }
        m.uvs.push_back(uv);
        keys_.push_back({idx.vt, idx.vn, builder, vertex, chainHead_[v]});
        chainHead_[v] = static_cast<std::uint32_t>(keys_.size() - 1);
        return vertex;
    }

    // Triangulates one polygon (corner positions `p`) into corner-index triples.
    void triangulate(const std::vector<Vec3>& p, std::vector<std::uint32_t>& out) {
        out.clear();
        const std::size_t n = p.size();
        if (n == 3) {
            out = {0, 1, 2};
            return;
        }
        if (n == 4) {  // split along the shorter diagonal
            Vec3 d02 = p[2] - p[0], d13 = p[3] - p[1];
            if (dot(d02, d02) <= dot(d13, d13))
                out = {0, 1, 2, 0, 2, 3};
            else
                out = {0, 1, 3, 1, 2, 3};
            return;
        }
        // Newell normal, then ear clipping in the polygon's plane (fan for huge or flat ones).
        Vec3 normal{};
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 a = p[i], b = p[(i + 1) % n];
            normal += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
        }
        auto fan = [&] {
            for (std::uint32_t i = 1; i + 1 < n; ++i) out.insert(out.end(), {0u, i, i + 1});
        };
        if (n > kMaxEarClipCorners || !(dot(normal, normal) > 0) || !isFinite(normal)) return fan();
        std::vector<std::uint32_t> ring(n);
        for (std::uint32_t i = 0; i < n; ++i) ring[i] = i;
        auto convex = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
            return dot(cross(p[b] - p[a], p[c] - p[b]), normal) > 0;
        };
        auto inside = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t q) {
            return dot(cross(p[b] - p[a], p[q] - p[a]), normal) >= 0 &&
                   dot(cross(p[c] - p[b], p[q] - p[b]), normal) >= 0 &&
                   dot(cross(p[a] - p[c], p[q] - p[c]), normal) >= 0;
        };
        std::size_t guard = 0;
        while (ring.size() > 3 && guard < 2 * n * n) {
            bool clipped = false;
            for (std::size_t i = 0; i < ring.size(); ++i, ++guard) {
                std::uint32_t a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i],
                              c = ring[(i + 1) % ring.size()];
                if (!convex(a, b, c)) continue;
                bool ear = true;
                for (std::uint32_t q : ring)
                    if (q != a && q != b && q != c && !(p[q] == p[a] || p[q] == p[b] || p[q] == p[c]) &&
                        inside(a, b, c, q)) {
                        ear = false;
                        break;
                    }
                if (!ear) continue;
                out.insert(out.end(), {a, b, c});
                ring.erase(ring.begin() + std::ptrdiff_t(i));
                clipped = true;
                break;
            }
            if (!clipped) break;  // self-intersecting: fan the rest
        }
        for (std::size_t i = 1; i + 1 < ring.size(); ++i) out.insert(out.end(), {ring[0], ring[i], ring[i + 1]});
    }

    void collectFaces(const obj::Parsed& a, const std::vector<int>& materialIds, std::size_t materialCount) {
        const std::size_t nv = a.positions.size() / 3;
        countTriangles(a, materialIds, materialCount);
        chainHead_ = hugeVector<std::uint32_t>(nv, kNone);
        reserveHuge(keys_, nv + nv / 4);
        std::vector<Vec3> corners;
        std::vector<std::uint32_t> tris;
        std::size_t use = 0;  // the `usemtl` run in force
        int materialId = -1;
        for (std::size_t f = 0; f < a.faceCount(); ++f) {
            while (use < a.materials.size() && a.materials[use].firstFace <= f) materialId = materialIds[use++];
            const obj::Corner* idx = &a.corners[a.faceStart[f]];
            const std::size_t count = a.faceStart[f + 1] - a.faceStart[f];
            if (count < 3) {
                skipped_.add(FaceDefect::Degenerate);
                continue;
            }
            corners.clear();
            for (std::size_t k = 0; k < count; ++k) {
                const auto v = std::size_t(idx[k].v);
                corners.push_back({a.positions[3 * v], a.positions[3 * v + 1], a.positions[3 * v + 2]});
            }
            triangulate(corners, tris);
            const std::uint32_t builder = builderFor(materialId, materialCount);
            for (std::size_t t = 0; t + 2 < tris.size(); t += 3) {
                const std::uint32_t i0 = tris[t], i1 = tris[t + 1], i2 = tris[t + 2];
                const FaceDefect d = idx[i0].v == idx[i1].v || idx[i1].v == idx[i2].v || idx[i0].v == idx[i2].v
                                         ? FaceDefect::Degenerate
                                         : faceDefect(corners[i0], corners[i1], corners[i2]);
                if (d != FaceDefect::None) {
                    skipped_.add(d);
                    continue;
                }
                for (std::uint32_t k : {i0, i1, i2})
                    builders_[builder].mesh.indices.push_back(vertexFor(builder, idx[k], a));
            }
        }
    }

    std::string_view text_;
    std::filesystem::path baseDir_;
    std::string name_;
    Scene scene_;
    std::vector<Builder> builders_;
    std::vector<std::uint32_t> builderOfMaterial_;
    std::uint32_t greyIndex_ = kNone;
    std::vector<std::size_t> trianglesOfMaterial_;  // [materialCount]: faces without a known material
    std::size_t totalTriangles_ = 0, positionCount_ = 0;
    std::vector<std::uint32_t> chainHead_;
    std::vector<VertexKey> keys_;
    std::map<std::string, int> textureCache_;
    SkippedFaces skipped_;
};

}  // namespace

Scene loadObj(const std::filesystem::path& path) {
    const MappedFile file(path, kMaxObjBytes, "OBJ file");
    MtlReader mtl(path.parent_path(), std::nullopt);
    return ObjImporter(file.bytes(), path.parent_path(), path.filename().string()).run(mtl);
}

Scene loadObjFromMemory(std::string_view obj, std::string_view mtl, const std::filesystem::path& baseDir,
                        const std::string& name) {
    MtlReader reader(baseDir, mtl);
    return ObjImporter(obj, baseDir, name).run(reader);
}

}  // namespace penumbra
