// Opening a scene from inside the viewer: the same loader as the command line, but failures come
// back as one line of text for the panel instead of an exception.
#pragma once

#include <optional>
#include <string>

#include "scene/scene.h"

namespace penumbra::app {

struct OpenedScene {
    std::optional<Scene> scene;  // set on success
    std::string error;           // one line, no "penumbra: error:" prefix; empty on success
};

// A scene file or built-in scene name, as `penumbra render` takes it (WAD files: the first map).
OpenedScene openSceneFile(const std::string& nameOrPath);

}  // namespace penumbra::app
