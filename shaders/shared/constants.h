// Mathematical constants the host and the shaders both use, written once. Valid GLSL and C++.
#ifndef PENUMBRA_SHADER_CONSTANTS_H
#define PENUMBRA_SHADER_CONSTANTS_H

#define PN_PI_DIGITS 3.14159265358979323846

#ifdef __cplusplus
namespace penumbra {
inline constexpr double kPi = PN_PI_DIGITS;
inline constexpr float kPiF = float(kPi);
inline constexpr double degreesToRadians(double degrees) { return degrees * (kPi / 180.0); }
inline constexpr float degreesToRadians(float degrees) { return degrees * float(kPi / 180.0); }
inline constexpr double radiansToDegrees(double radians) { return radians * (180.0 / kPi); }
inline constexpr float radiansToDegrees(float radians) { return radians * float(180.0 / kPi); }
}  // namespace penumbra
#else
const float PN_PI = PN_PI_DIGITS;
const float PN_INV_PI = 1.0 / PN_PI_DIGITS;
#endif

#endif
