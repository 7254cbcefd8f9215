#include "render/view_settings.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/error.h"

namespace penumbra {
namespace {

constexpr std::pair<const char*, DebugView> kDebugViews[] = {
    {"none", DebugView::None},          {"normals", DebugView::Normals},
    {"albedo", DebugView::Albedo},      {"depth", DebugView::Depth},
    {"motion", DebugView::Motion},      {"samples", DebugView::Samples},
    {"nodes", DebugView::HeatNodes},    {"triangles", DebugView::HeatTriangles},
    {"boxes", DebugView::BvhBoxes},     {"leaf-depth", DebugView::LeafDepth},
    {"leaf-triangles", DebugView::LeafTriangles},
};

void checkRange(float value, SettingRange range, const char* flag) {
    if (value >= range.min && value <= range.max) return;
    char line[160];
    std::snprintf(line, sizeof line, "%s must be between %g and %g", flag, double(range.min), double(range.max));
    throw UsageError(line);
}

}  // namespace

std::uint32_t scaledSide(std::uint32_t side, float scale) {
    const float s = std::clamp(scale, kResolutionScaleRange.min, kResolutionScaleRange.max);
    return std::max(1u, std::uint32_t(float(side) * s));
}

void checkViewSettingRanges(const ViewSettings& v) {
    checkRange(v.resolutionScale, kResolutionScaleRange, "--resolution-scale");
    checkRange(v.textureSaturation, kTextureSaturationRange, "--texture-saturation");
    checkRange(v.renderDistance, kRenderDistanceRange, "--render-distance");
}

std::span<const std::pair<const char*, DebugView>> debugViewNames() { return kDebugViews; }

std::optional<DebugView> debugViewFromName(std::string_view name) {
    for (const auto& [n, v] : kDebugViews)
        if (name == n) return v;
    return std::nullopt;
}

const char* debugViewName(DebugView view) {
    for (const auto& [n, v] : kDebugViews)
        if (v == view) return n;
    return "none";
}

}  // namespace penumbra
