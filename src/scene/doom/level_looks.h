// What a playing level shows of its own state besides moving sectors and lights: switches that
// turn (SW1 <-> SW2 on the switch's wall) and keys that vanish when picked up. The WAD loader
// gives each switch wall and each key sprite a material of its own (Level::switchMaterials,
// keyMaterials); applyLooks sets those materials to the level's state, and the front ends send the
// changed ones to the GPU in place (InteractiveRenderer::setMaterial), no scene reload. Plain
// data: no GPU.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/doom/level.h"
#include "scene/scene.h"

namespace penumbra::doom {

// An alpha cutoff above any texel's alpha: every texel is a hole, so a sprite with it is drawn
// nowhere and casts no shadow (lib/sprite.glsl), while its BVH slot stays where it was.
constexpr float kHiddenAlphaCutoff = 2.0f;

// The other texture of a switch: Doom's switch list (p_switch.c's alphSwitchList) pairs SW1xxx
// with SW2xxx, in Doom and Doom II alike. Empty for a name that is no switch texture.
std::string otherSwitchTexture(const std::string& name);

// Whether a line with this special turns its switch texture when it fires (S lines, as
// Level::trigger turns them).
bool turnsSwitch(int special);

// Sets the switch and key materials to what the level shows now; returns the materials it
// changed (none when nothing changed since the last call).
std::vector<std::uint32_t> applyLooks(const Level& level, std::vector<Material>& materials);

}  // namespace penumbra::doom
