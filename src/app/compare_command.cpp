// penumbra compare IMAGE.exr REFERENCE.exr: how close a render is to a reference, in the numbers
// docs/RENDERING.md uses for the denoiser (RMSE, displayed PSNR, mean luminance, detail).
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "app/commands.h"
#include "core/error.h"
#include "image/exr_layers.h"
#include "image/metrics.h"

namespace penumbra::app {
namespace {

struct CompareArgs {
    std::string image, reference;
};

// The beauty (R, G, B) of a single- or multi-layer EXR (render --aov writes the latter).
ImageRgb readBeauty(const std::string& path) {
    const ExrChannels exr = readExrChannels(path);
    ImageRgb img(exr.width, exr.height);
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        const auto it = exr.channels.find(names[c]);
        if (it == exr.channels.end()) throw Error("'" + path + "' has no " + names[c] + " channel");
        for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i][c] = it->second[i];
    }
    return img;
}

void runCompare(const CompareArgs& args) {
    const ImageRgb image = readBeauty(args.image), reference = readBeauty(args.reference);
    const double psnr = displayedPsnr(image, reference);  // checks the sizes
    const double detail = gradientEnergy(reference) > 0 ? gradientEnergy(image) / gradientEnergy(reference) : NAN;
    std::printf("rmse %.6g\npsnr %.2f dB\nmean luminance %.6g (reference %.6g)\ngradient energy ratio %.4f\n",
                rmse(image, reference), psnr, meanLuminance(image), meanLuminance(reference), detail);
}

}  // namespace

void registerCompare(CLI::App& app, Action& action) {
    auto args = std::make_shared<CompareArgs>();
    CLI::App* cmd = app.add_subcommand(
        "compare", "compare an EXR render with an EXR reference: RMSE, PSNR of the displayed images, detail kept");
    cmd->add_option("image", args->image, "the render (.exr)")->required();
    cmd->add_option("reference", args->reference, "the reference (.exr)")->required();
    cmd->callback([args, &action] { action = [args] { runCompare(*args); }; });
}

}  // namespace penumbra::app
