// The bad-input corpus: malformed files of every format the command line reads (OBJ, MTL,
// glTF, GLB, PLY, FBX/Collada/3DS/OFF/STL/X through Assimp, WAD, scene JSON, .hdr and .exr
// environment maps, viewer input scripts), made here rather than committed: truncated, wrong magic, absurd counts and sizes, NaN and infinite
// numbers, cyclic includes, huge images, empty files and directories. Each must end the run
// with one error line, exit code 1 and no output file, inside a memory limit: a loader that
// believes a count before checking it against the file runs out of address space and fails.
#include <cstdint>
#include <cstring>
#include <functional>

#include "cli_fixture.h"

namespace penumbra::test {
namespace {

constexpr std::uint64_t kMemoryLimitBytes = std::uint64_t(1) << 30;

std::string le32(std::uint32_t v) {
    return {char(v & 0xff), char((v >> 8) & 0xff), char((v >> 16) & 0xff), char(v >> 24)};
}
std::string le64(std::uint64_t v) { return le32(std::uint32_t(v)) + le32(std::uint32_t(v >> 32)); }
std::string f32(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    return le32(u);
}

// One triangle (three float positions) as glTF JSON around an accessor and buffer description.
std::string gltf(const std::string& accessor, const std::string& buffer,
                 const std::string& nodes = R"([{"mesh":0}])") {
    return R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":)" + nodes +
           R"(,"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
           R"("bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[)" +
           accessor + R"(],"buffers":[)" + buffer + "]}";
}
const std::string kTriangleBuffer =
    R"({"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA","byteLength":36})";
const std::string kTriangleAccessor = R"({"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"})";

// A binary glTF: 12-byte header, then a JSON chunk whose length field is `jsonLength`.
std::string glb(const std::string& json, std::uint32_t jsonLength, std::uint32_t totalLength) {
    return "glTF" + le32(2) + le32(totalLength) + le32(jsonLength) + "JSON" + json;
}

// A WAD: header, the lumps' bytes, then the directory (offset, size, 8-byte name per lump).
struct Lump {
    std::string name, data;
    std::int64_t sizeOverride = -1, offsetOverride = -1;
};
std::string wad(const std::vector<Lump>& lumps, std::int64_t countOverride = -1) {
    std::string body;
    std::string directory;
    for (const Lump& l : lumps) {
        const std::uint32_t offset = std::uint32_t(l.offsetOverride >= 0 ? l.offsetOverride : 12 + body.size());
        const std::uint32_t size = std::uint32_t(l.sizeOverride >= 0 ? l.sizeOverride : l.data.size());
        std::string name = l.name;
        name.resize(8, '\0');
        directory += le32(offset) + le32(size) + name;
        body += l.data;
    }
    const std::uint32_t count = std::uint32_t(countOverride >= 0 ? countOverride : lumps.size());
    return "PWAD" + le32(count) + le32(std::uint32_t(12 + body.size())) + body + directory;
}
// A map whose VERTEXES lump claims more than it holds, or holds garbage.
std::vector<Lump> mapLumps(const std::string& vertexes, const std::string& linedefs) {
    return {{"E1M1", ""},   {"THINGS", std::string(10, '\0')}, {"LINEDEFS", linedefs}, {"SIDEDEFS", ""},
            {"VERTEXES", vertexes}, {"SEGS", ""}, {"SSECTORS", ""}, {"NODES", ""}, {"SECTORS", ""}};
}

// An OpenEXR header with the attributes a scanline file needs; `width` x `height` pixels.
std::string exrHeader(std::int32_t width, std::int32_t height) {
    auto attr = [](const std::string& name, const std::string& type, const std::string& value) {
        return name + '\0' + type + '\0' + le32(std::uint32_t(value.size())) + value;
    };
    std::string channels;
    for (const char* c : {"B", "G", "R"}) channels += std::string(c) + '\0' + le32(2) + le32(0) + le32(1) + le32(1);
    channels += '\0';
    const std::string box = le32(0) + le32(0) + le32(std::uint32_t(width - 1)) + le32(std::uint32_t(height - 1));
    return std::string("\x76\x2f\x31\x01", 4) + le32(2) + attr("channels", "chlist", channels) +
           attr("compression", "compression", std::string(1, '\0')) + attr("dataWindow", "box2i", box) +
           attr("displayWindow", "box2i", box) + attr("lineOrder", "lineOrder", std::string(1, '\0')) +
           attr("pixelAspectRatio", "float", f32(1)) + attr("screenWindowCenter", "v2f", f32(0) + f32(0)) +
           attr("screenWindowWidth", "float", f32(1)) + '\0';
}

struct Case {
    std::string file;      // created in the scratch folder (a directory when `contents` is kDirectory)
    std::string contents;  // bytes, or kDirectory
    std::string args;      // the command; FILE stands for the file
    std::function<void(const fs::path&)> extra = {};  // more files (sparse ones, includes)
};
const std::string kDirectory = "<directory>";
const std::string kRender = "render FILE --width 8 --height 8 --spp 1 -q -o out.png";
const std::string kRenderEnv = "render cornell --env FILE --width 8 --height 8 --spp 1 -q -o out.png";

void sparseFile(const fs::path& path, std::uintmax_t size) {
    std::ofstream(path) << "v 0 0 0\n";
    fs::resize_file(path, size);
}

std::vector<Case> corpus() {
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    const std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";
    std::string junk;
    for (std::uint32_t i = 0, x = 12345; i < 4096; ++i) junk += char((x = x * 1103515245u + 12345u) >> 24);
    const std::string plyHead = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const std::string plyBinary = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                                  "property float y\nproperty float z\nelement face 1\n"
                                  "property list uchar int vertex_indices\nend_header\n";
    const std::string vertex = std::string(4, '\0');  // one Doom vertex: x, y as int16
    return {
        // OBJ and MTL
        {"empty.obj", "", kRender},
        {"truncated.obj", "v 0 0 0\nv 1 0", kRender},
        {"nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n", kRender},
        {"inf.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n", kRender},
        {"overflow.obj", "v 0 0 0\nv 1 0 0\nv 3e38 3e38 0\nf 1 2 3\n", kRender},
        {"index.obj", tri + "f 1 2 99999999999\n", kRender},
        {"relative.obj", tri + "f -1 -2 -2000000000\n", kRender},
        {"no_vertices.obj", "f 1 2 3\n", kRender},
        {"junk.obj", junk, kRender},
        {"dir.obj", kDirectory, kRender},
        {"huge.obj", "", kRender, [](const fs::path& p) { sparseFile(p, std::uintmax_t(5) << 30); }},
        {"huge_mtl.obj", "mtllib huge.mtl\n" + tri + "f 1 2 3\n", kRender,
         [](const fs::path& p) { sparseFile(p.parent_path() / "huge.mtl", std::uintmax_t(80) << 20); }},
        // glTF
        {"empty.gltf", "", kRender},
        {"truncated.gltf", gltf(kTriangleAccessor, kTriangleBuffer).substr(0, 100), kRender},
        {"not_json.gltf", junk, kRender},
        {"version.gltf", R"({"asset":{"version":"1.0"}})", kRender},
        {"count.gltf", gltf(R"({"bufferView":0,"componentType":5126,"count":2000000000,"type":"VEC3"})", kTriangleBuffer), kRender},
        {"byte_length.gltf",
         gltf(kTriangleAccessor, R"({"uri":"data:application/octet-stream;base64,AAAA","byteLength":1000000000000})"), kRender},
        {"missing_buffer.gltf", gltf(kTriangleAccessor, R"({"uri":"nowhere.bin","byteLength":36})"), kRender},
        {"inf_transform.gltf", gltf(kTriangleAccessor, kTriangleBuffer, R"([{"mesh":0,"scale":[1e999,1,1]}])"), kRender},
        {"cycle.gltf", gltf(kTriangleAccessor, kTriangleBuffer, R"([{"mesh":0,"children":[1]},{"children":[0]}])"), kRender},
        {"dir.gltf", kDirectory, kRender},
        // GLB
        {"empty.glb", "", kRender},
        {"magic.glb", "glTX" + le32(2) + le32(20) + le32(0) + "JSON", kRender},
        {"header.glb", "glTF" + le32(2), kRender},
        {"chunk_length.glb", glb("{}", 0xfffffff0u, 22), kRender},
        {"total_length.glb", glb(R"({"asset":{"version":"2.0"}})", 28, 0xffffffffu), kRender},
        {"version.glb", "glTF" + le32(99) + le32(20) + le32(0) + "JSON", kRender},
        // PLY
        {"empty.ply", "", kRender},
        {"magic.ply", "plx\n" + plyHead.substr(4) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", kRender},
        {"count.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
                      "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                      "end_header\n" + std::string(36, '\0'), kRender},
        {"truncated.ply", plyBinary + std::string(30, '\0'), kRender},
        {"nan.ply", plyHead + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", kRender},
        {"list.ply", plyBinary + std::string(36, '\0') + "\xff" + le32(0) + le32(1), kRender},
        {"no_end.ply", "ply\nformat ascii 1.0\nelement vertex 3\n", kRender},
        {"garbage.ply.gz", std::string("\x1f\x8b\x08\x00", 4) + junk, kRender},
        // formats read through Assimp
        {"empty.fbx", "", kRender},
        {"junk.fbx", "Kaydara FBX Binary  " + std::string("\0\x1a\0", 3) + le32(7400) + junk, kRender},
        {"junk.dae", junk, kRender},
        {"truncated.dae", "<?xml version=\"1.0\"?><COLLADA version=\"1.4.1\"><library_geometries><geometry>", kRender},
        {"junk.3ds", "MM" + le32(4102) + junk, kRender},
        {"count.off", "OFF\n100000000 1 0\n0 0 0\n", kRender},
        {"nan.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex nan 0 0\nvertex 0 1 0\n"
                    "endloop\nendfacet\nendsolid x\n", kRender},
        {"count.stl", std::string(80, ' ') + le32(0x0fffffff) + std::string(50, '\0'), kRender},
        {"junk.x", "xof 0303txt 0032\n" + junk, kRender},
        {"dir.fbx", kDirectory, kRender},
        // WAD
        {"empty.wad", "", kRender},
        {"magic.wad", "XWAD" + le32(0) + le32(12), kRender},
        {"lump_count.wad", wad({}, 0x7fffffff), kRender},
        {"directory.wad", "PWAD" + le32(3) + le32(0x7ffffff0), kRender},
        {"lump_size.wad", wad([&] {
             std::vector<Lump> lumps = mapLumps(vertex, "");
             lumps[4].sizeOverride = 0x7fffffff;  // VERTEXES runs far past the end of the file
             return lumps;
         }()), kRender},
        {"no_map.wad", wad({{"PLAYPAL", std::string(768, '\0')}}), kRender},
        {"map_lines.wad", wad(mapLumps(vertex, le32(0x7fff7fff) + std::string(10, '\0'))), kRender},
        // scene JSON
        {"empty.json", "", kRender},
        {"truncated.json", R"({"meshes": [{"name": "t", "positions": [0, 0)", kRender},
        {"array.json", "[1, 2, 3]", kRender},
        {"inf.json", R"({"meshes":[{"name":"t","positions":[0,0,0, 1e999,0,0, 0,1,0],"indices":[0,1,2]}]})", kRender},
        {"overflow.json",
         R"({"materials":[{"name":"m"}],"meshes":[{"name":"t","material":"m","positions":[0,0,0,1e30,0,0,0,1e30,0],)"
         R"("indices":[0,1,2]}]})", kRender},
        {"self.json", R"({"assets":[{"file":"self.json"}]})", kRender},
        {"cycle_a.json", R"({"assets":[{"file":"cycle_b.json"}]})", kRender,
         [](const fs::path& p) { std::ofstream(p.parent_path() / "cycle_b.json") << R"({"assets":[{"file":"cycle_a.json"}]})"; }},
        {"size.json",
         R"({"render":{"width":1e12},"materials":[{"name":"m"}],)"
         R"("meshes":[{"name":"t","material":"m","positions":[0,0,0,1,0,0,0,1,0],"indices":[0,1,2]}]})",
         "render FILE --spp 1 -q -o out.png"},
        {"dir.json", kDirectory, kRender},
        // environment maps
        {"empty.hdr", "", kRenderEnv},
        {"magic.hdr", "#?NOTRADIANCE\n\n-Y 2 +X 2\n" + std::string(16, '\0'), kRenderEnv},
        {"huge.hdr", hdr + "-Y 100000000 +X 100000000\n" + std::string(64, '\x02'), kRenderEnv},
        {"truncated.hdr", hdr + "-Y 64 +X 64\n" + std::string(40, '\x10'), kRenderEnv},
        {"empty.exr", "", kRenderEnv},
        {"magic.exr", junk, kRenderEnv},
        {"truncated.exr", exrHeader(4, 4).substr(0, 60), kRenderEnv},
        {"huge.exr", exrHeader(200000, 200000) + le64(0), kRenderEnv},
        {"dir.hdr", kDirectory, kRenderEnv},
        // viewer input scripts (read before any window opens)
        {"empty_line_bad.txt", "0 key W down\n0.5 key W sideways\n", "view cornell --script FILE"},
        {"nan_time.txt", "nan key W down\n", "view cornell --script FILE"},
        {"inf_mouse.txt", "0 mouse inf 0\n", "view cornell --script FILE"},
        {"junk_script.txt", junk, "view cornell --script FILE"},
        {"dir_script", kDirectory, "view cornell --script FILE"},
    };
}

class BadInputTest : public CliTest {
protected:
    // Under AddressSanitizer the shadow memory needs terabytes of address space: its own RSS
    // limit stands in for the address-space limit.
    static std::string memoryLimit() {
#if defined(__SANITIZE_ADDRESS__)
        const bool asan = true;
#elif defined(__has_feature)
        const bool asan = __has_feature(address_sanitizer);
#else
        const bool asan = false;
#endif
        const std::uint64_t mib = kMemoryLimitBytes >> 20;
        if (asan) {
            const char* options = std::getenv("ASAN_OPTIONS");
            return "ASAN_OPTIONS=" + std::string(options ? options : "") + ":hard_rss_limit_mb=" + std::to_string(mib);
        }
        return "prlimit --as=" + std::to_string(kMemoryLimitBytes) + " --";
    }
};

TEST_F(BadInputTest, EveryMalformedFileIsOneLineExitOneNoOutputInBoundedMemory) {
    const std::vector<Case> cases = corpus();
    ASSERT_GE(cases.size(), 50u);
    const bool haveViewer = run("view --help").exitCode == 0;  // builds without the viewer have no scripts
    for (const Case& c : cases) {
        if (c.args.rfind("view", 0) == 0 && !haveViewer) continue;
        SCOPED_TRACE(c.file);
        const fs::path work = dir / ("case-" + c.file);
        fs::create_directories(work);
        const fs::path file = work / c.file;
        if (c.contents == kDirectory)
            fs::create_directory(file);
        else
            std::ofstream(file, std::ios::binary) << c.contents;
        if (c.extra) c.extra(file);
        std::string args = c.args;
        args.replace(args.find("FILE"), 4, "'case-" + c.file + "/" + c.file + "'");
        const std::size_t before = filesIn(dir).size();
        const RunResult r = run(args, memoryLimit());
        std::printf("%-22s exit %d: %s", c.file.c_str(), r.exitCode, r.err.c_str());
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_EQ(r.err.rfind("penumbra: error: ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        for (const char* internal : {"std::", "bad_alloc", "basic_string", "out of memory"})
            EXPECT_EQ(r.err.find(internal), std::string::npos) << "an internal message, not what is wrong: " << r.err;
        if (c.contents == kDirectory) {
            EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << "a folder is not a missing file: " << r.err;
        }
        EXPECT_FALSE(fs::exists(dir / "out.png"));
        EXPECT_EQ(filesIn(dir).size(), before) << "a file was left behind";
        fs::remove_all(work);
    }
}

}  // namespace
}  // namespace penumbra::test
