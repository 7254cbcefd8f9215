#include "render/view_settings.h"

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

}  // namespace

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
