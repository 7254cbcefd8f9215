#include "app/scene_opener.h"

#include <algorithm>
#include <exception>

#include "app/common_options.h"

namespace penumbra::app {

OpenedScene openSceneFile(const std::string& nameOrPath) {
    OpenedScene out;
    const auto first = nameOrPath.find_first_not_of(" \t");
    const auto last = nameOrPath.find_last_not_of(" \t");
    if (first == std::string::npos) {
        out.error = "no scene file given";
        return out;
    }
    const std::string path = nameOrPath.substr(first, last - first + 1);
    try {
        out.scene = loadScene(path, "", CameraOverrides{});
    } catch (const std::exception& e) {  // loaders report bad input as Error; anything else is one line too
        out.error = e.what();
        std::replace(out.error.begin(), out.error.end(), '\n', ' ');
        if (out.error.empty()) out.error = "could not open '" + path + "'";
    }
    return out;
}

}  // namespace penumbra::app
