// What a render is asked to do; validated once, at the edge, with messages that say the fix.
#pragma once

#include <cstdint>
#include <string>

namespace penumbra {

// The ray walks (render/walks.h names and describes each). Wide: the compressed 8-wide BVH (flat
// scenes); Objects: a box per object; Stackless: the binary BVH through escape indices. New ones
// go last: checkpoints store the number.
enum class Accel { Bvh, Brute, Wide, Objects, Stackless };

// Where the flat world's BVH is built (--bvh-build): the CPU's binned SAH (through the BVH cache)
// or the GPU's linear BVH (render/gpu_bvh_build.h). Either tree serves every walk.
enum class BvhBuild { Cpu, Gpu };

// Which estimators of direct light the integrator combines (shaders/lib/mis.glsl): both with the
// power heuristic, light sampling only, or BSDF sampling only. All converge to the same image.
enum class MisMode { Both, LightOnly, BsdfOnly };

// The viewer's FrameUniforms::shadowRouletteShare unless asked otherwise: measured on the H200
// against 0.05 and 0.2 (docs/PERFORMANCE.md, session 33).
constexpr float kDefaultShadowRouletteShare = 0.1f;

struct RenderSettings {
    std::uint32_t width = 640;
    std::uint32_t height = 480;
    std::uint32_t samplesPerPixel = 64;
    std::uint32_t samplesPerPass = 1;  // paths per pixel in one dispatch
    std::uint32_t maxBounces = 16;     // path segments after the camera ray
    std::uint32_t rouletteStart = 3;   // Russian roulette from this bounce on
    // Shadow rays whose light is below this share of the pixel's value so far go through Russian
    // roulette (lib/path.glsl keepShadowRay); 0 traces them all. The mean is the same either way,
    // but the samples then depend on the sums of earlier passes, so an image would no longer be
    // the same bit for bit however its passes are split (MPI ranks, tiles, a resumed checkpoint):
    // headless renders keep it off unless asked (render --shadow-roulette); the viewer uses
    // kDefaultShadowRouletteShare.
    float shadowRouletteShare = 0.0f;
    std::uint32_t seed = 1;
    Accel accel = Accel::Bvh;
    BvhBuild bvhBuild = BvhBuild::Cpu;
    MisMode mis = MisMode::Both;
    // Pick every light with the same probability instead of by its estimated contribution: the
    // oracle that tests compare the light sampler with (same mean, more noise).
    bool uniformLightPick = false;
    float time = 0.0f;  // seconds: the moment animated textures show (render --time)
    // A pixel's samples in one pass share their camera ray (TracePass::setSharesCameraRays): the
    // viewer's setting, here so that tests can render with it.
    bool shareCameraRays = false;
    // The WebGPU renderer's view settings (shared/view_limits.h): base-colour textures'
    // saturation (1: as they are), and the render distance across the floor in metres beyond
    // which nothing is hit (0: no limit). The viewer's come from ViewSettings.
    float textureSaturation = 1.0f;
    float renderDistance = 0.0f;
    // Camera rays jittered over their pixel (anti-aliasing); false: through its centre (render
    // --no-jitter, the viewer's toggle), which shows aliased edges as the seed ray tracers do.
    bool pixelJitter = true;
    // Closest-hit walks skip triangles seen from behind (PN_OPTION_CULL_BACKFACES; --cull-backfaces):
    // not shadow rays, not transmissive materials (docs/RENDERING.md, "Back-face culling").
    bool cullBackfaces = false;
    // Paths per trace dispatch (render/passes/trace_tiles.h); 0: the device's default.
    std::uint64_t pathsPerDispatch = 0;
};

// Limits that keep absurd requests from allocating unbounded memory or running forever.
constexpr std::uint32_t kMaxImageSide = 16384;
constexpr std::uint64_t kMaxPixels = 16384ull * 16384ull / 4;  // 64 Mpixel: 1 GiB accumulation
constexpr std::uint32_t kMaxSamplesPerPixel = 1u << 20;
constexpr std::uint32_t kMaxBounces = 1024;
constexpr float kMaxTime = 1e6f;  // seconds; beyond it float time loses the animation frames

// RenderSettings::time at a moment of the scene (render --time, a sequence's frame): animated
// textures stand still before 0 and after kMaxTime, where a camera path may go on.
inline float textureTime(double sceneSeconds) {
    return float(sceneSeconds > 0 ? (sceneSeconds < double(kMaxTime) ? sceneSeconds : double(kMaxTime)) : 0.0);
}

// Throws UsageError naming the bad value and the allowed range.
void validateSettings(const RenderSettings& settings);
// The part of it the viewer's settings share (bench --viewer checks it alone).
void validateShadowRouletteShare(float share);

Accel parseAccel(const std::string& name);  // a name in render/walks.h; UsageError otherwise
const char* accelName(Accel accel);
BvhBuild parseBvhBuild(const std::string& name);  // "cpu" or "gpu"; UsageError otherwise
const char* bvhBuildName(BvhBuild where);

MisMode parseMisMode(const std::string& name);  // "both" | "light" | "bsdf"; UsageError otherwise

}  // namespace penumbra
