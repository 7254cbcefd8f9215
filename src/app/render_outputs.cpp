#include "app/render_outputs.h"

#include <vector>

#include "image/exr_layers.h"
#include "image/write.h"

namespace penumbra::app {
namespace {

// Background depth: far, as Blender writes it, rather than 0 (which compositors read as near).
constexpr float kMissDepth = 1e10f;

std::vector<ExrChannel> aovChannels(const FrameJob& job, const ImageRgb& beauty, const PixelAccumulator& sums,
                                    FinalFramePasses& passes) {
    std::vector<ExrChannel> channels;
    appendRgbChannels(channels, beauty);
    const std::size_t n = beauty.pixels.size();
    if (job.aovs.needsGuides()) {
        const FrameGuides g = passes.guides();
        auto asImage = [&](const std::vector<Vec3>& values) {
            ImageRgb img(beauty.width, beauty.height);
            img.pixels = values;
            return img;
        };
        if (job.aovs.albedo) appendRgbChannels(channels, asImage(g.albedo), "albedo");
        if (job.aovs.normal) appendRgbChannels(channels, asImage(g.normal), "N", "XYZ");
        if (job.aovs.depth) {
            ExrChannel z{"Z", g.depth};
            for (float& d : z.values)
                if (!(d > 0)) d = kMissDepth;
            channels.push_back(std::move(z));
        }
    }
    if (job.aovs.variance) channels.push_back({"variance.Y", varianceOf(sums)});
    if (job.aovs.samples) channels.push_back({"samples.N", samplesTakenOf(sums)});
    PN_CHECK(channels.back().values.size() == n);
    return channels;
}

}  // namespace

std::filesystem::path aovPathFor(const std::filesystem::path& output) {
    if (formatFromPath(output) == ImageFormat::Exr) return output;
    std::filesystem::path p = output;
    p.replace_extension(".exr");
    return p;
}

void writeFrameOutputs(const std::filesystem::path& output, const FrameJob& job, ProgressiveRender& render,
                       FinalFramePasses& passes, bool final) {
    writeFrameOutputs(output, job, render.current(), passes, final);
}

void writeFrameOutputs(const std::filesystem::path& output, const FrameJob& job, const PixelAccumulator& sums,
                       FinalFramePasses& passes, bool final) {
    const ImageRgb beauty = final && job.denoise ? passes.denoise(sums) : sums.image();
    const bool aovs = final && job.aovs.any();
    const bool exr = formatFromPath(output) == ImageFormat::Exr;
    if (!(aovs && exr)) writeImage(output, beauty, job.toneMap);
    if (aovs) writeExrChannels(aovPathFor(output), beauty.width, beauty.height, aovChannels(job, beauty, sums, passes));
}

}  // namespace penumbra::app
