// The settings panel over the network: a browser's `set` message applied to the view's
// settings, and the settings as JSON for hello and stats (docs/SERVE.md, the settings table).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "render/view_settings.h"

namespace penumbra::serve {

// What a browser may change: the view's settings, whether time runs, and whether the dungeon's
// phantom is shown (scene/phantom.h; ignored by scenes without one).
struct RemoteState {
    ViewSettings view;
    bool playing = true;
    bool phantom = true;
};

// Applies one setting (clamped to its range). False, with `error` saying why, for an unknown
// name or a value of the wrong type; the state is then unchanged.
bool applySetting(RemoteState& state, const std::string& name, const nlohmann::json& value, std::string& error);

nlohmann::json settingsJson(const RemoteState& state);

// The ranges of the number settings, {"scale": [min, max], ...}, from render/view_settings.h:
// the page sets its controls' limits from them, so it follows the viewer's.
nlohmann::json settingRangesJson();

// The debug views' names, in the order the page offers them ("none" first).
nlohmann::json debugViewsJson();

}  // namespace penumbra::serve
