#include "scene/io/wad/thing_placement.h"

#include <cmath>
#include <map>
#include <optional>

#include "core/log.h"
#include "scene/doom/line_specials.h"
#include "scene/io/wad/sprites.h"
#include "scene/io/wad/things.h"
#include "scene/io/wad/units.h"
#include "shared/constants.h"

namespace penumbra::wad {
namespace {

constexpr std::size_t kMaxLights = 4096;
constexpr std::size_t kMaxSprites = 65536;
// A full-bright frame (a lamp's flame, a power-up) shows its palette colour whatever the light,
// as Doom draws it; it is not a light the sampler aims at (the lamp's own light is).
constexpr float kFullBrightRadiance = 1.0f;

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

const LampType* lampType(std::uint16_t type) {
    for (const LampType& l : kLamps)
        if (l.type == type) return &l;
    return nullptr;
}

// A sprite frame as the scene holds it: its material (views texture) and its card's extents.
struct SpriteFrame {
    std::uint32_t material;
    std::uint32_t rotations;
    float left, right, bottom, top;  // metres around the thing's origin
};

class ThingPlacer {
public:
    ThingPlacer(const WadFile& wad, const MapData& map, TextureLibrary& textures,
                const WadOptions& options, Scene& scene)
        : wad_(wad),
          map_(map),
          textures_(textures),
          sprites_(wad, textures),
          options_(options),
          scene_(scene) {}

    std::vector<TakeableSprite> place() {
        for (std::size_t i = 0; i < map_.things.size(); ++i) {
            const Thing& t = map_.things[i];
            if (!inSinglePlayerMedium(t.flags)) continue;
            const int sector = sectorAt(map_, t.x, t.y);
            const double floor = sector >= 0 ? map_.sectors[std::size_t(sector)].floorHeight : 0.0;
            const double ceiling =
                sector >= 0 ? map_.sectors[std::size_t(sector)].ceilingHeight : 0.0;
            if (const ThingType* type = thingType(t.type))
                addSprite(i, *type, type->hangHeight > 0 ? ceiling - type->hangHeight : floor);
            if (const LampType* lamp = lampType(t.type)) addLamp(t, *lamp, floor);
        }
        const std::string where = wad_.fileName() + ": map " + map_.name;
        if (skippedSprites_ > 0)
            logWarning(where + " has more than " + std::to_string(kMaxSprites) +
                       " things to draw; " + std::to_string(skippedSprites_) + " are left out");
        if (skippedLights_ > 0)
            logWarning(where + " has more than " + std::to_string(kMaxLights) + " lamps; " +
                       std::to_string(skippedLights_) + " are left out");
        return std::move(takeable_);
    }

private:
    const SpriteFrame* frame(const ThingType& type) {
        const std::string key = std::string(type.sprite) + type.frame;
        auto [it, inserted] = frames_.try_emplace(key);
        if (!inserted) return it->second ? &*it->second : nullptr;
        std::optional<SpriteViews> views = sprites_.views(type.sprite, type.frame);
        if (!views) return nullptr;
        std::vector<Texture>& list = textures_.textures();
        const int texture = int(list.size());
        list.push_back(std::move(views->atlas));
        Material m;
        m.name = "sprite " + key;
        m.albedo = Vec3{1.0f};
        m.albedoTexture = {texture, Wrap::ClampToEdge, Wrap::ClampToEdge, options_.filter};
        m.alphaCutoff = 0.5f;
        if (type.fullBright && options_.glow > 0) {
            m.emission = Vec3{kFullBrightRadiance * options_.glow};
            m.emissionTexture = m.albedoTexture;
        }
        const auto material = std::uint32_t(scene_.materials.size());
        scene_.materials.push_back(std::move(m));
        it->second = SpriteFrame{material,
                                 std::uint32_t(views->rotations),
                                 views->left / kUnitsPerMetre,
                                 views->right / kUnitsPerMetre,
                                 views->bottom / kUnitsPerMetre,
                                 views->top / kUnitsPerMetre};
        return &*it->second;
    }

    // A key's sprite gets a copy of its frame's material, which vanishes when the key is taken.
    std::uint32_t ownMaterial(std::size_t thing, std::uint32_t shared) {
        Material m = scene_.materials[shared];
        m.name += " thing " + std::to_string(thing);
        const auto material = std::uint32_t(scene_.materials.size());
        scene_.materials.push_back(std::move(m));
        takeable_.push_back({thing, material});
        return material;
    }

    void addSprite(std::size_t thing, const ThingType& type, double z) {
        const Thing& t = map_.things[thing];
        const SpriteFrame* f = frame(type);
        if (!f) return;
        if (scene_.sprites.size() >= kMaxSprites) {
            ++skippedSprites_;
            return;
        }
        const double angle = degreesToRadians(double(t.angle));
        Sprite s;
        s.position = toWorld(t.x, z, t.y);
        s.facing = Vec3{float(std::cos(angle)), 0.0f, float(-std::sin(angle))};
        s.left = f->left, s.right = f->right, s.bottom = f->bottom, s.top = f->top;
        s.rotations = f->rotations;
        s.material = doom::keyOfThing(t.type) != doom::Key::None ? ownMaterial(thing, f->material) : f->material;
        scene_.sprites.push_back(s);
    }

    void addLamp(const Thing& t, const LampType& lamp, double floor) {
        if (lightCount_ >= kMaxLights) {
            ++skippedLights_;
            return;
        }
        ++lightCount_;
        Light light;
        light.name = lamp.name;
        light.type = LightType::Point;
        light.position = toWorld(t.x, floor + lamp.height, t.y);
        light.color = lamp.color;
        light.intensity = lamp.intensity;
        light.radius = 0.1f;
        scene_.lights.push_back(std::move(light));
    }

    const WadFile& wad_;
    const MapData& map_;
    TextureLibrary& textures_;
    SpriteLibrary sprites_;
    const WadOptions& options_;
    Scene& scene_;
    std::map<std::string, std::optional<SpriteFrame>> frames_;
    std::size_t lightCount_ = 0, skippedLights_ = 0, skippedSprites_ = 0;
    std::vector<TakeableSprite> takeable_;
};

}  // namespace

std::vector<TakeableSprite> placeThings(const WadFile& wad, const MapData& map, TextureLibrary& textures,
                                        const WadOptions& options, Scene& scene) {
    return ThingPlacer(wad, map, textures, options, scene).place();
}

}  // namespace penumbra::wad
