// An asset placed by a scene file (scale, rotate, translate) must render as the same mesh with the
// placement baked into its file: positions through the placement, normals through its inverse
// transpose, computed here from the placement's parts (R S^-1 n, independent of Affine::normal),
// and a mirror's winding reversed as any exporter would. As Wavefront OBJ with vertex normals and
// as glTF, each a coarse smooth sphere squashed into an ellipsoid (so the inverse transpose differs
// from the transform itself) in a glossy metal that shows where its normals point, placed in
// front of the spheres of the area-lit test world.
#include <sstream>

#include "../unit/image/test_dir.h"
#include "../unit/io/mesh_files.h"
#include "core/transform.h"
#include "gpu_fixture.h"
#include "render_compare.h"
#include "scene/io/scene_json.h"
#include "test_worlds.h"

namespace penumbra::test {
namespace {

struct Placement {
    Vec3 scale, rotate, translate;

    std::string keys() const {
        std::ostringstream s;
        s.precision(9);
        auto v = [&](const char* key, Vec3 a) {
            s << '"' << key << "\": [" << a.x << ", " << a.y << ", " << a.z << "]";
        };
        v("scale", scale);
        s << ", ";
        v("rotate", rotate);
        s << ", ";
        v("translate", translate);
        return s.str();
    }
};

// The mesh with the placement applied to its vertex data.
Mesh baked(const Mesh& mesh, const Placement& p) {
    const Affine rotation = Affine::eulerDegrees(p.rotate);
    const Affine placement = Affine::translation(p.translate) * rotation * Affine::scaling(p.scale);
    Mesh out = mesh;
    for (Vec3& v : out.positions) v = placement.point(v);
    for (Vec3& n : out.normals) n = normalize(rotation.vector(n / p.scale));
    if (p.scale.x * p.scale.y * p.scale.z < 0)
        for (std::size_t i = 0; i < out.indices.size(); i += 3)
            std::swap(out.indices[i + 1], out.indices[i + 2]);
    return out;
}

// The area-lit test world with the asset in front, in a glossy metal given by the scene file.
std::string sceneWith(const std::string& file, const std::string& placementKeys) {
    return R"({"assets": [{"file": "world.json"}, {"file": ")" + file + "\"" +
           (placementKeys.empty() ? "" : ", " + placementKeys) + R"(, "material": "shiny"}],
              "materials": [{"name": "shiny", "metallic": 1, "roughness": 0.45, "albedo": [0.95, 0.75, 0.5]}]})";
}

void expectPlacedRendersAsBaked(const gpu::Context& ctx, const std::string& format,
                                const Placement& placement) {
    TempDir dir;
    const Mesh sphere = smoothSphere(Vec3{0}, 1.0f, 8, 12, 0);
    if (format == "obj") {
        writeObj(dir / "mesh.obj", sphere);
        writeObj(dir / "baked.obj", baked(sphere, placement));
    } else {
        writeGltf(dir.path(), "mesh", sphere);
        writeGltf(dir.path(), "baked", baked(sphere, placement));
    }
    writeAll(dir / "world.json", sceneToJson(areaLitWorld()));
    writeAll(dir / "placed.json", sceneWith("mesh." + format, placement.keys()));
    writeAll(dir / "baked.json", sceneWith("baked." + format, ""));
    RenderSettings settings = testSettings(32, 32, 96, 4);
    settings.seed = 1;
    const SampledImage expected = renderSamples(ctx, loadSceneJson(dir / "baked.json"), settings);
    settings.seed = 2;
    const SampledImage actual = renderSamples(ctx, loadSceneJson(dir / "placed.json"), settings);
    expectSameImage(expected, actual, "placed-" + format);
}

TEST_F(GpuTest, ObjAssetPlacedByTheSceneFileRendersAsTheBakedMesh) {
    expectPlacedRendersAsBaked(*ctx, "obj",
                               {{0.35f, 0.5f, 0.25f}, {25, 140, -35}, {0.1f, 0.55f, 1.2f}});
}

TEST_F(GpuTest, MirroredGltfAssetPlacedByTheSceneFileRendersAsTheBakedMesh) {
    expectPlacedRendersAsBaked(*ctx, "gltf",
                               {{-0.3f, 0.45f, 0.35f}, {-30, 70, 50}, {0.1f, 0.55f, 1.2f}});
}

}  // namespace
}  // namespace penumbra::test
