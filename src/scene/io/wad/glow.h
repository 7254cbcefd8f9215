// Which Doom wall textures and flats give off light, and which of their texels do. The art shows
// lamps, lit signs and switch lights, computer screens and glowing liquids that the game can only
// suggest with sector light levels; here they become area lights whose emission comes from the
// texture itself, so only its lit parts glow. docs/SCENES.md gives the list and the reasons.
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace penumbra::wad {

enum class GlowKind {
    None,
    Whole,   // every texel emits its own colour: liquids and fire
    Bright,  // only texels near full brightness: lamps, tubes, lit signs and switch lights
    Panel,   // everything brighter than the dark frame: coloured light panels (Freedoom's AQLITE*)
    Screen,  // saturated and white texels (what a screen shows), not grey or brown machinery
};

struct Glow {
    GlowKind kind = GlowKind::None;
    float strength = 0.0f;  // radiance of a texel of linear colour 1 and weight 1 (W/(m^2 sr))
};

// The glow of a wall texture (flat = false) or flat by its upper-case WAD name.
Glow glowOf(const std::string& name, bool flat);

// How much of its own colour texel (r, g, b) (8-bit palette colour, as the WAD stores it)
// emits in a texture of that kind: in [0, 1].
float glowWeight(GlowKind kind, std::uint8_t r, std::uint8_t g, std::uint8_t b);

// The emission texture of a glowing texture: every texel's linear colour times its weight,
// stored sRGB-encoded like the original (alpha and animation kept); named "<name> glow".
Texture glowTexture(const Texture& texture, GlowKind kind);

}  // namespace penumbra::wad
