// Statistics over a renderer's accumulation buffer, for tests with tolerances derived from the
// sample count.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/vec.h"
#include "render/progressive.h"
#include "render/settings.h"
#include "scene/presets/mesh_builder.h"
#include "scene/scene.h"

namespace penumbra::test {

struct PixelStats {
    double mean;    // mean luminance of the pixel
    double stderr;  // standard error of that mean, from the sample variance
};

// A diffuse floor of albedo `albedo` at y = 0 (100 m square, facing up), seen from `eye` looking
// at the origin. A narrow field of view makes every pixel see (almost exactly) the origin.
inline Scene diffuseFloorScene(float albedo, Vec3 eye, Vec3 up, float fovDegrees) {
    Scene s;
    s.name = "floor";
    std::uint32_t m = addMaterial(s, "floor", Vec3{albedo});
    Mesh floor;
    floor.name = "floor";
    floor.material = m;
    addQuad(floor, {-50, 0, -50}, {-50, 0, 50}, {50, 0, 50}, {50, 0, -50});
    s.meshes.push_back(floor);
    s.camera.position = eye;
    s.camera.lookAt = {0, 0, 0};
    s.camera.up = up;
    s.camera.fovYDegrees = fovDegrees;
    return s;
}

// A quad from (-1,-1) to (1,1) at z = 0, its material's albedo the texture `tex` (texture 0, uv
// (0,0) top left), under a uniform white sky, seen from z = 2 with a 90-degree view: the quad fills
// the middle half of the image. A diffuse surface under a unit sky shows exactly its albedo.
inline Scene texturedQuadScene(const std::string& name, Texture tex) {
    Scene scene;
    scene.name = name;
    scene.background = Vec3{1.0f};
    scene.textures.push_back(std::move(tex));
    const std::uint32_t mat = addMaterial(scene, name, Vec3{1.0f});
    scene.materials[mat].albedoTexture.texture = 0;
    Mesh quad;
    quad.name = "quad";
    quad.material = mat;
    addQuad(quad, {-1, 1, 0}, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0});
    quad.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    scene.meshes.push_back(quad);
    scene.camera.position = {0, 0, 2};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.fovYDegrees = 90;
    return scene;
}

// A small test render: width x height, `spp` samples per pixel in passes of up to 16.
inline RenderSettings testSettings(std::uint32_t width, std::uint32_t height, std::uint32_t spp,
                                   std::uint32_t bounces) {
    RenderSettings s;
    s.width = width;
    s.height = height;
    s.samplesPerPixel = spp;
    s.samplesPerPass = std::min<std::uint32_t>(spp, 16);
    s.maxBounces = bounces;
    return s;
}

// The linear value of an 8-bit sRGB-encoded channel (IEC 61966-2-1).
inline float srgbToLinear8(float c8) {
    float c = c8 / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

inline PixelStats pixelStats(const Vec4& sums, double samples) {
    double mean = luminance(Vec3{sums.x, sums.y, sums.z}) / samples;
    double variance = std::max(0.0, sums.w / samples - mean * mean) * samples / std::max(1.0, samples - 1);
    return {mean, std::sqrt(variance / samples)};
}

// A progressive render's budget of exactly `spp` samples per pixel (no time limit).
inline RenderBudget samplesBudget(std::uint32_t spp) {
    RenderBudget b;
    b.samplesPerPixel = spp;
    return b;
}

struct MeanEstimate {
    double mean;
    double stderr;
};

// The mean luminance of an image from its accumulation (sums of samples and of squared
// luminance), with its standard error from the per-pixel sample variances.
inline MeanEstimate imageMean(const std::vector<Vec4>& sums, double samples) {
    double total = 0, variance = 0;
    for (const Vec4& s : sums) {
        PixelStats p = pixelStats(s, samples);
        total += p.mean;
        variance += p.stderr * p.stderr;
    }
    double n = double(sums.size());
    return {total / n, std::sqrt(variance) / n};
}

// The normal quantile that keeps the family-wise false-alarm rate at `alpha` over `tests`
// independent tests (Sidak), by bisection on the complementary error function.
inline double sidakZ(double alpha, std::size_t tests) {
    double perTest = 1.0 - std::pow(1.0 - alpha, 1.0 / double(tests));
    double lo = 0, hi = 40;
    for (int i = 0; i < 200; ++i) {
        double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > perTest ? lo : hi) = mid;
    }
    return hi;
}

}  // namespace penumbra::test
