// Builds a Scene from one Doom map: walls with Doom's pegging rules, sector floors and ceilings
// (triangulate.cpp), glowing textures and flats as emitters (glow.h), sector light levels as fill
// light from the ceilings (sector_light.h), sky ceilings as portals onto the sky (sky.h), the
// player start as the camera, and things as sprites and lamps (thing_placement.h). Floors and
// ceilings that the map's specials can move (scene/doom/level.h) go into instances of their own,
// with the walls that move with them, so the viewer moves them by their transforms. Doom units
// become metres at 32 units per metre; Doom (x, y, z up) becomes (x, z, -y) here, with y up.
#include "scene/io/wad/wad_loader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <tuple>

#include "core/error.h"
#include "core/log.h"
#include "scene/doom/level.h"
#include "scene/doom/level_looks.h"
#include "scene/environment.h"
#include "scene/io/wad/glow.h"
#include "scene/io/wad/map.h"
#include "scene/io/wad/sector_light.h"
#include "scene/io/wad/sky.h"
#include "scene/io/wad/textures.h"
#include "scene/io/wad/thing_placement.h"
#include "scene/io/wad/triangulate.h"
#include "scene/io/wad/units.h"
#include "scene/walk/wad_walk_map.h"
#include "scene/walk/walk_physics.h"
#include "shared/constants.h"

namespace penumbra {
namespace {
using namespace wad;

constexpr double kEyeHeight = walk::kEyeHeight;
// The sky's radiance when the WAD has no sky texture (a dull daylight grey-blue).
constexpr Vec3 kSkyRadiance{1.0f, 1.0f, 1.1f};
// Radiance per unit of the sky texture's linear colour: Doom draws the sky at its palette colours.
// (An outdoor sector is lit by its level's fill light, which comes through the sky too.)
constexpr float kSkyBrightness = 1.0f;
constexpr std::int64_t kFillBudget = 50'000'000;  // slab sweep work units per map

bool isSky(const std::string& flat) { return flat == "F_SKY1"; }
bool hasTexture(const std::string& name) { return !name.empty() && name != "-"; }

class SceneBuilder {
public:
    SceneBuilder(const WadFile& wad, const MapData& map, const WadOptions& options)
        : wad_(wad), map_(map), options_(options), textures_(wad), level_(std::make_shared<doom::Level>(map)) {}

    Scene build() {
        scene_.name = wad_.fileName() + ":" + map_.name;
        scene_.background = kSkyRadiance;
        // The sky lights the level through its sky ceilings, which light sampling finds as
        // emitters (portals onto the sky); sampling the environment too would send a second
        // shadow ray at the same sky. Escaping rays still see it.
        scene_.environment.sampled = false;
        buildWalls();
        buildFlats();
        if (hasSky_) buildSky();
        placeCamera();
        for (const TakeableSprite& key : placeThings(wad_, map_, textures_, options_, scene_))
            level_->keyMaterials().push_back({key.thing, key.material, scene_.materials[key.material].alphaCutoff});
        scene_.walkMap = walk::buildWalkMap(map_);
        placeMovingPlanes();
        scene_.doomLevel = level_;
        scene_.textures = std::move(textures_.textures());
        scene_.validate();
        return std::move(scene_);
    }

private:
    Material surface(const std::string& name, int texture, bool masked) const {
        Material m;
        m.name = name;
        m.albedo = Vec3(1.0f);
        m.albedoTexture.texture = texture;
        m.albedoTexture.filter = options_.filter;
        if (masked) m.alphaCutoff = 0.5f;
        return m;
    }
    std::uint32_t add(const std::string& key, const std::function<Material()>& make) {
        auto [it, inserted] = materials_.try_emplace(key, std::uint32_t(scene_.materials.size()));
        if (inserted) scene_.materials.push_back(make());
        return it->second;
    }

    // A wall texture or flat, glowing where glow.h says it does.
    // moving: for geometry that moves (an instance): a glow there is found by bounce rays only,
    // since light-sampled emitters are baked into the world where they stand (instances.h).
    std::uint32_t material(const std::string& key, const std::string& texName, bool flat, int texture, bool masked,
                           bool moving = false) {
        const Glow glow = options_.glow > 0 ? glowOf(texName, flat) : Glow{};
        const bool movingGlow = moving && glow.kind != GlowKind::None;
        return add(movingGlow ? "moving " + key : key, [&] {
            Material m = surface(key, texture, masked);
            if (glow.kind != GlowKind::None) {
                m.emission = Vec3(glow.strength * options_.glow);
                m.emissionTexture = m.albedoTexture;
                m.emissionTexture.texture = glowTextureOf(texture, glow.kind);
                m.lightSampled = !movingGlow;
            }
            return m;
        });
    }

    // A switch's wall (doom::SwitchMaterial): a material for line `line` alone, which knows the
    // texture the switch turns to (and that texture's glow, since SW1 and SW2 glow alike).
    std::uint32_t switchMaterial(std::size_t line, const std::string& texName, int texture, bool masked,
                                 bool moving) {
        const std::size_t before = scene_.materials.size();
        const std::uint32_t index =
            material("switch line " + std::to_string(line) + " " + texName, texName, false, texture, masked, moving);
        if (scene_.materials.size() == before) return index;  // the switch's second wall piece
        const int other = textures_.wallTexture(doom::otherSwitchTexture(texName));
        doom::SwitchMaterial turn{line, index, {texture, other}, {-1, -1}};
        if (scene_.materials[index].emissionTexture.present()) {
            turn.emission[0] = scene_.materials[index].emissionTexture.texture;
            turn.emission[1] = glowTextureOf(other, glowOf(texName, false).kind);
        }
        level_->switchMaterials().push_back(turn);
        return index;
    }

    // The part of a switch line's front side whose texture turns, as P_ChangeSwitchTexture picks
    // it: the first of upper, middle and lower that is a switch texture the WAD has the other of.
    enum class SidePart { Upper, Middle, Lower };
    std::optional<SidePart> turningPart(const Linedef& line, const Sidedef& side) const {
        if (!doom::turnsSwitch(line.special)) return std::nullopt;
        auto turns = [&](const std::string& name) {
            const std::string other = doom::otherSwitchTexture(name);
            return !other.empty() && textures_.hasWallTexture(name) && textures_.hasWallTexture(other);
        };
        if (turns(side.upper)) return SidePart::Upper;
        if (turns(side.middle)) return SidePart::Middle;
        if (turns(side.lower)) return SidePart::Lower;
        return std::nullopt;
    }

    // The emission texture of a glowing texture, made once; for an animated one, one per frame,
    // consecutive and animated alike, so the glow follows the frames.
    int glowTextureOf(int texture, GlowKind kind) {
        if (kind == GlowKind::Whole) return texture;  // every texel glows in its own colour
        if (auto it = glowTextures_.find(texture); it != glowTextures_.end()) return it->second;
        std::vector<Texture>& list = textures_.textures();
        const TextureAnimation animation = list[std::size_t(texture)].animation;
        const int first = texture - animation.frame;
        const int out = int(list.size());
        for (int k = 0; k < animation.frames; ++k) {
            Texture glow = glowTexture(list[std::size_t(first + k)], kind);
            list.push_back(std::move(glow));
            glowTextures_.try_emplace(first + k, out + k);
        }
        return glowTextures_.at(texture);
    }

    // A floor or non-sky ceiling: it gives off its sector's fill light (sector_light.h) unless it
    // glows itself (its own light fills the sector then) or the sector is closed (a shut door).
    // A sector whose light changes (a light special) gets materials of its own, which the level
    // drives (doom::Level::lightMaterials).
    std::uint32_t flatMaterial(int sector, const std::string& flatName, bool moving = false) {
        const Sector& sec = map_.sectors[std::size_t(sector)];
        const int texture = textures_.flat(flatName);
        const float radiance = sectorRadiance(sec.lightLevel) * options_.sectorLight;
        const bool glows = options_.glow > 0 && glowOf(flatName, true).kind != GlowKind::None;
        const bool varies = level_->lightVaries(sector) && options_.sectorLight > 0;
        if (glows || !(radiance > 0 || varies) || sec.ceilingHeight <= sec.floorHeight)
            return material("flat " + flatName, flatName, true, texture, false, moving);
        const int level = std::clamp<int>(sec.lightLevel, 0, 255);
        const std::string key = "flat " + flatName + " light " + std::to_string(level) +
                                (varies ? " sector " + std::to_string(sector) : std::string());
        const std::size_t before = scene_.materials.size();
        const std::uint32_t index = add(key, [&] {
            Material m = surface(key, texture, false);
            m.emission = Vec3(radiance);
            m.emissionHiddenFromCamera = true;  // the room looks lit; its floor and ceiling do not glow
            // Fill light covers most of what a bounce ray sees, so BSDF sampling finds it well;
            // light-sampled, the floors and ceilings were three quarters of E1M1's light list,
            // drew picks away from the lamps and glowing textures, and cost a light-tree walk
            // (the MIS pdf) at nearly every bounce hit.
            m.lightSampled = false;
            return m;
        });
        if (varies && scene_.materials.size() > before)
            level_->lightMaterials().push_back({sector, index, options_.sectorLight});
        return index;
    }

    // A sky ceiling: a portal onto the sky, which also brings its sector's fill light (outdoors,
    // the light a sector's level promises comes through the open sky).
    std::uint32_t skyMaterial(const Sector& sec) {
        const float radiance = sectorRadiance(sec.lightLevel) * options_.sectorLight;
        const int level = radiance > 0 ? std::clamp<int>(sec.lightLevel, 0, 255) : 0;
        return add("sky light " + std::to_string(level), [&] {
            Material m;
            m.name = "sky light " + std::to_string(level);
            m.albedo = Vec3(0.0f);
            m.skyPortal = true;
            m.emission = Vec3(std::max(radiance, 0.0f));
            m.emissionHiddenFromCamera = true;  // the camera sees the sky itself
            m.twoSided = false;
            hasSky_ = true;
            return m;
        });
    }

    // The level's sky texture as the environment, seen through the sky ceilings and by rays that
    // leave the level. Without the texture the sky stays the constant kSkyRadiance.
    void buildSky() {
        const std::string name = skyTextureName(map_.name);
        std::optional<Texture> sky = textures_.hasWallTexture(name) ? textures_.composeWall(name) : std::nullopt;
        if (!sky) {
            logWarning(wad_.fileName() + ": map " + map_.name + " has sky ceilings but no texture " + name +
                       "; the sky is a uniform grey");
            return;
        }
        scene_.environment.map = skyEnvironment(*sky, kSkyBrightness);
        scene_.background = skyPortalRadiance(scene_.environment, scene_.background);
    }

    // Meshes are grouped by (sector, part, material) so each keeps its sector's light level;
    // proto >= 0: in that prototype (a moving plane's), else in the world.
    Mesh& mesh(int sector, const char* part, std::uint32_t mat, int proto = -1) {
        std::vector<Mesh>& list = proto < 0 ? scene_.meshes : scene_.prototypes[std::size_t(proto)].meshes;
        auto key = std::make_tuple(sector, std::string(part), mat, proto);
        auto [it, inserted] = meshes_.try_emplace(key, list.size());
        if (inserted) {
            Mesh m;
            m.name = map_.name + " sector " + std::to_string(sector) + " " + part + " " +
                     scene_.materials[mat].name;
            m.material = mat;
            int level = std::clamp<int>(map_.sectors[std::size_t(sector)].lightLevel, 0, 255);
            m.lightLevel = float(level) / 255.0f;
            list.push_back(std::move(m));
        }
        return list[it->second];
    }

    // The prototype of a sector's moving floor or ceiling: what moves with it.
    int movingPrototype(int sector, doom::Plane plane) {
        auto [it, inserted] = prototypes_.try_emplace({sector, plane}, int(scene_.prototypes.size()));
        if (inserted) {
            Prototype p;
            p.name = map_.name + " sector " + std::to_string(sector) +
                     (plane == doom::Plane::Floor ? " floor" : " ceiling");
            scene_.prototypes.push_back(std::move(p));
        }
        return it->second;
    }

    // One instance per moving plane, placed where the map has it (the identity), and the level
    // told which instance carries which plane at which height.
    void placeMovingPlanes() {
        for (const auto& [key, proto] : prototypes_) {
            if (scene_.prototypes[std::size_t(proto)].meshes.empty()) continue;
            const auto [sector, plane] = key;
            const std::uint32_t instance = std::uint32_t(scene_.instances.size());
            scene_.instances.push_back({std::uint32_t(proto), Affine{}});
            const Sector& sec = map_.sectors[std::size_t(sector)];
            const double base = plane == doom::Plane::Floor ? sec.floorHeight : sec.ceilingHeight;
            level_->planeInstances().push_back({sector, plane, instance, base});
        }
    }
    bool moves(int sector, doom::Plane plane) const { return level_->range(sector, plane).moves; }

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
    // proto >= 0: the quad moves with that prototype's plane. switchLine: the quad shows that
    // line's switch, which turns.
    void wallQuad(int sector, const Vertex& a, const Vertex& b, double z0, double z1,
                  const std::string& texName, double textureTop, double uOffset, bool masked, int proto = -1,
                  std::optional<std::size_t> switchLine = std::nullopt) {
        if (!(z1 > z0)) return;
        int tex = textures_.wallTexture(texName);
        double tw = textures_.width(tex), th = textures_.height(tex);
        std::uint32_t mat = switchLine ? switchMaterial(*switchLine, texName, tex, masked, proto >= 0)
                                       : material((masked ? "masked " : "wall ") + texName, texName, false, tex,
                                                  masked, proto >= 0);
        double dx = double(b.x) - a.x, dy = double(b.y) - a.y;
        double len = std::sqrt(dx * dx + dy * dy);
        Vec3 facing = normalize(Vec3(float(dy), 0.0f, float(dx)));  // Doom right (dy, -dx)
        Vec3 p[4] = {toWorld(a.x, z0, a.y), toWorld(b.x, z0, b.y), toWorld(b.x, z1, b.y),
                     toWorld(a.x, z1, a.y)};
        float u0 = float(uOffset / tw), u1 = float((uOffset + len) / tw);
        float vBottom = float((textureTop - z0) / th), vTop = float((textureTop - z1) / th);
        Vec2 uv[4] = {{u0, vBottom}, {u1, vBottom}, {u1, vTop}, {u0, vTop}};
        addPolygon(mesh(sector, "walls", mat, proto), p, uv, 4, facing);
    }

    void buildWalls() {
        for (const Linedef& line : map_.linedefs) {
            if (line.front == kNoSide) continue;  // parseMap moved lone back sides to the front
            const Vertex& v1 = map_.vertices[line.v1];
            const Vertex& v2 = map_.vertices[line.v2];
            if (v1.x == v2.x && v1.y == v2.y) continue;
            const std::size_t index = std::size_t(&line - map_.linedefs.data());
            wallSide(line, map_.sidedefs[line.front], line.back, v1, v2, index);
            // Only the front side's switch turns (P_ChangeSwitchTexture).
            if (line.back != kNoSide) wallSide(line, map_.sidedefs[line.back], line.front, v2, v1);
        }
    }

    // A side's walls. Where a plane of either sector can move, the walls span every height it
    // can take: a wall whose edge is the other sector's moving plane moves with that plane (its
    // extra height goes behind this sector's own floor or ceiling), and a wall whose edge is this
    // sector's moving plane stays, reaching as far as the plane goes (the plane covers the rest).
    // frontOf: this is the front side of that linedef (whose switch may turn).
    void wallSide(const Linedef& line, const Sidedef& side, std::uint16_t otherSide,
                  const Vertex& a, const Vertex& b, std::optional<std::size_t> frontOf = std::nullopt) {
        using doom::Plane;
        const std::optional<SidePart> turning = frontOf ? turningPart(line, side) : std::nullopt;
        auto switchOf = [&](SidePart part) { return turning == part ? frontOf : std::nullopt; };
        const int fs = side.sector;
        const Sector& f = map_.sectors[std::size_t(fs)];
        const double u = side.xOffset, dyOff = side.yOffset;
        const bool lowerUnpegged = line.flags & kLineLowerUnpegged;
        const bool upperUnpegged = line.flags & kLineUpperUnpegged;
        auto texHeight = [&](const std::string& name) {
            return double(textures_.height(textures_.wallTexture(name)));
        };
        // This sector's lowest floor and highest ceiling.
        const double fFloorLow = moves(fs, Plane::Floor) ? level_->range(fs, Plane::Floor).low : f.floorHeight;
        const double fCeilHigh = moves(fs, Plane::Ceiling) ? level_->range(fs, Plane::Ceiling).high : f.ceilingHeight;
        if (otherSide == kNoSide) {
            if (!hasTexture(side.middle)) return;
            double top = lowerUnpegged ? f.floorHeight + texHeight(side.middle) : f.ceilingHeight;
            wallQuad(fs, a, b, fFloorLow, fCeilHigh, side.middle, top + dyOff, u, false, -1,
                     switchOf(SidePart::Middle));
            return;
        }
        const int ks = map_.sidedefs[otherSide].sector;
        const Sector& k = map_.sectors[std::size_t(ks)];
        if (hasTexture(side.upper) && !(isSky(f.ceilingFlat) && isSky(k.ceilingFlat))) {
            const double top = upperUnpegged ? f.ceilingHeight : k.ceilingHeight + texHeight(side.upper);
            if (moves(ks, Plane::Ceiling)) {
                const double reach = fCeilHigh - level_->range(ks, Plane::Ceiling).low;
                if (reach > 0)
                    wallQuad(fs, a, b, k.ceilingHeight, k.ceilingHeight + reach, side.upper, top + dyOff, u, false,
                             movingPrototype(ks, Plane::Ceiling), switchOf(SidePart::Upper));
            } else if (k.ceilingHeight < fCeilHigh) {
                wallQuad(fs, a, b, k.ceilingHeight, fCeilHigh, side.upper, top + dyOff, u, false, -1,
                         switchOf(SidePart::Upper));
            }
        }
        if (hasTexture(side.lower)) {
            const double top = lowerUnpegged ? f.ceilingHeight : k.floorHeight;
            if (moves(ks, Plane::Floor)) {
                const double reach = level_->range(ks, Plane::Floor).high - fFloorLow;
                if (reach > 0)
                    wallQuad(fs, a, b, k.floorHeight - reach, k.floorHeight, side.lower, top + dyOff, u, false,
                             movingPrototype(ks, Plane::Floor), switchOf(SidePart::Lower));
            } else if (k.floorHeight > fFloorLow) {
                wallQuad(fs, a, b, fFloorLow, k.floorHeight, side.lower, top + dyOff, u, false, -1,
                         switchOf(SidePart::Lower));
            }
        }
        if (hasTexture(side.middle)) {
            // Masked middle textures are drawn once, not tiled vertically, between the
            // higher floor and the lower ceiling.
            double hi = std::min(f.ceilingHeight, k.ceilingHeight);
            double lo = std::max(f.floorHeight, k.floorHeight);
            double th = texHeight(side.middle);
            double top = (lowerUnpegged ? lo + th : hi) + dyOff;
            wallQuad(fs, a, b, std::max(lo, top - th), std::min(hi, top), side.middle, top, u, true, -1,
                     switchOf(SidePart::Middle));
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
            const bool floorMoves = moves(int(s), doom::Plane::Floor);
            const bool ceilingMoves = moves(int(s), doom::Plane::Ceiling);
            std::uint32_t floorMat = flatMaterial(int(s), sec.floorFlat, floorMoves);
            std::uint32_t ceilMat =
                isSky(sec.ceilingFlat) ? skyMaterial(sec) : flatMaterial(int(s), sec.ceilingFlat, ceilingMoves);
            const int floorProto = floorMoves ? movingPrototype(int(s), doom::Plane::Floor) : -1;
            const int ceilingProto = ceilingMoves ? movingPrototype(int(s), doom::Plane::Ceiling) : -1;
            Mesh& floor = mesh(int(s), "floor", floorMat, floorProto);
            for (const Triangle2& t : tris) flatTriangle(floor, t, sec.floorHeight, Vec3(0, 1, 0));
            Mesh& ceiling = mesh(int(s), "ceiling", ceilMat, ceilingProto);
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
            double angle = degreesToRadians(double(t.angle));
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

    const WadFile& wad_;
    const MapData& map_;
    const WadOptions& options_;
    TextureLibrary textures_;
    Scene scene_;
    std::map<std::string, std::uint32_t> materials_;
    std::map<int, int> glowTextures_;  // albedo texture -> its emission texture
    bool hasSky_ = false;
    std::map<std::tuple<int, std::string, std::uint32_t, int>, std::size_t> meshes_;
    std::shared_ptr<doom::Level> level_;
    std::map<std::pair<int, doom::Plane>, int> prototypes_;  // moving planes' prototypes
};

std::string upper(std::string s) {
    for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace

void validateWadOptions(const WadOptions& o) {
    if (!(o.glow >= 0 && o.glow <= 1e6f)) throw UsageError("--wad-glow must be a scale between 0 and 1e6 (0: nothing glows)");
    if (!(o.sectorLight >= 0 && o.sectorLight <= 1e6f))
        throw UsageError("--wad-sector-light must be a scale between 0 and 1e6 (0: no sector light)");
}

Scene loadWadFromMemory(std::string_view bytes, const std::string& map, const std::string& name,
                        const WadOptions& options) {
    validateWadOptions(options);
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
    return SceneBuilder(wad, data, options).build();
}

Scene loadWad(const std::filesystem::path& path, const std::string& map, const WadOptions& options) {
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
    return loadWadFromMemory(bytes, map, path.filename().string(), options);
}

std::vector<std::string> wadMapNames(std::string_view bytes) {
    WadFile wad(bytes, "WAD");
    std::vector<std::string> names;
    for (const MapLumps& m : findMaps(wad)) names.push_back(m.name);
    return names;
}

}  // namespace penumbra
