// Parsing scene-file text in tests, and the message a bad one gives.
#pragma once

#include <string>

#include "core/error.h"
#include "scene/io/scene_json.h"

namespace penumbra::test {

inline Scene parseSceneText(const std::string& text, SceneFileSettings* settings = nullptr) {
    return loadSceneJsonFromText(text, ".", "test.json", settings);
}

// The error message of a scene text that fails to load; empty when it loads.
inline std::string sceneTextError(const std::string& text) {
    try {
        parseSceneText(text);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace penumbra::test
