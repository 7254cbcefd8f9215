// Doom's sector light levels as light. The game darkens every surface of a sector through a
// colormap chosen by the sector's level (in 16 steps of 16) and the distance from the eye
// (r_main.c's light tables); here a sector's level sets the radiance of a fill light on its
// ceiling, so that a bright sector is lit brightly and a dark one dimly (docs/SCENES.md).
#pragma once

namespace penumbra::wad {

// The brightness at which Doom draws a surface of a sector of light level `level` seen from 128
// units (4 m, across a typical room), as a fraction of its palette colour: 1 - c / 32 for the
// colormap c = clamp(4 (15 - level / 16) - 10, 0, 31) the game's light tables give at that
// distance. 1 from level 240 up, 0.69 at 160, 0.44 at 128, 1/32 (its darkest) from 64 down.
float doomBrightness(int level);

// Radiance (W/(m^2 sr), white) of the fill light on the ceiling of a sector of that level: the
// linear light of doomBrightness (the palette is sRGB-like, so it is decoded). A large room under
// a ceiling of radiance R has its floor lit to R times its albedo, so a sector at full light
// shows its textures at their palette colours, as Doom does.
float sectorRadiance(int level);

}  // namespace penumbra::wad
