#include "core/error.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

struct Preset {
    const char* name;
    Scene (*make)();
};

Scene makeDefaultFurnace() { return makeFurnace(0.5f, Vec3{1.0f}); }

// Every built-in scene, once: names, lookups, errors and the command-line help all read this.
constexpr Preset kPresets[] = {
    {"cornell", makeCornellBox}, {"furnace", makeDefaultFurnace},      {"caffeine", makeCaffeine},
    {"bunny-room", makeBunnyRoom}, {"materials", makeMaterialSpheres}, {"bvh-lesson", makeBvhLesson},
    {"dungeon", makeDungeon}, {"suzanne", makeSuzanne},
};

}  // namespace

std::vector<std::string> presetNames() {
    std::vector<std::string> names;
    for (const Preset& p : kPresets) names.push_back(p.name);
    return names;
}

std::string presetList() {
    std::string list;
    for (const Preset& p : kPresets) list += (list.empty() ? "" : ", ") + std::string(p.name);
    return list;
}

bool isPreset(const std::string& name) {
    for (const Preset& p : kPresets)
        if (name == p.name) return true;
    return false;
}

Scene makePreset(const std::string& name) {
    for (const Preset& p : kPresets)
        if (name == p.name) return p.make();
    throw UsageError("unknown scene '" + name + "'; built-in scenes are: " + presetList());
}

}  // namespace penumbra
