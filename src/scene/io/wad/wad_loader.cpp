// Builds a Scene from one Doom map: walls with Doom's pegging rules, sector floors and ceilings
// (triangulate.cpp), sky ceilings as emitters, the player start as the camera and lamps as
// point lights. Doom units become metres at 32 units per metre; Doom (x, y, z up) becomes
// (x, z, -y) here, with y up.
#include "scene/io/wad/wad_loader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <tuple>

#include "core/error.h"
#include "core/log.h"
#include "scene/io/wad/map.h"
#include "scene/io/wad/textures.h"
#include "scene/io/wad/triangulate.h"
#include "scene/io/wad/units.h"
#include "scene/walk/wad_walk_map.h"
#include "scene/walk/walk_physics.h"

namespace penumbra {
namespace {
using namespace wad;

constexpr double kEyeHeight = walk::kEyeHeight;
constexpr Vec3 kSkyRadiance{1.0f, 1.0f, 1.1f};
constexpr std::int64_t kFillBudget = 50'000'000;  // slab sweep work units per map
constexpr std::size_t kMaxLights = 4096;

Vec3 toWorld(double x, double height, double y) { return mapToScene(x, y, height); }

bool isSky(const std::string& flat) { return flat == "F_SKY1"; }
bool hasTexture(const std::string& name) { return !name.empty() && name != "-"; }

struct LampType {
    std::uint16_t type;
    Vec3 color;
    float intensity;  // candela
    float height;     // Doom units above the floor
    const char* name;
};
// Light-emitting decorations of Doom and Doom II (thing type numbers from the Doom source).
constexpr LampType kLamps[] = {
    {2028, {1.0f, 0.9f, 0.7f}, 40.0f, 44.0f, "floor lamp"},
    {85, {0.85f, 0.9f, 1.0f}, 40.0f, 72.0f, "tall techno lamp"},
    {86, {0.85f, 0.9f, 1.0f}, 30.0f, 52.0f, "short techno lamp"},
    {34, {1.0f, 0.7f, 0.35f}, 4.0f, 12.0f, "candle"},
    {35, {1.0f, 0.75f, 0.4f}, 15.0f, 56.0f, "candelabra"},
    {44, {0.35f, 0.5f, 1.0f}, 25.0f, 64.0f, "tall blue torch"},
    {45, {0.4f, 1.0f, 0.4f}, 25.0f, 64.0f, "tall green torch"},
    {46, {1.0f, 0.35f, 0.25f}, 25.0f, 64.0f, "tall red torch"},
    {55, {0.35f, 0.5f, 1.0f}, 18.0f, 40.0f, "short blue torch"},
    {56, {0.4f, 1.0f, 0.4f}, 18.0f, 40.0f, "short green torch"},
    {57, {1.0f, 0.35f, 0.25f}, 18.0f, 40.0f, "short red torch"},
    {70, {1.0f, 0.6f, 0.3f}, 25.0f, 40.0f, "burning barrel"},
};

// The sector containing a point: the nearest line crossed by a ray towards +x decides, by the
// side of it the point is on. -1 when the point is outside the map.
int sectorAt(const MapData& map, double px, double py) {
    double best = INFINITY;
    int sector = -1;
    for (const Linedef& line : map.linedefs) {
        const Vertex& a = map.vertices[line.v1];
        const Vertex& b = map.vertices[line.v2];
        if ((a.y > py) == (b.y > py)) continue;
        double xi = a.x + (py - a.y) * double(b.x - a.x) / double(b.y - a.y);
        if (xi < px || xi >= best) continue;
        best = xi;
        double side = double(b.x - a.x) * (py - a.y) - double(b.y - a.y) * (px - a.x);
        std::uint16_t sd = side < 0 ? line.front : line.back;
        sector = sd != kNoSide ? int(map.sidedefs[sd].sector) : -1;
    }
    return sector;
}

class SceneBuilder {
public:
    SceneBuilder(const WadFile& wad, const MapData& map) : wad_(wad), map_(map), textures_(wad) {}

    Scene build() {
        scene_.name = wad_.fileName() + ":" + map_.name;
        scene_.background = kSkyRadiance;
        // The sky lights the level through its sky ceilings, which light sampling finds as
        // emitters; sampling the background too would send a second shadow ray at the same sky.
        scene_.environment.sampled = false;
        buildWalls();
        buildFlats();
        placeCamera();
        placeLights();
        scene_.walkMap = walk::buildWalkMap(map_);
        scene_.textures = std::move(textures_.textures());
        scene_.validate();
        return std::move(scene_);
    }

private:
    std::uint32_t material(const std::string& key, int texture, bool masked) {
        auto [it, inserted] = materials_.try_emplace(key, std::uint32_t(scene_.materials.size()));
        if (inserted) {
            Material m;
            m.name = key;
            m.albedo = Vec3(1.0f);
            m.albedoTexture.texture = texture;
            if (masked) m.alphaCutoff = 0.5f;
            scene_.materials.push_back(std::move(m));
        }
        return it->second;
    }
    std::uint32_t skyMaterial() {
        auto [it, inserted] = materials_.try_emplace("sky", std::uint32_t(scene_.materials.size()));
        if (inserted) {
            Material m;
            m.name = "sky";
            m.albedo = Vec3(0.0f);
            m.emission = kSkyRadiance;
            m.twoSided = false;
            scene_.materials.push_back(std::move(m));
        }
        return it->second;
    }

    // Meshes are grouped by (sector, part, material) so each keeps its sector's light level.
    Mesh& mesh(int sector, const char* part, std::uint32_t mat) {
        auto key = std::make_tuple(sector, std::string(part), mat);
        auto [it, inserted] = meshes_.try_emplace(key, scene_.meshes.size());
        if (inserted) {
            Mesh m;
            m.name = map_.name + " sector " + std::to_string(sector) + " " + part + " " +
                     scene_.materials[mat].name;
            m.material = mat;
            int level = std::clamp<int>(map_.sectors[std::size_t(sector)].lightLevel, 0, 255);
            m.lightLevel = float(level) / 255.0f;
            scene_.meshes.push_back(std::move(m));
        }
        return scene_.meshes[it->second];
    }

    // A convex polygon (3 or 4 corners), wound so that its front faces `facing`.
    static void addPolygon(Mesh& m, const Vec3* p, const Vec2* uv, int n, Vec3 facing) {
        Vec3 normal = cross(p[1] - p[0], p[2] - p[0]);
        bool flip = dot(normal, facing) < 0;
        auto base = std::uint32_t(m.positions.size());
        for (int i = 0; i < n; ++i) {
            m.positions.push_back(p[i]);
            m.normals.push_back(facing);
            m.uvs.push_back(uv[i]);
        }
        for (int i = 1; i + 1 < n; ++i) {
            std::uint32_t a = base, b = base + std::uint32_t(i), c = base + std::uint32_t(i + 1);
            if (flip) std::swap(b, c);
            m.indices.insert(m.indices.end(), {a, b, c});
        }
    }

    // One wall piece from z0 to z1 (Doom units) along a -> b, facing right of a -> b.
    // textureTop: the height of the texture's top row (offsets included).
    void wallQuad(int sector, const Vertex& a, const Vertex& b, double z0, double z1,
                  const std::string& texName, double textureTop, double uOffset, bool masked) {
        if (!(z1 > z0)) return;
        int tex = textures_.wallTexture(texName);
        double tw = textures_.width(tex), th = textures_.height(tex);
        std::uint32_t mat = material((masked ? "masked " : "wall ") + texName, tex, masked);
        double dx = double(b.x) - a.x, dy = double(b.y) - a.y;
        double len = std::sqrt(dx * dx + dy * dy);
        Vec3 facing = normalize(Vec3(float(dy), 0.0f, float(dx)));  // Doom right (dy, -dx)
        Vec3 p[4] = {toWorld(a.x, z0, a.y), toWorld(b.x, z0, b.y), toWorld(b.x, z1, b.y),
                     toWorld(a.x, z1, a.y)};
        float u0 = float(uOffset / tw), u1 = float((uOffset + len) / tw);
        float vBottom = float((textureTop - z0) / th), vTop = float((textureTop - z1) / th);
        Vec2 uv[4] = {{u0, vBottom}, {u1, vBottom}, {u1, vTop}, {u0, vTop}};
        addPolygon(mesh(sector, "walls", mat), p, uv, 4, facing);
    }

    void buildWalls() {
        for (const Linedef& line : map_.linedefs) {
            if (line.front == kNoSide) continue;  // parseMap moved lone back sides to the front
            const Vertex& v1 = map_.vertices[line.v1];
            const Vertex& v2 = map_.vertices[line.v2];
            if (v1.x == v2.x && v1.y == v2.y) continue;
            wallSide(line, map_.sidedefs[line.front], line.back, v1, v2);
            if (line.back != kNoSide) wallSide(line, map_.sidedefs[line.back], line.front, v2, v1);
        }
    }

    void wallSide(const Linedef& line, const Sidedef& side, std::uint16_t otherSide,
                  const Vertex& a, const Vertex& b) {
        const int fs = side.sector;
        const Sector& f = map_.sectors[std::size_t(fs)];
        const double u = side.xOffset, dyOff = side.yOffset;
        const bool lowerUnpegged = line.flags & kLineLowerUnpegged;
        const bool upperUnpegged = line.flags & kLineUpperUnpegged;
        auto texHeight = [&](const std::string& name) {
            return double(textures_.height(textures_.wallTexture(name)));
        };
        if (otherSide == kNoSide) {
            if (!hasTexture(side.middle)) return;
            double top = lowerUnpegged ? f.floorHeight + texHeight(side.middle) : f.ceilingHeight;
            wallQuad(fs, a, b, f.floorHeight, f.ceilingHeight, side.middle, top + dyOff, u, false);
            return;
        }
        const Sector& k = map_.sectors[map_.sidedefs[otherSide].sector];
        if (k.ceilingHeight < f.ceilingHeight && hasTexture(side.upper) &&
            !(isSky(f.ceilingFlat) && isSky(k.ceilingFlat))) {
            double top = upperUnpegged ? f.ceilingHeight : k.ceilingHeight + texHeight(side.upper);
            wallQuad(fs, a, b, k.ceilingHeight, f.ceilingHeight, side.upper, top + dyOff, u, false);
        }
        if (k.floorHeight > f.floorHeight && hasTexture(side.lower)) {
            double top = lowerUnpegged ? f.ceilingHeight : k.floorHeight;
            wallQuad(fs, a, b, f.floorHeight, k.floorHeight, side.lower, top + dyOff, u, false);
        }
        if (hasTexture(side.middle)) {
            // Masked middle textures are drawn once, not tiled vertically, between the
            // higher floor and the lower ceiling.
            double hi = std::min(f.ceilingHeight, k.ceilingHeight);
            double lo = std::max(f.floorHeight, k.floorHeight);
            double th = texHeight(side.middle);
            double top = (lowerUnpegged ? lo + th : hi) + dyOff;
            wallQuad(fs, a, b, std::max(lo, top - th), std::min(hi, top), side.middle, top, u, true);
        }
    }

    void buildFlats() {
        std::vector<SectorOutline> outlines = buildSectorOutlines(map_);
        std::int64_t budget = kFillBudget;
        int closed = 0, skipped = 0;
        std::vector<Triangle2> tris;
        for (std::size_t s = 0; s < outlines.size(); ++s) {
            closed += outlines[s].closedChains;
            tris.clear();
            if (!fillNonzero(outlines[s].edges, tris, budget)) {
                ++skipped;
                continue;
            }
            if (tris.empty()) continue;
            const Sector& sec = map_.sectors[s];
            std::uint32_t floorMat = material("flat " + sec.floorFlat, textures_.flat(sec.floorFlat), false);
            std::uint32_t ceilMat = isSky(sec.ceilingFlat)
                                        ? skyMaterial()
                                        : material("flat " + sec.ceilingFlat,
                                                   textures_.flat(sec.ceilingFlat), false);
            Mesh& floor = mesh(int(s), "floor", floorMat);
            for (const Triangle2& t : tris) flatTriangle(floor, t, sec.floorHeight, Vec3(0, 1, 0));
            Mesh& ceiling = mesh(int(s), "ceiling", ceilMat);
            for (const Triangle2& t : tris)
                flatTriangle(ceiling, t, sec.ceilingHeight, Vec3(0, -1, 0));
        }
        const std::string where = wad_.fileName() + ": map " + map_.name;
        if (closed > 0)
            logWarning(where + ": " + std::to_string(closed) +
                       " unclosed sector outlines were closed with straight edges");
        if (skipped > 0)
            logWarning(where + ": " + std::to_string(skipped) +
                       " sectors are too complex to triangulate; their floors and ceilings are left out");
    }

    static void flatTriangle(Mesh& m, const Triangle2& t, double height, Vec3 facing) {
        Vec3 p[3];
        Vec2 uv[3];
        for (int i = 0; i < 3; ++i) {
            p[i] = toWorld(t[std::size_t(i)].x, height, t[std::size_t(i)].y);
            uv[i] = {float(t[std::size_t(i)].x / 64.0), float(-t[std::size_t(i)].y / 64.0)};
        }
        addPolygon(m, p, uv, 3, facing);
    }

    double floorAt(double x, double y) const {
        int s = sectorAt(map_, x, y);
        return s >= 0 ? map_.sectors[std::size_t(s)].floorHeight : 0.0;
    }

    void placeCamera() {
        Camera& cam = scene_.camera;
        cam.fovYDegrees = 70.0f;
        // Doom lights rooms by sector light level, not by lamps; a path tracer needs real light,
        // so levels come with a torch, as in the WebGPU E1M1 renderer we measure against.
        scene_.torch.enabled = true;
        // Measured on DOOM1 and Freedoom E1M1 (docs/PERFORMANCE.md): roulette from bounce 2 is both
        // faster and less noisy at equal time than from 3 on their dark walls; from 1 is noisier.
        scene_.viewerRouletteStart = 2;
        cam.up = Vec3(0, 1, 0);
        for (const Thing& t : map_.things) {
            if (t.type != 1) continue;
            double angle = double(t.angle) * (3.14159265358979323846 / 180.0);
            cam.position = toWorld(t.x, floorAt(t.x, t.y) + kEyeHeight, t.y);
            cam.lookAt = cam.position + Vec3(float(std::cos(angle)), 0.0f, float(-std::sin(angle)));
            return;
        }
        logWarning(wad_.fileName() + ": map " + map_.name +
                   " has no player 1 start; the camera looks along +x from the map's centre");
        double minX = INFINITY, maxX = -INFINITY, minY = INFINITY, maxY = -INFINITY;
        for (const Vertex& v : map_.vertices) {
            minX = std::min<double>(minX, v.x), maxX = std::max<double>(maxX, v.x);
            minY = std::min<double>(minY, v.y), maxY = std::max<double>(maxY, v.y);
        }
        double cx = 0.5 * (minX + maxX), cy = 0.5 * (minY + maxY);
        cam.position = toWorld(cx, floorAt(cx, cy) + kEyeHeight, cy);
        cam.lookAt = cam.position + Vec3(1, 0, 0);
    }

    void placeLights() {
        std::size_t count = 0;
        for (const Thing& t : map_.things) {
            if (t.flags & 0x10) continue;  // multiplayer only
            const LampType* lamp = nullptr;
            for (const LampType& l : kLamps)
                if (l.type == t.type) lamp = &l;
            if (!lamp) continue;
            if (++count > kMaxLights) {
                logWarning(wad_.fileName() + ": map " + map_.name + " has more than " +
                           std::to_string(kMaxLights) + " lamps; the rest are left out");
                return;
            }
            Light light;
            light.name = lamp->name;
            light.type = LightType::Point;
            light.position = toWorld(t.x, floorAt(t.x, t.y) + lamp->height, t.y);
            light.color = lamp->color;
            light.intensity = lamp->intensity;
            light.radius = 0.1f;
            scene_.lights.push_back(std::move(light));
        }
    }

    const WadFile& wad_;
    const MapData& map_;
    TextureLibrary textures_;
    Scene scene_;
    std::map<std::string, std::uint32_t> materials_;
    std::map<std::tuple<int, std::string, std::uint32_t>, std::size_t> meshes_;
};

std::string upper(std::string s) {
    for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace

Scene loadWadFromMemory(std::string_view bytes, const std::string& map, const std::string& name) {
    WadFile wad(bytes, name);
    std::vector<MapLumps> maps = findMaps(wad);
    if (maps.empty()) throw Error(name + ": the WAD contains no maps");
    const MapLumps* chosen = &maps.front();
    if (!map.empty()) {
        chosen = nullptr;
        const std::string wanted = upper(map);
        for (const MapLumps& m : maps)
            if (m.name == wanted) chosen = &m;
        if (!chosen) {
            std::string list;
            for (std::size_t i = 0; i < maps.size() && i < 12; ++i)
                list += (i ? ", " : "") + maps[i].name;
            if (maps.size() > 12) list += ", ...";
            throw Error(name + ": no map named " + map + " (the WAD has " + list + ")");
        }
    }
    MapData data = parseMap(wad, *chosen);
    return SceneBuilder(wad, data).build();
}

Scene loadWad(const std::filesystem::path& path, const std::string& map) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error(path.string() + ": no such file (or not a regular file)");
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) throw Error(path.string() + ": cannot open the file");
    std::streamoff size = in.tellg();
    constexpr std::streamoff kMaxBytes = std::streamoff(2) << 30;  // WAD offsets are 32-bit
    if (size < 0 || size > kMaxBytes)
        throw Error(path.string() + ": the file is larger than a WAD can be (2 GiB)");
    std::string bytes(std::size_t(size), '\0');
    in.seekg(0);
    if (!in.read(bytes.data(), size)) throw Error(path.string() + ": cannot read the file");
    return loadWadFromMemory(bytes, map, path.filename().string());
}

std::vector<std::string> wadMapNames(std::string_view bytes) {
    WadFile wad(bytes, "WAD");
    std::vector<std::string> names;
    for (const MapLumps& m : findMaps(wad)) names.push_back(m.name);
    return names;
}

}  // namespace penumbra
