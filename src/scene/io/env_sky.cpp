#include "scene/io/env_sky.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "scene/environment.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

constexpr double kUnitsPerLux = kPi * 1e-5;        // see makeSky
constexpr double kExtraterrestrialLux = 128000.0;  // solar illuminance above the atmosphere

// Perez et al.'s sky distribution F(theta, gamma) with one coefficient set.
struct Perez {
    double a, b, c, d, e;
    double operator()(double cosTheta, double gamma) const {
        const double cosGamma = std::cos(gamma);
        return (1 + a * std::exp(b / std::max(cosTheta, 1e-3))) * (1 + c * std::exp(d * gamma) + e * cosGamma * cosGamma);
    }
};

// Preetham et al. 1999, appendix: coefficients linear in the turbidity T for luminance Y and
// chromaticities x, y, and the zenith values as functions of T and the sun's zenith angle.
struct PreethamSky {
    Perez fY, fx, fy;
    double zenithY, zenithx, zenithy;  // zenith luminance in cd/m^2 and chromaticity
    double sunZenith;

    PreethamSky(double t, double thetaS) : sunZenith(thetaS) {
        fY = {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771, -0.0670 * t + 0.3703};
        fx = {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989, -0.0033 * t + 0.0452};
        fy = {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537, -0.0109 * t + 0.0529};
        const double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2 * thetaS);
        zenithY = 1000.0 * ((4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192);
        const double s1 = thetaS, s2 = s1 * s1, s3 = s2 * s1, t2 = t * t;
        zenithx = t2 * (0.00166 * s3 - 0.00375 * s2 + 0.00209 * s1) +
                  t * (-0.02903 * s3 + 0.06377 * s2 - 0.03202 * s1 + 0.00394) +
                  (0.11693 * s3 - 0.21196 * s2 + 0.06052 * s1 + 0.25886);
        zenithy = t2 * (0.00275 * s3 - 0.00610 * s2 + 0.00317 * s1) +
                  t * (-0.04214 * s3 + 0.08970 * s2 - 0.04153 * s1 + 0.00516) +
                  (0.15346 * s3 - 0.26756 * s2 + 0.06670 * s1 + 0.26688);
    }

    // Linear sRGB radiance in cd/m^2-scaled units for a direction with the given cosine to the
    // zenith and angle gamma to the sun.
    Vec3 radiance(double cosTheta, double gamma) const {
        const double Y = zenithY * fY(cosTheta, gamma) / fY(1.0, sunZenith);
        const double x = zenithx * fx(cosTheta, gamma) / fx(1.0, sunZenith);
        const double y = zenithy * fy(cosTheta, gamma) / fy(1.0, sunZenith);
        if (!(Y > 0) || !(y > 0)) return Vec3{0};
        const double X = x / y * Y, Z = (1 - x - y) / y * Y;
        // CIE XYZ to linear sRGB (D65).
        const double r = 3.2406 * X - 1.5372 * Y - 0.4986 * Z;
        const double g = -0.9689 * X + 1.8758 * Y + 0.0415 * Z;
        const double b = 0.0557 * X - 0.2040 * Y + 1.0570 * Z;
        return Vec3{float(std::max(r, 0.0) * kUnitsPerLux), float(std::max(g, 0.0) * kUnitsPerLux),
                    float(std::max(b, 0.0) * kUnitsPerLux)};
    }
};

// Rayleigh optical depth of the whole atmosphere at wavelength `micrometres` (Bucholtz-style fit).
double rayleighDepth(double micrometres) {
    const double l2 = micrometres * micrometres, l4 = l2 * l2;
    return 0.008569 / l4 * (1 + 0.0113 / l2 + 0.00013 / l4);
}

// Sun illuminance (lux) reaching the ground per sRGB channel. Turbidity is by definition the
// ratio of total to molecular optical depth, so haze adds (T - 1) Rayleigh depths at 550 nm,
// falling off with wavelength by an Angstrom exponent of 1.3.
Vec3 sunIlluminance(double elevation, double turbidity) {
    const double zenithDeg = 90.0 - elevation * 180 / kPi;
    const double airMass = 1.0 / (std::cos(kPi / 2 - elevation) + 0.50572 * std::pow(96.07995 - zenithDeg, -1.6364));
    const double wavelengths[3] = {0.65, 0.55, 0.45};
    Vec3 e;
    for (int c = 0; c < 3; ++c) {
        const double haze = (turbidity - 1) * rayleighDepth(0.55) * std::pow(wavelengths[c] / 0.55, -1.3);
        e[c] = float(kExtraterrestrialLux * std::exp(-airMass * (rayleighDepth(wavelengths[c]) + haze)));
    }
    return e;
}

void checkRange(float v, float lo, float hi, const char* what) {
    if (!(v >= lo && v <= hi))
        throw UsageError(std::string("sky ") + what + " must be between " + std::to_string(lo) + " and " + std::to_string(hi));
}

}  // namespace

Vec3 sunDirection(float elevationDegrees, float azimuthDegrees) {
    const double e = elevationDegrees * kPi / 180, a = azimuthDegrees * kPi / 180;
    return Vec3{float(std::cos(e) * std::sin(a)), float(std::sin(e)), float(-std::cos(e) * std::cos(a))};
}

Sky makeSky(const SkyParams& p) {
    checkRange(p.sunElevationDegrees, 0.0f, 90.0f, "sun elevation (degrees)");
    checkRange(p.sunAzimuthDegrees, -360.0f, 360.0f, "sun azimuth (degrees)");
    checkRange(p.turbidity, 1.7f, 10.0f, "turbidity");
    checkRange(p.sunRadiusDegrees, 0.0f, kMaxAngularRadius * 180 / float(kPi), "sun radius (degrees)");
    checkRange(p.groundAlbedo, 0.0f, 1.0f, "ground albedo");
    if (p.width < 4 || p.height < 2 || p.width > 8192 || p.height > 4096) throw UsageError("sky map size out of range");

    const double elevation = p.sunElevationDegrees * kPi / 180;
    const Vec3 toSun = sunDirection(p.sunElevationDegrees, p.sunAzimuthDegrees);
    const PreethamSky model(p.turbidity, kPi / 2 - elevation);

    Sky sky;
    EnvironmentMap& m = sky.map;
    m.name = "sky";
    m.width = p.width;
    m.height = p.height;
    m.radiance.assign(std::size_t(p.width) * std::size_t(p.height), Vec3{0});
    // Upper hemisphere from the model; the sky's irradiance on the ground is summed on the way.
    Vec3 skyIrradiance{0};
    for (int y = 0; y < p.height; ++y) {
        const double theta0 = kPi * y / p.height, theta1 = kPi * (y + 1) / p.height;
        const double thetaMid = 0.5 * (theta0 + theta1);
        if (thetaMid >= kPi / 2) break;
        // Integral of cos(theta) over one texel's solid angle.
        const double projected = (2 * kPi / p.width) * 0.5 * (std::sin(theta1) * std::sin(theta1) - std::sin(theta0) * std::sin(theta0));
        for (int x = 0; x < p.width; ++x) {
            const Vec3 d = environmentDirection((x + 0.5) / p.width, (y + 0.5) / p.height);
            const double gamma = std::acos(std::clamp(double(dot(d, toSun)), -1.0, 1.0));
            const Vec3 L = model.radiance(d.y, gamma);
            m.radiance[std::size_t(y) * std::size_t(p.width) + std::size_t(x)] = L;
            skyIrradiance = skyIrradiance + L * float(projected);
        }
    }
    // The ground: a diffuse plane of the given albedo lit by the sun and the sky above it.
    const Vec3 sunLux = sunIlluminance(elevation, p.turbidity);
    const Vec3 sunOnGround = sunLux * float(kUnitsPerLux * std::sin(elevation));
    const Vec3 ground = (sunOnGround + skyIrradiance) * float(p.groundAlbedo / kPi);
    for (int y = 0; y < p.height; ++y) {
        if (kPi * (y + 0.5) / p.height < kPi / 2) continue;
        for (int x = 0; x < p.width; ++x) m.radiance[std::size_t(y) * std::size_t(p.width) + std::size_t(x)] = ground;
    }

    Light& sun = sky.sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    sun.direction = -toSun;
    const float lum = luminance(sunLux);
    sun.color = lum > 0 ? sunLux / lum : Vec3{1};
    sun.intensity = float(lum * kUnitsPerLux);
    sun.angularRadius = float(p.sunRadiusDegrees * kPi / 180);
    return sky;
}

}  // namespace penumbra
