// A procedural daylight sky without any file: the Preetham et al. (1999) analytic sky luminance
// and chromaticity model rendered into an equirectangular map, a ground below the horizon lit by
// that sky and the sun, and the sun itself as a directional light with an angular radius.
#pragma once

#include "scene/scene.h"

namespace penumbra {

struct SkyParams {
    float sunElevationDegrees = 45.0f;  // [0, 90] above the horizon
    float sunAzimuthDegrees = 135.0f;   // from -z toward +x (the map's u = 0.5 + azimuth / 360)
    float turbidity = 3.0f;             // [1.7, 10]: 2 clear, 3 typical, 6+ hazy
    float sunRadiusDegrees = 0.27f;     // angular radius; the real sun's is 0.27
    float groundAlbedo = 0.2f;          // [0, 1]
    int width = 512;                    // map size; the sky is smooth, the sun is not in the map
    int height = 256;
};

struct Sky {
    EnvironmentMap map;
    Light sun;  // directional, with angularRadius
};

// Units: physical luminance (cd/m^2) and illuminance (lux) times pi * 1e-5, so that a white
// diffuse surface facing a 100 klux sun has radiance 1 (renders need no exposure change). The
// sun's illuminance follows the extraterrestrial 128 klux through Rayleigh and haze extinction
// (optical depth from the turbidity) along the Kasten-Young air mass. Throws UsageError on
// parameters outside the ranges above.
Sky makeSky(const SkyParams& params);

// Direction toward the sun for an elevation and azimuth in degrees (map-local, before rotation).
Vec3 sunDirection(float elevationDegrees, float azimuthDegrees);

}  // namespace penumbra
