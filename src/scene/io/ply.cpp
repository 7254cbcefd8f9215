// Stanford PLY. The header (ply_header.cpp) is checked against the file's size first; then the
// elements are read in file order: `vertex` (x, y, z; nx, ny, nz; u, v under any of their usual
// names; red, green, blue), `face` (vertex_indices or vertex_index: triangles and polygons,
// fan-triangulated), and anything else skipped, lists included. Every index is checked before
// use. Binary vertices, a fixed-size record each, are decoded on every thread.
#include "scene/io/ply.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <mutex>
#include <vector>

#include "core/big_buffer.h"
#include "core/error.h"
#include "core/log.h"
#include "core/mapped_file.h"
#include "core/parallel.h"
#include "scene/face_check.h"
#include "scene/io/gzip.h"
#include "scene/io/normals.h"
#include "scene/io/ply_body.h"

namespace penumbra {
namespace {

using namespace ply;

constexpr std::size_t kMaxPlyBytes = std::size_t(4) << 30;  // on disk, and after inflating
constexpr float kCreaseDegrees = 60.0f;

// What each vertex property feeds.
enum Slot : std::uint8_t { kNone, kX, kY, kZ, kNX, kNY, kNZ, kU, kV, kRed, kGreen, kBlue, kSlots };

struct VertexLayout {
    std::vector<std::uint8_t> slot;  // per property
    bool normals = false, uvs = false, colours = false;
    float colourScale = 1.0f;  // 1/255 for 8-bit colours
};

// The names the PLY writers in use give each attribute.
VertexLayout vertexLayout(const Element& e, const std::string& name) {
    VertexLayout l;
    l.slot.assign(e.properties.size(), kNone);
    auto claim = [&](std::initializer_list<std::string_view> names, Slot s) {
        for (std::string_view n : names) {
            const int i = e.find(n);
            if (i < 0) continue;
            if (e.properties[std::size_t(i)].isList)
                throw Error(name + ":" + std::to_string(e.line) + ": vertex property '" +
                            std::string(n) + "' is a list; a single value was expected");
            l.slot[std::size_t(i)] = s;
            return true;
        }
        return false;
    };
    if (!claim({"x"}, kX) || !claim({"y"}, kY) || !claim({"z"}, kZ))
        throw Error(name + ":" + std::to_string(e.line) +
                    ": the vertex element needs properties x, y and z");
    // Each property of a group is claimed even when an earlier one is missing (no short-circuit).
    auto all = [](std::initializer_list<bool> claimed) { return std::ranges::all_of(claimed, std::identity{}); };
    l.normals = all({claim({"nx"}, kNX), claim({"ny"}, kNY), claim({"nz"}, kNZ)});
    l.uvs = all({claim({"u", "s", "texture_u", "texture_s"}, kU), claim({"v", "t", "texture_v", "texture_t"}, kV)});
    l.colours = all({claim({"red", "diffuse_red", "r"}, kRed), claim({"green", "diffuse_green", "g"}, kGreen),
                     claim({"blue", "diffuse_blue", "b"}, kBlue)});
    if (l.colours) {
        const int r = e.find("red") >= 0
                          ? e.find("red")
                          : (e.find("diffuse_red") >= 0 ? e.find("diffuse_red") : e.find("r"));
        l.colourScale = isInteger(e.properties[std::size_t(r)].type) ? 1.0f / 255.0f : 1.0f;
    }
    return l;
}

float srgbToLinear(float c) {
    c = std::isfinite(c) ? std::clamp(c, 0.0f, 1.0f) : 0.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// Sums of linear vertex colours, per thread, merged at the end.
struct ColourSum {
    double r = 0, g = 0, b = 0;
    std::uint64_t n = 0;
};

template <typename Reader>
void skipList(Reader& r, const Property& p) {
    const std::int64_t n = r.integer(p.countType);
    if (n < 0) r.fail("a list claims a negative length (" + std::to_string(n) + ")");
    r.skipMany(p.type, std::uint64_t(n));
}

class Importer {
public:
    Importer(std::string_view bytes, std::string name) : bytes_(bytes), name_(std::move(name)) {}

    Scene run() {
        header_ = parseHeader(bytes_, name_);
        const Element* vertices = nullptr;
        for (const Element& e : header_.elements)
            if (e.name == "vertex" && !vertices) vertices = &e;
        if (!vertices) throw Error(name_ + ": the file has no 'vertex' element");
        vertexCount_ = vertices->count;
        layout_ = vertexLayout(*vertices, name_);
        if (header_.format == Format::Ascii)
            readAscii();
        else
            readBinary(header_.format == Format::BinaryBigEndian
                           ? std::endian::native == std::endian::little
                           : std::endian::native == std::endian::big);
        return finish();
    }

private:
    bool isVertex(const Element& e) const { return &e == vertexElement(); }
    const Element* vertexElement() const {
        for (const Element& e : header_.elements)
            if (e.name == "vertex") return &e;
        return nullptr;
    }
    bool isFace(const Element& e) const { return e.name == "face" && !facesSeen_; }

    void allocateVertices() {
        const std::size_t n = std::size_t(vertexCount_);
        auto sized = [n](auto& v) {
            v.reserve(n);
            adviseHugePages(v.data(), n * sizeof(v[0]));
            v.resize(n);
        };
        sized(mesh_.positions);
        if (layout_.normals) sized(mesh_.normals);
        if (layout_.uvs) sized(mesh_.uvs);
    }

    template <typename Reader>
    void readVertex(Reader& r, const Element& e, std::size_t i, ColourSum& colour) {
        double v[kSlots] = {};
        for (std::size_t k = 0; k < e.properties.size(); ++k) {
            const Property& p = e.properties[k];
            if (p.isList)
                skipList(r, p);
            else if (layout_.slot[k] != kNone)
                v[layout_.slot[k]] = r.real(p.type);
            else
                r.skip(p.type);
        }
        const Vec3 pos{float(v[kX]), float(v[kY]), float(v[kZ])};
        if (!isFinite(pos)) r.fail("a coordinate is not a finite number");
        mesh_.positions[i] = pos;
        if (layout_.normals) mesh_.normals[i] = {float(v[kNX]), float(v[kNY]), float(v[kNZ])};
        if (layout_.uvs) {
            // PLY's v, like OBJ's, runs up from the bottom row; the scene's runs down.
            Vec2 uv{float(v[kU]), 1.0f - float(v[kV])};
            mesh_.uvs[i] = std::isfinite(uv.x) && std::isfinite(uv.y) ? uv : Vec2{};
        }
        if (layout_.colours) {
            colour.r += srgbToLinear(float(v[kRed]) * layout_.colourScale);
            colour.g += srgbToLinear(float(v[kGreen]) * layout_.colourScale);
            colour.b += srgbToLinear(float(v[kBlue]) * layout_.colourScale);
            ++colour.n;
        }
    }

    template <typename Reader>
    void readVertices(Reader& r, const Element& e) {
        for (std::uint64_t i = 0; i < e.count; ++i) {
            r.place() = {&name_, &e, i};
            readVertex(r, e, std::size_t(i), colour_);
        }
    }

    // Fixed-size binary records: every thread decodes its own share, straight from its offset.
    void readVerticesParallel(BinaryReader& r, const Element& e, bool swap) {
        const std::size_t size = e.recordBytes();
        if (e.count > r.left() / std::max<std::size_t>(size, 1)) {
            r.place() = {&name_, &e, r.left() / std::max<std::size_t>(size, 1)};
            r.fail("the file ends inside it");
        }
        const char* start = r.position();
        std::mutex merge;
        parallelFor(std::size_t(e.count), 64 * 1024, [&](std::size_t lo, std::size_t hi) {
            BinaryReader local(std::string_view(start + lo * size, (hi - lo) * size), swap, name_);
            ColourSum sum;
            for (std::size_t i = lo; i < hi; ++i) {
                local.place() = {&name_, &e, i};
                readVertex(local, e, i, sum);
            }
            std::lock_guard lock(merge);
            colour_.r += sum.r;
            colour_.g += sum.g;
            colour_.b += sum.b;
            colour_.n += sum.n;
        });
        r.seek(start + std::size_t(e.count) * size);
    }

    template <typename Reader>
    void readFaces(Reader& r, const Element& e) {
        int list = e.find("vertex_indices");
        if (list < 0) list = e.find("vertex_index");
        if (list < 0 || !e.properties[std::size_t(list)].isList)
            throw Error(name_ + ":" + std::to_string(e.line) +
                        ": the face element needs a list property vertex_indices");
        if (!isInteger(e.properties[std::size_t(list)].type))
            throw Error(name_ + ":" + std::to_string(e.line) +
                        ": vertex_indices must be a list of integers");
        facesSeen_ = true;
        mesh_.indices.reserve(std::size_t(e.count) * 3);
        adviseHugePages(mesh_.indices.data(), std::size_t(e.count) * 3 * sizeof(std::uint32_t));
        std::vector<std::uint32_t> corners;
        for (std::uint64_t f = 0; f < e.count; ++f) {
            r.place() = {&name_, &e, f};
            for (std::size_t k = 0; k < e.properties.size(); ++k) {
                const Property& p = e.properties[k];
                if (int(k) != list) {
                    p.isList ? skipList(r, p) : r.skip(p.type);
                    continue;
                }
                const std::int64_t n = r.integer(p.countType);
                if (n < 0)
                    r.fail("a face claims a negative number of corners (" + std::to_string(n) +
                           ")");
                if (n < 3) {
                    r.skipMany(p.type, std::uint64_t(n));
                    skipped_.add(FaceDefect::Degenerate);
                    continue;
                }
                corners.clear();
                for (std::int64_t c = 0; c < n; ++c) {
                    const std::int64_t v = r.integer(p.type);
                    if (v < 0 || std::uint64_t(v) >= vertexCount_)
                        r.fail("refers to vertex " + std::to_string(v) + ", but the file has " +
                               std::to_string(vertexCount_) + " vertices (numbered from 0)");
                    corners.push_back(std::uint32_t(v));
                }
                for (std::size_t c = 1; c + 1 < corners.size(); ++c)
                    mesh_.indices.insert(mesh_.indices.end(),
                                         {corners[0], corners[c], corners[c + 1]});
            }
        }
    }

    template <typename Reader>
    void skipElement(Reader& r, const Element& e) {
        if (e.properties.empty()) return;
        for (std::uint64_t i = 0; i < e.count; ++i) {
            r.place() = {&name_, &e, i};
            for (const Property& p : e.properties) p.isList ? skipList(r, p) : r.skip(p.type);
        }
    }

    void readAscii() {
        AsciiReader r(bytes_.substr(header_.bodyOffset), header_.lines + 1, name_);
        for (const Element& e : header_.elements) {
            if (isVertex(e)) {
                allocateVertices();
                readVertices(r, e);
            } else if (isFace(e)) {
                readFaces(r, e);
            } else {
                skipElement(r, e);
            }
        }
    }

    void readBinary(bool swap) {
        BinaryReader r(bytes_.substr(header_.bodyOffset), swap, name_);
        for (const Element& e : header_.elements) {
            if (isVertex(e)) {
                allocateVertices();
                if (e.hasLists())
                    readVertices(r, e);
                else
                    readVerticesParallel(r, e, swap);
            } else if (isFace(e)) {
                readFaces(r, e);
            } else if (!e.hasLists()) {
                r.place() = {&name_, &e, 0};
                r.skipMany(Type::UInt8, e.count * e.recordBytes());
            } else {
                skipElement(r, e);
            }
        }
    }

    Scene finish() {
        if (!facesSeen_)
            throw Error(name_ +
                        ": the file has no 'face' element (point clouds are not supported)");
        dropBadTriangles(mesh_, skipped_);
        if (mesh_.indices.empty())
            throw Error(name_ + ": no face can be rendered: the file has " +
                        (skipped_.total() > 0 ? skipped_.describe() : std::string("no faces")));
        skipped_.warn(name_);
        bool goodNormals = layout_.normals;
        for (Vec3& n : mesh_.normals) {
            n = normalize(n);
            if (!isFinite(n) || dot(n, n) == 0) goodNormals = false;
        }
        if (!goodNormals) generateCreaseNormals(mesh_, kCreaseDegrees);

        Scene scene;
        scene.name = name_;
        Material m;
        m.name = "default";
        if (colour_.n > 0) {
            // The scene has no vertex colours: the mesh gets their average as its albedo.
            const double n = double(colour_.n);
            m.albedo = {float(colour_.r / n), float(colour_.g / n), float(colour_.b / n)};
        }
        scene.materials.push_back(std::move(m));
        mesh_.name = name_;
        mesh_.material = 0;
        scene.meshes.push_back(std::move(mesh_));
        scene.camera = cameraFittingBounds(scene.bounds());
        scene.validate();
        return scene;
    }

    std::string_view bytes_;
    std::string name_;
    Header header_;
    VertexLayout layout_;
    std::uint64_t vertexCount_ = 0;
    bool facesSeen_ = false;
    SkippedFaces skipped_;
    ColourSum colour_;
    Mesh mesh_;
};

}  // namespace

namespace ply {

std::string AsciiReader::printable(std::string_view s) {
    std::string out(s.substr(0, 40));
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
    return s.size() > 40 ? out + "..." : out;
}

void BinaryReader::fail(const std::string& what) const {
    std::string where = *place_.file + ": ";
    if (place_.element) where += place_.element->name + " " + std::to_string(place_.index) + ": ";
    throw Error(where + what);
}

void AsciiReader::fail(const std::string& what) const {
    std::string where = *place_.file + ":" + std::to_string(line_) + ": ";
    if (place_.element) where += place_.element->name + " " + std::to_string(place_.index) + ": ";
    throw Error(where + what);
}

}  // namespace ply

Scene loadPlyFromMemory(std::string_view bytes, const std::string& name) {
    if (isGzip(bytes)) {
        const std::string inflated = gunzip(bytes, kMaxPlyBytes, name);
        return Importer(inflated, name).run();
    }
    return Importer(bytes, name).run();
}

Scene loadPly(const std::filesystem::path& path) {
    const MappedFile file(path, kMaxPlyBytes, "PLY file");
    return loadPlyFromMemory(file.bytes(), path.filename().string());
}

}  // namespace penumbra
