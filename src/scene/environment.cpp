#include "scene/environment.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "shared/constants.h"

namespace penumbra {
namespace {
}

Vec3 environmentDirection(double u, double v) {
    const double phi = 2 * kPi * (u - 0.5), theta = kPi * v;
    return Vec3{float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)), float(-std::sin(theta) * std::cos(phi))};
}

Vec2 environmentUv(Vec3 d) {
    const double theta = std::acos(std::clamp(double(d.y), -1.0, 1.0));
    double u = std::atan2(double(d.x), -double(d.z)) / (2 * kPi) + 0.5;
    if (u >= 1.0) u -= 1.0;
    return Vec2{float(u), float(theta / kPi)};
}

Vec3 rotateAboutY(Vec3 v, double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return Vec3{float(c * v.x + s * v.z), v.y, float(-s * v.x + c * v.z)};
}

Vec3 environmentRadiance(const Environment& env, Vec3 background, Vec3 direction) {
    if (!env.map) return background * env.intensity;
    const EnvironmentMap& m = *env.map;
    Vec2 uv = environmentUv(rotateAboutY(direction, -double(env.rotationDegrees) * kPi / 180));
    const int x = std::min(int(uv.x * float(m.width)), m.width - 1);
    const int y = std::min(int(uv.y * float(m.height)), m.height - 1);
    return m.radiance[std::size_t(y) * std::size_t(m.width) + std::size_t(x)] * env.intensity;
}

std::vector<Light> distantLights(const Environment& env) {
    std::vector<Light> out;
    if (env.sun) {
        Light sun = *env.sun;
        sun.direction = rotateAboutY(sun.direction, double(env.rotationDegrees) * kPi / 180);
        sun.intensity *= env.intensity;
        out.push_back(sun);
    }
    return out;
}

Vec3 skyPortalRadiance(const Environment& env, Vec3 background) {
    if (!env.map || env.map->width <= 0 || env.map->height <= 0) return background * env.intensity;
    const EnvironmentMap& m = *env.map;
    // Rows above the horizon: the integral of cos(theta) over a row's band is
    // (sin^2 theta1 - sin^2 theta0) / 2 per radian of azimuth; over the hemisphere it sums to 1/2.
    double sum[3] = {0, 0, 0}, weight = 0;
    for (int y = 0; y < m.height; ++y) {
        const double t0 = kPi * y / m.height, t1 = std::min(kPi * (y + 1) / m.height, kPi / 2);
        if (t0 >= kPi / 2) break;
        const double w = 0.5 * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0)) / m.width;
        for (int x = 0; x < m.width; ++x) {
            const Vec3 c = m.radiance[std::size_t(y) * std::size_t(m.width) + std::size_t(x)];
            for (int k = 0; k < 3; ++k) sum[k] += c[k] * w;
        }
        weight += w * m.width;
    }
    if (!(weight > 0)) return Vec3{0};
    return Vec3{float(sum[0] / weight), float(sum[1] / weight), float(sum[2] / weight)} * env.intensity;
}

void validateEnvironment(const Environment& env) {
    if (!(std::isfinite(env.intensity) && env.intensity >= 0))
        throw Error("environment intensity must be finite and >= 0");
    if (!std::isfinite(env.rotationDegrees)) throw Error("environment rotation must be finite");
    if (env.sun && (env.sun->type != LightType::Directional || !(env.sun->angularRadius <= kMaxAngularRadius)))
        throw Error("environment sun must be a directional light of angular radius at most 45 degrees");
    if (!env.map) return;
    const EnvironmentMap& m = *env.map;
    if (m.width <= 0 || m.height <= 0 || m.width > kMaxEnvironmentSide || m.height > kMaxEnvironmentSide ||
        std::size_t(m.width) * std::size_t(m.height) > kMaxEnvironmentTexels)
        throw Error("environment '" + m.name + "' is " + std::to_string(m.width) + "x" + std::to_string(m.height) +
                    "; sides must be 1.." + std::to_string(kMaxEnvironmentSide) + " and the map at most " +
                    std::to_string(kMaxEnvironmentTexels) + " texels");
    if (m.radiance.size() != std::size_t(m.width) * std::size_t(m.height))
        throw Error("environment '" + m.name + "' has inconsistent size or pixel data");
    for (std::size_t i = 0; i < m.radiance.size(); ++i)
        if (!isFinite(m.radiance[i]) || minComponent(m.radiance[i]) < 0)
            throw Error("environment '" + m.name + "': texel " + std::to_string(i % std::size_t(m.width)) + "," +
                        std::to_string(i / std::size_t(m.width)) + " is negative or not finite");
}

}  // namespace penumbra
