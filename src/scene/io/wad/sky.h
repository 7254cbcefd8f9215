// Doom's sky as an environment: the texture the game draws wherever a ceiling is F_SKY1, wrapped
// around the horizon the way its renderer does, for escaping rays and for the sky ceilings, which
// are portals onto it (Material::skyPortal).
#pragma once

#include <string>

#include "scene/scene.h"

namespace penumbra::wad {

// The sky texture of a map: SKY1 to SKY4 by episode for ExMy; for Doom II's MAPxx, SKY1 up to
// MAP11, SKY2 up to MAP20 and SKY3 after (as the game's G_DoLoadLevel picks it). Other names: SKY1.
std::string skyTextureName(const std::string& mapName);

// Equirectangular map size: Doom turns 1024 sky columns around the full circle.
constexpr int kSkyMapWidth = 1024;
constexpr int kSkyMapHeight = 512;

// The sky as Doom shows it, in the map layout of scene.h's EnvironmentMap: column
// floor(1024 a / 2 pi) mod width of the texture at Doom angle a (so a 256-wide sky repeats 4
// times), and texture row 100 - 160 tan(elevation): row 100 on the horizon and one row per pixel
// of Doom's 320-wide, 90-degree view. Above the texture the top row fades over 32 rows into the
// mean colour of its top 4 rows, below it the bottom row into that of its bottom 4. Radiance is
// the texels' linear colour times `brightness` (Doom draws the sky at full brightness).
EnvironmentMap skyEnvironment(const Texture& sky, float brightness);

}  // namespace penumbra::wad
