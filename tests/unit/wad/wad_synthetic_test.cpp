// The WAD loader on small WADs written here byte by byte.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "scene/io/wad/sector_light.h"
#include "scene/io/wad/wad_loader.h"
#include "wad_builder.h"

namespace penumbra {
namespace {
using testing::MapBuilder;
using testing::WadBuilder;

std::string roomWad() {
    WadBuilder wad;
    testing::roomWithPillar().addTo(wad, "E1M1");
    testing::addTestGraphics(wad);
    return wad.build("IWAD");
}

const Mesh* findMesh(const Scene& scene, const std::string& part) {
    for (const Mesh& m : scene.meshes)
        if (m.name.find(part) != std::string::npos) return &m;
    return nullptr;
}

Vec3 triNormal(const Mesh& m, std::size_t t) {
    Vec3 p0 = m.positions[m.indices[3 * t]], p1 = m.positions[m.indices[3 * t + 1]],
         p2 = m.positions[m.indices[3 * t + 2]];
    return cross(p1 - p0, p2 - p0);  // length = twice the area
}

double area(const Mesh& m) {
    double a = 0;
    for (std::size_t t = 0; t < m.triangleCount(); ++t) a += 0.5 * length(triNormal(m, t));
    return a;
}

std::string errorOf(const std::string& bytes, const std::string& map = "") {
    try {
        loadWadFromMemory(bytes, map, "test.wad");
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(WadSynthetic, RoomWithPillarFloorsCeilingsWalls) {
    Scene scene = loadWadFromMemory(roomWad(), "", "test.wad");
    const Mesh* floor = findMesh(scene, "sector 0 floor");
    const Mesh* ceiling = findMesh(scene, "sector 0 ceiling");
    const Mesh* walls = findMesh(scene, "sector 0 walls");
    ASSERT_TRUE(floor && ceiling && walls);
    // (256^2 - 64^2) units^2 at 32 units per metre = 60 m^2, as 4 slabs of 2 triangles.
    EXPECT_EQ(floor->triangleCount(), 8u);
    EXPECT_EQ(ceiling->triangleCount(), 8u);
    EXPECT_NEAR(area(*floor), 60.0, 1e-4);
    EXPECT_NEAR(area(*ceiling), 60.0, 1e-4);
    for (std::size_t t = 0; t < 8; ++t) {
        EXPECT_GT(triNormal(*floor, t).y, 0) << "floors face up";
        EXPECT_LT(triNormal(*ceiling, t).y, 0) << "ceilings face down";
    }
    for (Vec3 p : floor->positions) EXPECT_EQ(p.y, 0.0f);
    for (Vec3 p : ceiling->positions) EXPECT_EQ(p.y, 4.0f);
    EXPECT_NEAR(floor->lightLevel, 160.0f / 255.0f, 1e-6);
    // The sector's fill light leaves floor and ceiling, unseen by the camera and found only by
    // rays that hit them (light sampling would spend its picks on them).
    for (const Mesh* flat : {floor, ceiling}) {
        const Material& m = scene.materials[flat->material];
        EXPECT_FLOAT_EQ(m.emission.x, wad::sectorRadiance(160));
        EXPECT_TRUE(m.emissionHiddenFromCamera);
        EXPECT_FALSE(m.lightSampled);
    }

    // 8 one-sided walls of 128 units (4 m), each a quad facing into the room.
    ASSERT_EQ(walls->triangleCount(), 16u);
    EXPECT_NEAR(area(*walls), (4 * 8.0 + 4 * 2.0) * 4.0, 1e-4);
    const Vec3 roomCentre(4, 2, -4);
    for (std::size_t t = 0; t < 16; ++t) {
        Vec3 n = normalize(triNormal(*walls, t));
        Vec3 p = walls->positions[walls->indices[3 * t]];
        Vec3 toCentre = roomCentre - p;
        bool pillar = std::abs(p.x - 4) <= 1.01f && std::abs(p.z + 4) <= 1.01f;
        // Outer walls face the centre; pillar walls face away from it.
        EXPECT_GT(dot(n, toCentre) * (pillar ? -1 : 1), 0) << "wall triangle " << t;
        EXPECT_NEAR(std::abs(n.y), 0.0f, 1e-6);
        EXPECT_EQ(n, normalize(walls->normals[walls->indices[3 * t]]));
    }
    // WALL1 is 16x16: a 256-unit wall spans 16 repeats in u, 128 units 8 in v.
    float uMin = 1e9f, uMax = -1e9f, vMin = 1e9f, vMax = -1e9f;
    for (std::size_t i = 0; i < 4; ++i) {
        uMin = std::min(uMin, walls->uvs[i].x), uMax = std::max(uMax, walls->uvs[i].x);
        vMin = std::min(vMin, walls->uvs[i].y), vMax = std::max(vMax, walls->uvs[i].y);
    }
    EXPECT_FLOAT_EQ(uMax - uMin, 16.0f);
    EXPECT_FLOAT_EQ(vMin, 0.0f);  // upper-pegged: texture top at the ceiling
    EXPECT_FLOAT_EQ(vMax, 8.0f);

    // Player start at (64, 64) facing 90 degrees (north, Doom +y = our -z), eyes 41 up.
    EXPECT_NEAR(scene.camera.position.x, 2.0f, 1e-6);
    EXPECT_NEAR(scene.camera.position.y, 41.0f / 32.0f, 1e-6);
    EXPECT_NEAR(scene.camera.position.z, -2.0f, 1e-6);
    Vec3 dir = scene.camera.lookAt - scene.camera.position;
    EXPECT_NEAR(dir.x, 0.0f, 1e-6);
    EXPECT_NEAR(dir.z, -1.0f, 1e-6);
    EXPECT_FLOAT_EQ(scene.camera.fovYDegrees, 70.0f);

    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_NEAR(scene.lights[0].position.x, 200.0f / 32, 1e-5);
    EXPECT_NEAR(scene.lights[0].position.z, -200.0f / 32, 1e-5);
    EXPECT_GT(scene.lights[0].position.y, 0.5f);
    EXPECT_LT(scene.lights[0].position.y, 4.0f);

    // Textures: WALL1, FLOOR1, CEIL1, each decoded once, with the patch's holes transparent.
    ASSERT_EQ(scene.textures.size(), 3u);
    const Texture& wall = scene.textures[scene.materials[walls->material].albedoTexture.texture];
    EXPECT_EQ(wall.name, "WALL1");
    EXPECT_EQ(wall.width, 16);
    EXPECT_EQ(wall.rgba[3], 255);                      // (0, 0) painted
    EXPECT_EQ(wall.rgba[(7 * 16 + 0) * 4 + 3], 0);     // (0, 7) is below the post
    EXPECT_EQ(wall.rgba[(15 * 16 + 8) * 4 + 3], 0);    // (8, 15) second patch's hole
    EXPECT_EQ(wall.rgba[(9 * 16 + 9) * 4 + 3], 255);   // (9, 9) second patch
    EXPECT_EQ(wall.rgba[0], 1);                        // palette index 1 -> red 1
    EXPECT_TRUE(wall.srgb);
    EXPECT_FLOAT_EQ(scene.materials[walls->material].albedo.x, 1.0f);
}

// Two rooms side by side: the east one has a higher floor and lower ceiling, both skies.
std::string stepWad(bool sky, int flags) {
    MapBuilder m;
    int a = m.sector(0, 128, "FLOOR1", sky ? "F_SKY1" : "CEIL1", 200);
    int b = m.sector(32, 96, "FLOOR1", sky ? "F_SKY1" : "CEIL1", 100);
    int v0 = m.vertex(0, 0), v1 = m.vertex(0, 128), v2 = m.vertex(128, 128), v3 = m.vertex(128, 0);
    int v4 = m.vertex(256, 128), v5 = m.vertex(256, 0);
    m.line(v0, v1, m.side(a, "-", "-", "WALL1"));
    m.line(v1, v2, m.side(a, "-", "-", "WALL1"));
    m.line(v3, v0, m.side(a, "-", "-", "WALL1"));
    // Shared line v2 -> v3: front (right, west... ) faces room a.
    m.line(v2, v3, m.side(a, "WALL1", "TALL1", "WALL1"), m.side(b, "WALL1", "TALL1", "-"),
           4 | flags);
    m.line(v2, v4, m.side(b, "-", "-", "WALL1"));
    m.line(v4, v5, m.side(b, "-", "-", "WALL1"));
    m.line(v5, v3, m.side(b, "-", "-", "WALL1"));
    m.thing(64, 64, 0, 1);
    WadBuilder wad;
    m.addTo(wad, "MAP01");
    testing::addTestGraphics(wad);
    return wad.build();
}

TEST(WadSynthetic, TwoSidedUpperLowerMaskedAndSky) {
    Scene scene = loadWadFromMemory(stepWad(false, 0), "map01", "step.wad");
    const Mesh* walls = findMesh(scene, "sector 0 walls wall WALL1");
    const Mesh* lower = findMesh(scene, "sector 0 walls wall TALL1");
    const Mesh* masked = findMesh(scene, "sector 0 walls masked WALL1");
    ASSERT_TRUE(walls && lower && masked);
    // Lower: from 0 to 32 along 128 units = 4 m x 1 m; pegged to the higher floor (v from 0).
    EXPECT_NEAR(area(*lower), 4.0, 1e-5);
    for (Vec2 uv : lower->uvs) EXPECT_TRUE(uv.y == 0.0f || uv.y == 1.0f);
    // One-sided walls of room a (3 x 4 m high: 4 + 4 + 4 m wide) and the upper 96..128.
    EXPECT_NEAR(area(*walls), 3 * 4.0 * 4.0 + 4.0 * 1.0, 1e-4);
    // Masked middle: drawn once (16 units) from the lower ceiling down.
    EXPECT_NEAR(area(*masked), 4.0 * 0.5, 1e-5);
    EXPECT_FLOAT_EQ(scene.materials[masked->material].alphaCutoff, 0.5f);
    for (Vec3 p : masked->positions) EXPECT_TRUE(p.y == 3.0f || p.y == 2.5f);
    // Room b sees nothing on its side of the shared line: no step faces it.
    const Mesh* bWalls = findMesh(scene, "sector 1 walls wall WALL1");
    ASSERT_TRUE(bWalls);
    EXPECT_NEAR(area(*bWalls), 4 * 2.0 * 3 - 0, 1e-4);  // 3 walls 4 m wide, 2 m high (32..96)
    EXPECT_EQ(findMesh(scene, "sector 1 walls wall TALL1"), nullptr);

    // Lower unpegged: the lower texture starts at the front ceiling (128): v from 96 to 128.
    Scene unpegged = loadWadFromMemory(stepWad(false, 0x10), "MAP01", "step.wad");
    lower = findMesh(unpegged, "sector 0 walls wall TALL1");
    ASSERT_TRUE(lower);
    for (Vec2 uv : lower->uvs) EXPECT_TRUE(uv.y == 3.0f || uv.y == 4.0f) << uv.y;

    // Sky: the upper between two sky ceilings disappears; ceilings become portals onto the sky
    // (without a SKY1 texture, the constant background) that bring their sector's fill light.
    Scene sky = loadWadFromMemory(stepWad(true, 0), "MAP01", "step.wad");
    walls = findMesh(sky, "sector 0 walls wall WALL1");
    ASSERT_TRUE(walls);
    EXPECT_NEAR(area(*walls), 3 * 4.0 * 4.0, 1e-4);
    const Mesh* ceiling = findMesh(sky, "sector 0 ceiling");
    ASSERT_TRUE(ceiling);
    const Material& m = sky.materials[ceiling->material];
    EXPECT_TRUE(m.isEmissive());
    EXPECT_FALSE(m.twoSided);
    EXPECT_FALSE(m.albedoTexture.present());
    EXPECT_TRUE(m.skyPortal);
    EXPECT_TRUE(m.emissionHiddenFromCamera);
    EXPECT_FLOAT_EQ(m.emission.x, wad::sectorRadiance(200));
    EXPECT_FALSE(sky.environment.map.has_value());
    // Emission leaves the counter-clockwise front face: it must face down into the room.
    for (std::size_t t = 0; t < ceiling->triangleCount(); ++t) EXPECT_LT(triNormal(*ceiling, t).y, 0);
}

TEST(WadSynthetic, MissingTexturesGetAChecker) {
    WadBuilder wad;
    MapBuilder m;
    int s = m.sector(0, 64, "NOFLAT", "NOFLAT", 255);
    m.loop({{0, 0}, {0, 64}, {64, 64}, {64, 0}}, s, "NOTEX");
    m.addTo(wad, "E1M1");
    Scene scene = loadWadFromMemory(wad.build(), "E1M1", "bare.wad");
    ASSERT_EQ(scene.textures.size(), 2u);  // one checker per missing name
    EXPECT_EQ(scene.textures[0].width, 64);
    EXPECT_EQ(scene.textures[0].rgba[0], 255);
    EXPECT_EQ(scene.textures[0].rgba[1], 0);
}

TEST(WadSynthetic, UnclosedSectorIsClosed) {
    MapBuilder m;
    int s = m.sector(0, 64, "FLOOR1", "CEIL1", 255);
    int a = m.vertex(0, 0), b = m.vertex(0, 64), c = m.vertex(64, 64), d = m.vertex(64, 0);
    m.line(a, b, m.side(s, "-", "-", "WALL1"));
    m.line(b, c, m.side(s, "-", "-", "WALL1"));
    m.line(c, d, m.side(s, "-", "-", "WALL1"));  // d -> a missing
    WadBuilder wad;
    m.addTo(wad, "E1M1");
    testing::addTestGraphics(wad);
    Scene scene = loadWadFromMemory(wad.build(), "", "open.wad");
    const Mesh* floor = findMesh(scene, "sector 0 floor");
    ASSERT_TRUE(floor);
    EXPECT_NEAR(area(*floor), 4.0, 1e-5);
}

TEST(WadSynthetic, MapNames) {
    WadBuilder wad;
    testing::roomWithPillar().addTo(wad, "E1M1");
    testing::roomWithPillar().addTo(wad, "E1M2");
    EXPECT_EQ(wadMapNames(wad.build()), (std::vector<std::string>{"E1M1", "E1M2"}));
    EXPECT_NE(errorOf(wad.build(), "E9M9").find("no map named E9M9"), std::string::npos);
}

TEST(WadSynthetic, MalformedInputsSayWhatIsWrong) {
    const std::string good = roomWad();
    EXPECT_NE(errorOf("PWAD").find("shorter than the 12-byte header"), std::string::npos);
    EXPECT_NE(errorOf("JUNKJUNKJUNKJUNK").find("not a WAD"), std::string::npos);

    // Truncated directory: cut the last directory entry in half.
    std::string e = errorOf(good.substr(0, good.size() - 8));
    EXPECT_NE(e.find("truncated directory"), std::string::npos) << e;

    // Absurd lump count.
    std::string absurd = good;
    absurd[4] = absurd[5] = absurd[6] = char(0xFF);
    absurd[7] = 0x7F;
    e = errorOf(absurd);
    EXPECT_NE(e.find("absurd lump count"), std::string::npos) << e;

    // LINEDEFS (the third directory entry) moved past the end of the file.
    WadBuilder wad;
    testing::roomWithPillar().addTo(wad, "E1M1");
    std::string bad = wad.build();
    std::size_t dir = std::size_t(std::uint8_t(bad[8])) | std::size_t(std::uint8_t(bad[9])) << 8;
    bad[dir + 2 * 16 + 4 + 2] = 0x10;  // size += 1 MiB
    e = errorOf(bad);
    EXPECT_EQ(e, "test.wad: lump LINEDEFS of E1M1 ends past the end of the file") << e;
    bad[dir + 2 * 16 + 3] = 0x70;
    e = errorOf(bad);
    EXPECT_NE(e.find("lump LINEDEFS of E1M1 starts past the end of the file"), std::string::npos) << e;

    // A linedef referencing a vertex that does not exist.
    MapBuilder m = testing::roomWithPillar();
    m.line(0, 999, 0);
    WadBuilder badVertex;
    m.addTo(badVertex, "E1M1");
    e = errorOf(badVertex.build());
    EXPECT_NE(e.find("linedef 8 references vertex 999, but the map has 8 vertices"), std::string::npos) << e;

    // A sidedef referencing a sector that does not exist, and a bad sidedef index.
    MapBuilder ms = testing::roomWithPillar();
    ms.side(7, "-", "-", "-");
    WadBuilder badSector;
    ms.addTo(badSector, "E1M1");
    e = errorOf(badSector.build());
    EXPECT_NE(e.find("sidedef 8 references sector 7"), std::string::npos) << e;
    MapBuilder ml = testing::roomWithPillar();
    ml.line(0, 1, 0, 500);
    WadBuilder badSide;
    ml.addTo(badSide, "E1M1");
    e = errorOf(badSide.build());
    EXPECT_NE(e.find("references sidedef 500"), std::string::npos) << e;

    // An empty map (marker and empty lumps), and a WAD without maps.
    WadBuilder empty;
    MapBuilder().addTo(empty, "E1M1");
    e = errorOf(empty.build());
    EXPECT_NE(e.find("map E1M1 is empty"), std::string::npos) << e;
    WadBuilder noMaps;
    testing::addTestGraphics(noMaps);
    e = errorOf(noMaps.build());
    EXPECT_NE(e.find("contains no maps"), std::string::npos) << e;

    // A missing lump is named.
    WadBuilder noSectors;
    MapBuilder r = testing::roomWithPillar();
    noSectors.add("E1M1");
    noSectors.add("THINGS", r.things);
    noSectors.add("LINEDEFS", r.linedefs);
    noSectors.add("SIDEDEFS", r.sidedefs);
    noSectors.add("VERTEXES", r.vertexes);
    e = errorOf(noSectors.build());
    EXPECT_NE(e.find("has no SECTORS lump"), std::string::npos) << e;
}

TEST(WadSynthetic, TruncationsNeverCrash) {
    const std::string good = roomWad();
    int errors = 0;
    for (std::size_t n = 0; n < good.size(); n += 7) {
        std::string cut = good.substr(0, n);
        try {
            loadWadFromMemory(cut, "", "cut.wad");
        } catch (const Error&) {
            ++errors;
        }
    }
    EXPECT_GT(errors, 0);
}

}  // namespace
}  // namespace penumbra
