#include "scene/doom/level_looks.h"

#include <optional>

#include "scene/doom/line_specials.h"

namespace penumbra::doom {
namespace {

bool setTexture(TextureRef& ref, int texture) {
    if (!ref.present() || texture < 0 || ref.texture == texture) return false;
    ref.texture = texture;
    return true;
}

}  // namespace

std::string otherSwitchTexture(const std::string& name) {
    if (name.size() < 4 || name.compare(0, 2, "SW") != 0 || (name[2] != '1' && name[2] != '2')) return {};
    std::string other = name;
    other[2] = name[2] == '1' ? '2' : '1';
    return other;
}

bool turnsSwitch(int special) {
    const std::optional<LineSpecial> s = lineSpecial(special);
    return s && s->trigger == Trigger::Switch;
}

std::vector<std::uint32_t> applyLooks(const Level& level, std::vector<Material>& materials) {
    std::vector<std::uint32_t> changed;
    for (const SwitchMaterial& s : level.switchMaterials()) {
        if (s.material >= materials.size() || s.line >= level.lines().size()) continue;
        const int side = level.switchFlipped(s.line) ? 1 : 0;
        Material& m = materials[s.material];
        const bool albedo = setTexture(m.albedoTexture, s.albedo[side]);
        const bool glow = setTexture(m.emissionTexture, s.emission[side]);
        if (albedo || glow) changed.push_back(s.material);
    }
    for (const KeyMaterial& k : level.keyMaterials()) {
        if (k.material >= materials.size()) continue;
        const float cutoff = level.thingTaken(k.thing) ? kHiddenAlphaCutoff : k.shownCutoff;
        Material& m = materials[k.material];
        if (m.alphaCutoff == cutoff) continue;
        m.alphaCutoff = cutoff;
        changed.push_back(k.material);
    }
    return changed;
}

}  // namespace penumbra::doom
