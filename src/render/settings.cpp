#include "render/settings.h"

#include "core/error.h"

namespace penumbra {

void validateSettings(const RenderSettings& s) {
    auto bad = [](const std::string& what) { throw UsageError(what); };
    if (s.width == 0 || s.height == 0 || s.width > kMaxImageSide || s.height > kMaxImageSide)
        bad("image size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
            " is out of range; width and height must be between 1 and " + std::to_string(kMaxImageSide));
    if (std::uint64_t(s.width) * s.height > kMaxPixels)
        bad("image of " + std::to_string(std::uint64_t(s.width) * s.height) + " pixels is too large; the limit is " +
            std::to_string(kMaxPixels) + " pixels");
    if (s.samplesPerPixel == 0 || s.samplesPerPixel > kMaxSamplesPerPixel)
        bad("--spp must be between 1 and " + std::to_string(kMaxSamplesPerPixel) + " (got " +
            std::to_string(s.samplesPerPixel) + ")");
    if (s.samplesPerPass == 0 || s.samplesPerPass > s.samplesPerPixel)
        bad("samples per pass must be between 1 and --spp");
    if (s.maxBounces > kMaxBounces)
        bad("--bounces must be at most " + std::to_string(kMaxBounces) + " (got " + std::to_string(s.maxBounces) + ")");
    if (!(s.time >= 0 && s.time <= kMaxTime)) bad("--time must be a number of seconds between 0 and 1e6");
    validateShadowRouletteShare(s.shadowRouletteShare);
}

void validateShadowRouletteShare(float share) {
    if (!(share >= 0 && share <= 1)) throw UsageError("--shadow-roulette must be a share between 0 (off) and 1");
}

MisMode parseMisMode(const std::string& name) {
    if (name == "both") return MisMode::Both;
    if (name == "light") return MisMode::LightOnly;
    if (name == "bsdf") return MisMode::BsdfOnly;
    throw UsageError("unknown --mis '" + name + "'; use both, light or bsdf");
}

BvhBuild parseBvhBuild(const std::string& name) {
    if (name == "cpu") return BvhBuild::Cpu;
    if (name == "gpu") return BvhBuild::Gpu;
    throw UsageError("unknown --bvh-build '" + name + "'; use cpu or gpu");
}

const char* bvhBuildName(BvhBuild where) { return where == BvhBuild::Gpu ? "gpu" : "cpu"; }

}  // namespace penumbra
