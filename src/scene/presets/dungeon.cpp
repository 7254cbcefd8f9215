// The dungeon: a 16 x 16 tile map (the second scene of the WebGPU Doom-style renderer), walls,
// floor and ceiling built once as world meshes, lit by the player's torch and by torches hung on
// the walls (point lights), with a phantom whose eyes glow patrolling the southern corridor. The
// phantom is one instance moved by a scene motion (scene/object_motion.h), so only the top level
// changes while it walks; the light sampler picks the torches that matter at each point, which is
// the job the WebGPU renderer's per-tile BVH copies did.
#include <array>
#include <cmath>

#include "core/error.h"
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

// The phantom's corridor: row 13, patrolled between these columns.
constexpr int kCorridorRow = 13;
constexpr int kPatrolFrom = 3, kPatrolTo = 13;

bool isWall(int x, int z) { return x < 0 || z < 0 || x >= kSize || z >= kSize || kMap[std::size_t(z)][x] == '#'; }

Vec3 tileCentre(int x, int z) { return {(float(x) + 0.5f) * kTile, 0.0f, (float(z) + 0.5f) * kTile}; }

// Floor and ceiling of every floor tile, and a wall quad on each side that faces a wall tile.
void addMap(Scene& scene, std::uint32_t floorMat, std::uint32_t ceilingMat, std::uint32_t wallMat) {
    Mesh floor{"floor"}, ceiling{"ceiling"}, walls{"walls"};
    floor.material = floorMat;
    ceiling.material = ceilingMat;
    walls.material = wallMat;
    const Vec3 up{0, 1, 0};
    for (int z = 0; z < kSize; ++z)
        for (int x = 0; x < kSize; ++x) {
            if (isWall(x, z)) continue;
            const float x0 = float(x) * kTile, x1 = x0 + kTile, z0 = float(z) * kTile, z1 = z0 + kTile;
            addQuad(floor, {x0, 0, z0}, {x0, 0, z1}, {x1, 0, z1}, {x1, 0, z0});
            addQuad(ceiling, {x0, kWallHeight, z0}, {x1, kWallHeight, z0}, {x1, kWallHeight, z1}, {x0, kWallHeight, z1});
            const int sides[4][2] = {{0, -1}, {0, 1}, {-1, 0}, {1, 0}};
            for (const auto& side : sides) {
                if (!isWall(x + side[0], z + side[1])) continue;
                // Seen from inside the tile, looking at the wall: right = toward x up.
                const Vec3 toward{float(side[0]), 0, float(side[1])};
                const Vec3 right = cross(toward, up);
                const Vec3 c = tileCentre(x, z) + toward * (0.5f * kTile);
                const Vec3 h = right * (0.5f * kTile), top{0, kWallHeight, 0};
                addQuad(walls, c - h, c + h, c + h + top, c - h + top);
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

void addTorches(Scene& scene) {
    for (const WallTorch& t : kTorches) {
        if (isWall(t.x, t.z) || !isWall(t.x + t.dx, t.z + t.dz))
            throw Error("dungeon: a wall torch is not on a floor tile next to a wall");  // a map edit gone wrong
        Light light;
        light.name = "wall torch";
        light.position = tileCentre(t.x, t.z) + Vec3{float(t.dx), 0, float(t.dz)} * (0.5f * kTile - 0.2f) +
                         Vec3{0, 2.1f, 0};
        light.color = {1.0f, 0.62f, 0.3f};  // flame
        light.intensity = 6.0f;            // candela: a tile or two around it are well lit
        light.radius = 0.06f;              // soft shadows
        scene.lights.push_back(light);
    }
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

Scene makeDungeon() {
    Scene scene;
    scene.name = "dungeon";
    const std::uint32_t floorMat = addMaterial(scene, "flagstones", {0.32f, 0.29f, 0.25f});
    const std::uint32_t ceilingMat = addMaterial(scene, "vault", {0.22f, 0.21f, 0.2f});
    const std::uint32_t wallMat = addMaterial(scene, "stone", {0.45f, 0.41f, 0.36f});
    const std::uint32_t bodyMat = addMaterial(scene, "shroud", {0.78f, 0.82f, 0.86f});
    // The eyes glow but light nothing else (lightSampled off): a light sampler entry would pin
    // them to the world, and two tiny emitters add nothing the torches do not.
    const std::uint32_t eyeMat = addMaterial(scene, "phantom eyes", Vec3{0.0f}, {3.0f, 0.6f, 0.15f});
    scene.materials[eyeMat].lightSampled = false;
    scene.materials[eyeMat].roughness = 1.0f;
    addMap(scene, floorMat, ceilingMat, wallMat);

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

    addTorches(scene);
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
