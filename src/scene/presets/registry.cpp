#include "core/error.h"
#include "scene/presets/presets.h"

namespace penumbra {

std::vector<std::string> presetNames() { return {"cornell", "furnace", "caffeine", "bunny-room", "materials", "bvh-lesson"}; }

bool isPreset(const std::string& name) {
    for (const std::string& n : presetNames())
        if (n == name) return true;
    return false;
}

Scene makePreset(const std::string& name) {
    if (name == "cornell") return makeCornellBox();
    if (name == "furnace") return makeFurnace(0.5f, Vec3{1.0f});
    if (name == "caffeine") return makeCaffeine();
    if (name == "bunny-room") return makeBunnyRoom();
    if (name == "materials") return makeMaterialSpheres();
    if (name == "bvh-lesson") return makeBvhLesson();
    std::string list;
    for (const std::string& n : presetNames()) list += (list.empty() ? "" : ", ") + n;
    throw UsageError("unknown scene '" + name + "'; built-in scenes are: " + list);
}

}  // namespace penumbra
