// A linear-light RGB float image on the CPU: what a render reads back from the GPU, what EXR
// files hold, and what tone mapping and comparison metrics work on.
#pragma once

#include <cstddef>
#include <vector>

#include "core/error.h"
#include "core/vec.h"

namespace penumbra {

struct ImageRgb {
    int width = 0;
    int height = 0;
    std::vector<Vec3> pixels;  // row-major, top row first (as PNG and EXR store them)

    ImageRgb() = default;
    ImageRgb(int w, int h, Vec3 fill = Vec3{})
        : width(w), height(h), pixels(checkedCount(w, h), fill) {}

    Vec3& at(int x, int y) { return pixels[index(x, y)]; }
    const Vec3& at(int x, int y) const { return pixels[index(x, y)]; }

    bool empty() const { return pixels.empty(); }
    bool sameSize(const ImageRgb& o) const { return width == o.width && height == o.height; }

    Vec3 mean() const;          // per-channel mean (accumulated in double); 0 for an empty image
    bool hasNonFinite() const;  // any NaN or infinity: a renderer bug worth reporting

private:
    static std::size_t checkedCount(int w, int h) {
        PN_CHECK(w >= 0 && h >= 0);
        return static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    }
    // Cheap enough to keep on in every build; an out-of-range pixel is always a bug.
    std::size_t index(int x, int y) const {
        PN_CHECK(x >= 0 && x < width && y >= 0 && y < height);
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
               static_cast<std::size_t>(x);
    }
};

}  // namespace penumbra
