// Doom's sector light levels as light. The game darkens every surface of a sector through a
// colormap chosen by the sector's level (in 16 steps of 16) and the distance from the eye
// (r_main.c's light tables); here a sector's level sets the radiance of a fill light given off by
// its floor and ceiling (which the camera does not see glow), so that a bright sector is lit
// brightly and a dark one dimly (docs/SCENES.md).
#pragma once

namespace penumbra::wad {

// The brightness at which Doom draws a surface of a sector of light level `level` seen from 128
// units (4 m, across a typical room), as a fraction of its palette colour: 1 - c / 32 for the
// colormap c = clamp(4 (15 - level / 16) - 10, 0, 31) the game's light tables give at that
// distance. 1 from level 240 up, 0.69 at 160, 0.44 at 128, 1/32 (its darkest) from 64 down.
float doomBrightness(int level);

// Radiance (W/(m^2 sr), white) of the fill light of a sector of that level: twice the linear
// light of doomBrightness (the palette is sRGB-like, so it is decoded). The middle of a floor of a
// room twice as wide as it is high sees the ceiling over about half of its cosine-weighted
// hemisphere (view factor 0.55), and the ceiling sees the floor alike, so both are lit to about
// the brightness Doom gives them: a sector at full light shows its textures near their palette
// colours.
float sectorRadiance(int level);

}  // namespace penumbra::wad
