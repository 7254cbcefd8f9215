#include "serve/remote_settings.h"

#include <algorithm>
#include <cmath>

namespace penumbra::serve {
namespace {

bool readNumber(const nlohmann::json& value, double lo, double hi, double& out, std::string& error) {
    if (!value.is_number() || !std::isfinite(value.get<double>())) {
        error = "must be a number";
        return false;
    }
    out = std::clamp(value.get<double>(), lo, hi);
    return true;
}

bool readBool(const nlohmann::json& value, bool& out, std::string& error) {
    if (!value.is_boolean()) {
        error = "must be true or false";
        return false;
    }
    out = value.get<bool>();
    return true;
}

bool readDebugView(const nlohmann::json& value, DebugView& out, std::string& error) {
    if (value.is_string())
        if (std::optional<DebugView> view = debugViewFromName(value.get_ref<const std::string&>())) {
            out = *view;
            return true;
        }
    error = "must be one of the debug views' names";
    return false;
}

}  // namespace

bool applySetting(RemoteState& state, const std::string& name, const nlohmann::json& value, std::string& error) {
    ViewSettings& v = state.view;
    double x = 0;
    bool ok = false;
    if (name == "spp") {
        if ((ok = readNumber(value, 1, 64, x, error))) v.samplesPerFrame = std::uint32_t(std::lround(x));
    } else if (name == "bounces") {
        if ((ok = readNumber(value, 1, 32, x, error))) v.maxBounces = std::uint32_t(std::lround(x));
    } else if (name == "scale") {
        if ((ok = readNumber(value, kResolutionScaleRange.min, kResolutionScaleRange.max, x, error)))
            v.resolutionScale = float(x);
    } else if (name == "saturation") {
        if ((ok = readNumber(value, kTextureSaturationRange.min, kTextureSaturationRange.max, x, error)))
            v.textureSaturation = float(x);
    } else if (name == "renderDistance") {
        if ((ok = readNumber(value, kRenderDistanceRange.min, kRenderDistanceRange.max, x, error)))
            v.renderDistance = float(x);
    } else if (name == "temporal") {
        ok = readBool(value, v.temporal, error);
    } else if (name == "denoise") {
        if ((ok = readNumber(value, 0, 8, x, error))) {
            v.denoise = std::lround(x) > 0;
            if (v.denoise) v.denoiseIterations = std::uint32_t(std::lround(x));
        }
    } else if (name == "debug") {
        ok = readDebugView(value, v.debug, error);
    } else if (name == "debugOpacity") {
        if ((ok = readNumber(value, 0, 1, x, error))) v.debugOpacity = float(x);
    } else if (name == "torch") {
        ok = readBool(value, v.torch, error);
    } else if (name == "exposure") {
        if ((ok = readNumber(value, -10, 10, x, error))) v.exposure = float(x);
    } else if (name == "playing") {
        ok = readBool(value, state.playing, error);
    } else if (name == "phantom") {
        ok = readBool(value, state.phantom, error);
    } else {
        error = "is not a setting";
    }
    if (!ok) {
        std::string line = "'";
        line.append(name, 0, 32);
        line += "' ";
        error = line + error;
    }
    return ok;
}

nlohmann::json settingsJson(const RemoteState& state) {
    const ViewSettings& v = state.view;
    return {{"spp", v.samplesPerFrame},
            {"bounces", v.maxBounces},
            {"scale", v.resolutionScale},
            {"saturation", v.textureSaturation},
            {"renderDistance", v.renderDistance},
            {"temporal", v.temporal},
            {"denoise", v.denoise ? v.denoiseIterations : 0u},
            {"debug", debugViewName(v.debug)},
            {"debugOpacity", v.debugOpacity},
            {"torch", v.torch},
            {"exposure", v.exposure},
            {"playing", state.playing},
            {"phantom", state.phantom}};
}

nlohmann::json settingRangesJson() {
    auto range = [](SettingRange r) { return nlohmann::json::array({r.min, r.max}); };
    return {{"scale", range(kResolutionScaleRange)},
            {"saturation", range(kTextureSaturationRange)},
            {"renderDistance", range(kRenderDistanceRange)}};
}

nlohmann::json debugViewsJson() {
    nlohmann::json names = nlohmann::json::array();
    for (const auto& [name, view] : debugViewNames()) names.push_back(name);
    return names;
}

}  // namespace penumbra::serve
