// The dungeon: a 16 x 16 tile map (the second scene of the WebGPU Doom-style renderer), walls,
// floor and ceiling built once as world meshes and textured from Freedoom (dungeon_textures.h;
// flat colours without it), lit by the player's torch and by torches on the walls, which are
// glowing panels set into the wall as the WebGPU renderer makes them (emissive triangles, so the
// light sampler aims at them like any area light), with a phantom whose eyes glow patrolling the
// southern corridor. The phantom is one instance moved by a scene motion (scene/object_motion.h),
// so only the top level changes while it walks (scene/phantom.h switches it off and on); the light
// sampler picks the torches that matter at each point, which is the job the WebGPU renderer's
// per-tile BVH copies did.
#include <array>
#include <cmath>
#include <optional>

#include "core/error.h"
#include "scene/presets/dungeon_textures.h"
#include "scene/presets/mesh_builder.h"
#include "scene/presets/presets.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

constexpr int kSize = 16;
constexpr float kTile = 2.0f;         // metres per tile
constexpr float kWallHeight = 3.0f;

// '#': wall, '.': floor. Row z = 0 is the north edge (least z), column x = 0 the west edge.
constexpr std::array<const char*, kSize> kMap = {
    "################",
    "#......#.......#",
    "#......#.......#",
    "#..............#",
    "#......#.......#",
    "####.#####.#####",
    "#....#...#.....#",
    "#....#...#.....#",
    "#..........#...#",
    "#....#...#.#...#",
    "##.###...#.#.###",
    "#........#.....#",
    "#.######.#####.#",
    "#..............#",
    "#..............#",
    "################",
};

// A wall torch: on the floor tile (x, z), hung on its wall toward (dx, dz).
struct WallTorch {
    int x, z, dx, dz;
};
constexpr WallTorch kTorches[] = {
    {3, 1, 0, -1}, {11, 1, 0, -1}, {1, 7, -1, 0}, {14, 7, 1, 0}, {7, 6, 0, -1}, {4, 11, 0, -1},
    {13, 11, 0, -1}, {7, 14, 0, 1}, {1, 13, -1, 0}, {14, 13, 1, 0},
};

// A torch panel's share of the wall's width, its bottom and top edges as shares of the wall's
// height, and how far it stands in front of the wall.
constexpr float kTorchWidth = 0.7f, kTorchBottom = 0.25f, kTorchTop = 0.75f;
constexpr float kTorchStandOff = 0.01f;  // metres
// The panel's radiance: the flame colour at a strength that makes a panel about as bright, seen
// from in front, as the 6-candela point light it replaced (radiance x area = 3 x 2.1 m^2).
constexpr Vec3 kTorchEmission{3.0f, 1.86f, 0.9f};

// The phantom's corridor: row 13, patrolled between these columns.
constexpr int kCorridorRow = 13;
constexpr int kPatrolFrom = 3, kPatrolTo = 13;

bool isWall(int x, int z) { return x < 0 || z < 0 || x >= kSize || z >= kSize || kMap[std::size_t(z)][x] == '#'; }

Vec3 tileCentre(int x, int z) { return {(float(x) + 0.5f) * kTile, 0.0f, (float(z) + 0.5f) * kTile}; }

// Texture coordinates of the map's surfaces, in texture repeats: flats tile the floor and ceiling
// one per tile; the wall texture runs along each wall from its top edge down, 1 texel per Doom unit.
struct MapUvs {
    float flat = 2.0f;                      // metres per flat repeat
    float wallWidth = 4.0f, wallHeight = 4.0f;  // metres per wall texture repeat
};

void addFlatQuad(Mesh& m, const std::array<Vec3, 4>& p, float metres) {
    addQuad(m, p[0], p[1], p[2], p[3]);
    for (const Vec3& q : p) m.uvs.push_back({q.x / metres, q.z / metres});
}

// Floor and ceiling of every floor tile, and a wall quad on each side that faces a wall tile.
void addMap(Scene& scene, std::uint32_t floorMat, std::uint32_t ceilingMat, std::uint32_t wallMat, const MapUvs& uv) {
    Mesh floor{"floor"}, ceiling{"ceiling"}, walls{"walls"};
    floor.material = floorMat;
    ceiling.material = ceilingMat;
    walls.material = wallMat;
    const Vec3 up{0, 1, 0};
    for (int z = 0; z < kSize; ++z)
        for (int x = 0; x < kSize; ++x) {
            if (isWall(x, z)) continue;
            const float x0 = float(x) * kTile, x1 = x0 + kTile, z0 = float(z) * kTile, z1 = z0 + kTile;
            addFlatQuad(floor, {Vec3{x0, 0, z0}, {x0, 0, z1}, {x1, 0, z1}, {x1, 0, z0}}, uv.flat);
            addFlatQuad(ceiling, {Vec3{x0, kWallHeight, z0}, {x1, kWallHeight, z0}, {x1, kWallHeight, z1}, {x0, kWallHeight, z1}},
                        uv.flat);
            const int sides[4][2] = {{0, -1}, {0, 1}, {-1, 0}, {1, 0}};
            for (const auto& side : sides) {
                if (!isWall(x + side[0], z + side[1])) continue;
                // Seen from inside the tile, looking at the wall: right = toward x up.
                const Vec3 toward{float(side[0]), 0, float(side[1])};
                const Vec3 right = cross(toward, up);
                const Vec3 c = tileCentre(x, z) + toward * (0.5f * kTile);
                const Vec3 h = right * (0.5f * kTile), top{0, kWallHeight, 0};
                const std::array<Vec3, 4> corners{c - h, c + h, c + h + top, c - h + top};
                addQuad(walls, corners[0], corners[1], corners[2], corners[3]);
                for (const Vec3& q : corners) walls.uvs.push_back({dot(q, right) / uv.wallWidth, (kWallHeight - q.y) / uv.wallHeight});
            }
        }
    scene.meshes.push_back(std::move(floor));
    scene.meshes.push_back(std::move(ceiling));
    scene.meshes.push_back(std::move(walls));
}

// A ring of `sides` points at height y.
void addRing(Mesh& m, int sides, float radius, float y) {
    for (int i = 0; i < sides; ++i) {
        const float a = 2.0f * kPiF * float(i) / float(sides);
        m.positions.push_back({radius * std::cos(a), y, radius * std::sin(a)});
    }
}

// The phantom's body: a hovering shroud (a tapered, capped tube) in its own space, standing on
// y = 0 around the y axis; its eyes: two small quads on each side it walks toward (+x and -x).
Prototype phantom(std::uint32_t bodyMat, std::uint32_t eyeMat) {
    constexpr int kSides = 12;
    Mesh body{"phantom body"};
    body.material = bodyMat;
    addRing(body, kSides, 0.42f, 0.25f);  // ragged hem, above the floor
    addRing(body, kSides, 0.30f, 1.10f);
    addRing(body, kSides, 0.26f, 1.55f);
    body.positions.push_back({0, 1.85f, 0});  // the crown
    for (std::uint32_t ring = 0; ring < 2; ++ring)
        for (std::uint32_t i = 0; i < kSides; ++i) {
            const std::uint32_t j = (i + 1) % kSides, a = ring * kSides, b = a + kSides;
            body.indices.insert(body.indices.end(), {a + i, b + i, b + j, a + i, b + j, a + j});
        }
    const std::uint32_t crown = 3 * kSides, top = 2 * kSides;
    for (std::uint32_t i = 0; i < kSides; ++i) body.indices.insert(body.indices.end(), {top + i, crown, top + (i + 1) % kSides});
    Mesh eyes{"phantom eyes"};
    eyes.material = eyeMat;
    for (float side : {1.0f, -1.0f})
        for (float z : {-0.09f, 0.09f}) {
            // Counter-clockwise seen from outside, so the glowing (front) face looks out.
            const float x = side * 0.285f, y = 1.4f;
            addQuad(eyes, {x, y - 0.03f, z + 0.05f * side}, {x, y - 0.03f, z - 0.05f * side},
                    {x, y + 0.03f, z - 0.05f * side}, {x, y + 0.03f, z + 0.05f * side});
        }
    return {"phantom", {std::move(body), std::move(eyes)}};
}

// The wall torches: a glowing panel on the wall each, across the middle 70% of the wall's width
// and half its height (the WebGPU renderer's proportions), 1 cm in front of the wall, its
// glowing front face toward the room.
void addTorches(Scene& scene, std::uint32_t torchMat) {
    Mesh panels{"wall torches"};
    panels.material = torchMat;
    const Vec3 up{0, 1, 0};
    for (const WallTorch& t : kTorches) {
        if (isWall(t.x, t.z) || !isWall(t.x + t.dx, t.z + t.dz))
            throw Error("dungeon: a wall torch is not on a floor tile next to a wall");  // a map edit gone wrong
        const Vec3 toward{float(t.dx), 0, float(t.dz)};
        const Vec3 right = cross(toward, up);
        const Vec3 c = tileCentre(t.x, t.z) + toward * (0.5f * kTile - kTorchStandOff);
        const Vec3 h = right * (0.5f * kTorchWidth * kTile);
        const Vec3 bottom{0, kTorchBottom * kWallHeight, 0}, top{0, kTorchTop * kWallHeight, 0};
        addQuad(panels, c - h + bottom, c + h + bottom, c + h + top, c - h + top);
    }
    scene.meshes.push_back(std::move(panels));
}

TileGrid grid() {
    TileGrid g;
    g.tileSize = kTile;
    g.width = g.depth = kSize;
    g.eyeHeight = 1.6f;
    for (int z = 0; z < kSize; ++z)
        for (int x = 0; x < kSize; ++x) g.walkable.push_back(isWall(x, z) ? 0 : 1);
    return g;
}

}  // namespace

Scene makeDungeon() { return makeDungeon(freedoomWadPath()); }

Scene makeDungeon(const std::filesystem::path& textureWad) {
    Scene scene;
    scene.name = "dungeon";
    std::optional<DungeonTextures> textures = loadDungeonTextures(textureWad);
    // Textured: white albedo under the texture, looked up with the nearest texel as Doom does.
    // Without Freedoom: the stone colours the textures would show on average.
    auto surface = [&](const char* name, Vec3 flat, int texture) {
        if (!textures) return addMaterial(scene, name, flat);
        const std::uint32_t m = addMaterial(scene, name, Vec3{1.0f});
        scene.materials[m].albedoTexture = {texture, Wrap::Repeat, Wrap::Repeat, Filter::Nearest};
        return m;
    };
    const std::uint32_t floorMat = surface("flagstones", {0.32f, 0.29f, 0.25f}, textures ? textures->floor : -1);
    const std::uint32_t ceilingMat = surface("vault", {0.22f, 0.21f, 0.2f}, textures ? textures->ceiling : -1);
    const std::uint32_t wallMat = surface("stone", {0.45f, 0.41f, 0.36f}, textures ? textures->wall : -1);
    const std::uint32_t torchMat = addMaterial(scene, "torch", {0.9f, 0.75f, 0.45f}, kTorchEmission);
    const std::uint32_t bodyMat = addMaterial(scene, "shroud", {0.78f, 0.82f, 0.86f});
    // The eyes glow but light nothing else (lightSampled off): a light sampler entry would pin
    // them to the world, and two tiny emitters add nothing the torches do not.
    const std::uint32_t eyeMat = addMaterial(scene, "phantom eyes", Vec3{0.0f}, {3.0f, 0.6f, 0.15f});
    scene.materials[eyeMat].lightSampled = false;
    scene.materials[eyeMat].roughness = 1.0f;
    MapUvs uv;
    if (textures) {
        uv = {textures->flatMetres, textures->wallMetres, textures->wallHeightMetres};
        scene.textures = std::move(textures->textures);
    }
    addMap(scene, floorMat, ceilingMat, wallMat, uv);

    scene.prototypes.push_back(phantom(bodyMat, eyeMat));
    const Vec3 start = tileCentre(kPatrolFrom, kCorridorRow);
    scene.instances.push_back({0, Affine::translation(start)});
    NodeMotion patrol;
    patrol.fixed = Affine::translation(start);
    patrol.scripted = ScriptedMotion{};
    patrol.scripted->path = {Vec3{0}, Vec3{float(kPatrolTo - kPatrolFrom) * kTile, 0, 0}};
    patrol.scripted->speed = 1.2f;
    patrol.scripted->repeat = MotionRepeat::BackAndForth;
    scene.instanceAnimations.push_back({0, {patrol}});

    addTorches(scene, torchMat);
    scene.torch.enabled = true;
    scene.torch.intensity = 4.0f;  // candela: the tile ahead, then the dark
    scene.tileGrid = grid();

    // At the west end of the corridor, looking east along it toward the phantom.
    scene.camera.position = tileCentre(1, kCorridorRow) + Vec3{0, scene.tileGrid->eyeHeight, 0};
    scene.camera.lookAt = scene.camera.position + Vec3{1, 0, 0};
    scene.camera.fovYDegrees = 60.0f;
    scene.background = Vec3{0};
    scene.environment.sampled = false;
    return scene;
}

}  // namespace penumbra
