// Normal maps against analytic answers: a diffuse floor with a constant tangent-space normal,
// lit by a directional light, shows albedo / pi * E * cos(mapped normal, light). Tilting the map
// toward +x (its +u tangent) and toward image-up (-v) checks the tangent frame built from UV
// derivatives, handedness included.
#include <cmath>

#include "gpu_fixture.h"
#include "render/renderer.h"
#include "scene/presets/mesh_builder.h"
#include "shared/constants.h"

namespace penumbra::test {
namespace {

constexpr float kAlbedo = 0.5f, kIrradiance = 2.0f;

// The tangent-space normal as the 8-bit texel stores it, decoded the way the shader decodes it.
struct MapTexel {
    std::uint8_t rgb[3];
    Vec3 decoded;
};

MapTexel encode(Vec3 n) {
    MapTexel t{};
    for (int k = 0; k < 3; ++k) {
        t.rgb[k] = static_cast<std::uint8_t>(std::lround((n[k] * 0.5f + 0.5f) * 255.0f));
        t.decoded[k] = t.rgb[k] / 255.0f * 2.0f - 1.0f;
    }
    t.decoded = normalize(t.decoded);
    return t;
}

// Floor at y = 0 facing up, u along +x and v along +z, seen straight down.
Scene mappedFloor(const MapTexel& texel, Vec3 toLight) {
    Scene s;
    s.name = "mapped-floor";
    Texture tex;
    tex.name = "normal";
    tex.width = tex.height = 1;
    tex.rgba = {texel.rgb[0], texel.rgb[1], texel.rgb[2], 255};
    tex.srgb = false;
    s.textures.push_back(tex);
    std::uint32_t m = addMaterial(s, "floor", Vec3{kAlbedo});
    s.materials[m].normalTexture.texture = 0;
    Mesh floor;
    floor.name = "floor";
    floor.material = m;
    addQuad(floor, {-50, 0, -50}, {-50, 0, 50}, {50, 0, 50}, {50, 0, -50});
    for (Vec3 p : floor.positions) floor.uvs.push_back({(p.x + 50) / 100, (p.z + 50) / 100});
    s.meshes.push_back(floor);
    Light l;
    l.type = LightType::Directional;
    l.direction = -normalize(toLight);
    l.intensity = kIrradiance;
    s.lights.push_back(l);
    s.camera.position = {0, 3, 0};
    s.camera.lookAt = {0, 0, 0};
    s.camera.up = {0, 0, -1};
    s.camera.fovYDegrees = 1.0f;
    return s;
}

float renderCentre(const gpu::Context& ctx, const Scene& scene) {
    RenderSettings settings;
    settings.width = 4;
    settings.height = 4;
    settings.samplesPerPixel = 8;
    settings.samplesPerPass = 8;
    settings.maxBounces = 1;
    Renderer r(ctx, scene, settings);
    r.render();
    EXPECT_EQ(r.stats().invalidSamples, 0u);
    return luminance(r.image().mean());
}

TEST_F(GpuTest, NormalMapTiltsShadingAlongTheUvTangentFrame) {
    const float s30 = 0.5f, c30 = 0.8660254f;
    struct Case {
        const char* what;
        Vec3 tangentSpace;  // the map's normal: x along +u, y image-up (-v), z out of the surface
        Vec3 toLight;
    };
    const Case cases[] = {
        {"flat map", {0, 0, 1}, {1, 1, 0}},
        {"tilted toward +u", {s30, 0, c30}, {1, 1, 0}},   // 15 degrees from the light
        {"tilted toward -u", {-s30, 0, c30}, {1, 1, 0}},  // 75 degrees from the light
        {"tilted toward image up", {0, s30, c30}, {0, 1, -1}},
    };
    for (const Case& c : cases) {
        MapTexel texel = encode(c.tangentSpace);
        // On this floor tangent = +x (u), image up = -z (-v), normal = +y: the world normal the
        // quantised texel encodes.
        Vec3 n{texel.decoded.x, texel.decoded.z, -texel.decoded.y};
        const float expected = kAlbedo / kPiF * kIrradiance * std::max(0.0f, dot(normalize(n), normalize(c.toLight)));
        EXPECT_NEAR(renderCentre(*ctx, mappedFloor(texel, c.toLight)), expected, 2e-3f * std::max(expected, 1.0f)) << c.what;
    }
}

}  // namespace
}  // namespace penumbra::test
