#include "scene/io/wad/animation.h"

#include <unordered_map>

namespace penumbra::wad {

const std::vector<AnimationDef>& animationDefs() {
    static const std::vector<AnimationDef> defs = {
        {false, "NUKAGE1", "NUKAGE3"},  {false, "FWATER1", "FWATER4"},
        {false, "SWATER1", "SWATER4"},  {false, "LAVA1", "LAVA4"},
        {false, "BLOOD1", "BLOOD3"},    {false, "RROCK05", "RROCK08"},
        {false, "SLIME01", "SLIME04"},  {false, "SLIME05", "SLIME08"},
        {false, "SLIME09", "SLIME12"},  {true, "BLODGR1", "BLODGR4"},
        {true, "SLADRIP1", "SLADRIP3"}, {true, "BLODRIP1", "BLODRIP4"},
        {true, "FIREWALA", "FIREWALL"}, {true, "GSTFONT1", "GSTFONT3"},
        {true, "FIRELAV3", "FIRELAVA"}, {true, "FIREMAG1", "FIREMAG3"},
        {true, "FIREBLU1", "FIREBLU2"}, {true, "ROCKRED1", "ROCKRED3"},
        {true, "BFALL1", "BFALL4"},     {true, "SFALL1", "SFALL4"},
        {true, "WFALL1", "WFALL4"},     {true, "DBRAIN1", "DBRAIN4"},
    };
    return defs;
}

std::vector<std::vector<std::string>> findCycles(const std::vector<std::string>& orderedNames,
                                                 bool textures) {
    std::unordered_map<std::string, std::size_t> position;
    for (std::size_t i = 0; i < orderedNames.size(); ++i) position.try_emplace(orderedNames[i], i);
    std::vector<std::vector<std::string>> cycles;
    for (const AnimationDef& def : animationDefs()) {
        if (def.texture != textures) continue;
        auto first = position.find(def.first), last = position.find(def.last);
        if (first == position.end() || last == position.end() || last->second <= first->second)
            continue;
        const std::size_t frames = last->second - first->second + 1;
        if (frames > kMaxAnimationFrames) continue;
        cycles.emplace_back(orderedNames.begin() + std::ptrdiff_t(first->second),
                            orderedNames.begin() + std::ptrdiff_t(last->second) + 1);
    }
    return cycles;
}

}  // namespace penumbra::wad
