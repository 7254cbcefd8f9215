#include "app/viewer/screenshot.h"

#include "gpu/buffer.h"
#include "image/write.h"

namespace penumbra::viewer {

void writeScreenshot(const gpu::Context& ctx, InteractiveRenderer& renderer, const std::string& path) {
    const std::size_t pixels = std::size_t(renderer.width()) * renderer.height();
    std::vector<std::uint32_t> rgba = gpu::downloadBuffer<std::uint32_t>(ctx, renderer.commands(), renderer.display(), pixels);
    std::vector<std::uint8_t> rgb(pixels * 3);
    for (std::size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c) rgb[3 * i + c] = std::uint8_t(rgba[i] >> (8 * c));
    writePngRgb8(path, int(renderer.width()), int(renderer.height()), rgb);
}

}  // namespace penumbra::viewer
