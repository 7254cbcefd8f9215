// The WAD loader on every map of Freedoom (Debian package freedoom). Skips when the WADs are
// not installed, unless the CI environment variable is set.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include "core/error.h"
#include "scene/io/wad/map.h"
#include "scene/io/wad/triangulate.h"
#include "scene/io/wad/wad_file.h"
#include "scene/io/wad/wad_loader.h"
#include "freedoom_wad.h"

namespace penumbra {
namespace {

// Counts as read by the parser equal lump size / record size.
void checkCounts(const std::string& bytes, const std::string& file, const std::string& mapName) {
    wad::WadFile wad(bytes, file);
    const wad::MapLumps* lumps = nullptr;
    std::vector<wad::MapLumps> maps = wad::findMaps(wad);
    for (const wad::MapLumps& m : maps)
        if (m.name == mapName) lumps = &m;
    ASSERT_TRUE(lumps);
    wad::MapData map = wad::parseMap(wad, *lumps);
    auto size = [&](long i) { return std::size_t(wad.lumps()[std::size_t(i)].size); };
    EXPECT_EQ(map.vertices.size(), size(lumps->vertexes) / wad::kVertexBytes);
    EXPECT_EQ(map.linedefs.size(), size(lumps->linedefs) / wad::kLinedefBytes);
    EXPECT_EQ(map.sidedefs.size(), size(lumps->sidedefs) / wad::kSidedefBytes);
    EXPECT_EQ(map.sectors.size(), size(lumps->sectors) / wad::kSectorBytes);
    EXPECT_EQ(map.things.size(), size(lumps->things) / wad::kThingBytes);
    EXPECT_GT(map.sectors.size(), 10u);
    EXPECT_EQ(size(lumps->linedefs) % wad::kLinedefBytes, 0u);
}

TEST(WadFreedoom, E1M1Counts) {
    REQUIRE_WAD(bytes, "freedoom1.wad");
    checkCounts(bytes, "freedoom1.wad", "E1M1");
}

TEST(WadFreedoom, Map01Counts) {
    REQUIRE_WAD(bytes, "freedoom2.wad");
    checkCounts(bytes, "freedoom2.wad", "MAP01");
}

double triArea(const Mesh& m, std::size_t t) {
    Vec3 p0 = m.positions[m.indices[3 * t]], p1 = m.positions[m.indices[3 * t + 1]],
         p2 = m.positions[m.indices[3 * t + 2]];
    return 0.5 * length(cross(p1 - p0, p2 - p0));
}

struct MapReport {
    int sectors = 0, degenerate = 0, mismatched = 0;
};

// Every sector gets a floor and a ceiling whose area is the area enclosed by its outline,
// computed here independently (shoelace over the sector's own sides, in Doom units).
void checkMap(const std::string& bytes, const std::string& file, const wad::MapLumps& lumps,
              MapReport& report) {
    wad::WadFile wad(bytes, file);
    wad::MapData map = wad::parseMap(wad, lumps);
    Scene scene = loadWadFromMemory(bytes, lumps.name, file);
    scene.validate();
    EXPECT_TRUE(isFinite(scene.camera.position));
    validateCamera(scene.camera);

    std::vector<double> floorArea(map.sectors.size()), ceilingArea(map.sectors.size());
    for (const Mesh& m : test::worldAndMovingMeshes(scene)) {
        for (Vec3 p : m.positions) ASSERT_TRUE(isFinite(p)) << m.name;
        for (Vec3 n : m.normals) ASSERT_NEAR(length(n), 1.0f, 1e-5f) << m.name;
        ASSERT_GE(m.lightLevel, 0.0f);
        ASSERT_LE(m.lightLevel, 1.0f);
        for (Vec2 uv : m.uvs) ASSERT_TRUE(std::isfinite(uv.x) && std::isfinite(uv.y)) << m.name;
        ASSERT_EQ(m.normals.size(), m.positions.size());
        ASSERT_EQ(m.uvs.size(), m.positions.size());
        int sector = -1;
        char part[16] = {};
        std::string prefix = lumps.name + " sector %d %15s";
        ASSERT_EQ(std::sscanf(m.name.c_str(), prefix.c_str(), &sector, part), 2) << m.name;
        ASSERT_LT(std::size_t(sector), map.sectors.size());
        double a = 0;
        for (std::size_t t = 0; t < m.triangleCount(); ++t) {
            double ta = triArea(m, t);
            if (std::string(part) == "walls") {
                EXPECT_GT(ta, 0.0) << m.name << " triangle " << t;
            }
            a += ta;
        }
        a *= 32.0 * 32.0;  // back to Doom units
        if (std::string(part) == "floor") floorArea[std::size_t(sector)] += a;
        if (std::string(part) == "ceiling") ceilingArea[std::size_t(sector)] += a;
    }

    // The sector's sides, directed with the sector on the right.
    std::vector<std::map<std::pair<int, int>, int>> balance(map.sectors.size());
    std::vector<double> shoelace(map.sectors.size());
    for (const wad::Linedef& l : map.linedefs) {
        const wad::Vertex& a = map.vertices[l.v1];
        const wad::Vertex& b = map.vertices[l.v2];
        int fs = l.front != wad::kNoSide ? map.sidedefs[l.front].sector : -1;
        int bs = l.back != wad::kNoSide ? map.sidedefs[l.back].sector : -1;
        if (fs == bs) continue;
        double cr = double(a.x) * b.y - double(b.x) * a.y;
        if (fs >= 0) {
            shoelace[std::size_t(fs)] += 0.5 * cr;
            ++balance[std::size_t(fs)][{a.x, a.y}];
            --balance[std::size_t(fs)][{b.x, b.y}];
        }
        if (bs >= 0) {
            shoelace[std::size_t(bs)] -= 0.5 * cr;
            --balance[std::size_t(bs)][{a.x, a.y}];
            ++balance[std::size_t(bs)][{b.x, b.y}];
        }
    }
    for (std::size_t s = 0; s < map.sectors.size(); ++s) {
        ++report.sectors;
        bool closed = true;
        for (const auto& [v, b] : balance[s]) closed = closed && b == 0;
        double expected = std::abs(shoelace[s]);
        if (!closed || expected == 0) {
            ++report.degenerate;  // unclosed outline or no area at all
            continue;
        }
        EXPECT_NEAR(ceilingArea[s], floorArea[s], 1e-3 * expected) << file << " " << lumps.name;
        if (std::abs(floorArea[s] - expected) > 1e-3 * expected) {
            ++report.mismatched;
            ADD_FAILURE() << file << " " << lumps.name << " sector " << s << ": floor area "
                          << floorArea[s] << ", outline area " << expected;
        }
    }
}

void checkAllMaps(const std::string& bytes, const std::string& file) {
    auto start = std::chrono::steady_clock::now();
    wad::WadFile wad(bytes, file);
    std::vector<wad::MapLumps> maps = wad::findMaps(wad);
    EXPECT_EQ(wadMapNames(bytes).size(), maps.size());
    int sectors = 0, degenerate = 0;
    for (const wad::MapLumps& lumps : maps) {
        MapReport r;
        checkMap(bytes, file, lumps, r);
        sectors += r.sectors;
        degenerate += r.degenerate;
        if (r.degenerate > 0)
            std::printf("%s %s: %d of %d sectors have unclosed or empty outlines\n", file.c_str(),
                        lumps.name.c_str(), r.degenerate, r.sectors);
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %zu maps, %d sectors (%d degenerate) checked in %.2f s\n", file.c_str(),
                maps.size(), sectors, degenerate, seconds);
    EXPECT_LE(degenerate, sectors / 100 + 5);
}

TEST(WadFreedoom, EveryMapOfFreedoom1) {
    REQUIRE_WAD(bytes, "freedoom1.wad");
    checkAllMaps(bytes, "freedoom1.wad");
}

TEST(WadFreedoom, EveryMapOfFreedoom2) {
    REQUIRE_WAD(bytes, "freedoom2.wad");
    checkAllMaps(bytes, "freedoom2.wad");
}

TEST(WadFreedoom, LoadTimeOfEveryMap) {
    REQUIRE_WAD(wad1, "freedoom1.wad");
    REQUIRE_WAD(wad2, "freedoom2.wad");
    auto start = std::chrono::steady_clock::now();
    std::size_t triangles = 0, maps = 0, lights = 0;
    for (const std::string* bytes : {&wad1, &wad2})
        for (const std::string& name : wadMapNames(*bytes)) {
            Scene scene = loadWadFromMemory(*bytes, name, "freedoom.wad");
            triangles += scene.triangleCount();
            lights += scene.lights.size();
            ++maps;
        }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("loaded %zu maps (%zu triangles, %zu lights) in %.2f s\n", maps, triangles, lights,
                seconds);
    EXPECT_EQ(maps, 36u + 32u);
}

TEST(WadFreedoom, LoadFromFile) {
    std::filesystem::path path = std::filesystem::path(test::kDoomDir) / "freedoom1.wad";
    if (!std::filesystem::exists(path)) {
        if (std::getenv("CI")) FAIL() << path << " is missing";
        GTEST_SKIP() << path << " is not installed";
    }
    Scene scene = loadWad(path, "e1m1");
    EXPECT_GT(scene.triangleCount(), 1000u);
    EXPECT_GT(scene.textures.size(), 10u);
    try {
        loadWad(path, "E7M7");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("freedoom1.wad: no map named E7M7"), std::string::npos);
    }
}

}  // namespace
}  // namespace penumbra

namespace penumbra {
namespace {

// What E1M1 of Freedoom brings besides geometry: glowing textures and flats, sector light, the
// sky and its portals, animated textures and sprites, counted. The counts are this importer's on
// Debian 12's freedoom1.wad (0.12.1): a change in them is a change in what is lit or drawn (or
// another Freedoom).
TEST(WadFreedoom, E1M1GlowsSectorLightSkyAndSprites) {
    REQUIRE_WAD(bytes, "freedoom1.wad");
    Scene scene = loadWadFromMemory(bytes, "E1M1", "freedoom1.wad");
    std::size_t glowing = 0, sectorLit = 0, sky = 0;
    std::map<std::string, std::size_t> glowingByMaterial;
    for (const Mesh& m : test::worldAndMovingMeshes(scene)) {
        const Material& mat = scene.materials[m.material];
        if (mat.skyPortal) sky += m.triangleCount();
        else if (mat.emissionHiddenFromCamera) sectorLit += m.triangleCount();
        else if (mat.isEmissive()) glowing += m.triangleCount(), glowingByMaterial[mat.name] += m.triangleCount();
    }
    std::size_t animated = 0, eightViews = 0;
    for (const Texture& t : scene.textures) animated += t.animation.frames > 1;
    for (const Sprite& s : scene.sprites) eightViews += s.rotations == 8;
    std::printf("E1M1: %zu glowing, %zu sector-lit, %zu sky triangles; %zu animated textures; %zu sprites (%zu with 8 views)\n",
                glowing, sectorLit, sky, animated, scene.sprites.size(), eightViews);
    for (const auto& [name, count] : glowingByMaterial) std::printf("  %s: %zu\n", name.c_str(), count);
    EXPECT_EQ(glowing, 420u);
    EXPECT_EQ(glowingByMaterial["wall LITE5"], 28u);
    EXPECT_EQ(glowingByMaterial["flat NUKAGE1"], 128u);
    EXPECT_EQ(sectorLit, 1906u);
    EXPECT_EQ(sky, 248u);
    EXPECT_EQ(animated, 15u);  // NUKAGE1-3, FWATER1-4, SFALL1-4, WFALL1-4
    EXPECT_EQ(scene.sprites.size(), 169u);
    EXPECT_EQ(eightViews, 25u);
    EXPECT_EQ(scene.lights.size(), 7u);
    ASSERT_TRUE(scene.environment.map.has_value());
    EXPECT_EQ(scene.environment.map->name, "SKY1");
    EXPECT_NO_THROW(scene.validate());
}

}  // namespace
}  // namespace penumbra
