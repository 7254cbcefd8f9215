#include "scene/node_animation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace penumbra {
namespace {

KeyValue lerp(const KeyValue& a, const KeyValue& b, double s) {
    KeyValue out;
    for (int i = 0; i < 4; ++i) out[std::size_t(i)] = float(a[std::size_t(i)] + (b[std::size_t(i)] - a[std::size_t(i)]) * s);
    return out;
}

KeyValue normalized(KeyValue q) {
    double len = 0;
    for (float c : q) len += double(c) * c;
    len = std::sqrt(len);
    if (!(len > 0) || !std::isfinite(len)) return {0, 0, 0, 1};
    for (float& c : q) c = float(c / len);
    return q;
}

KeyValue slerp(const KeyValue& a, KeyValue b, double s) {
    double cosTheta = 0;
    for (int i = 0; i < 4; ++i) cosTheta += double(a[std::size_t(i)]) * b[std::size_t(i)];
    if (cosTheta < 0) {  // q and -q are one rotation: take the shorter way
        for (float& c : b) c = -c;
        cosTheta = -cosTheta;
    }
    if (cosTheta > 0.9995) return normalized(lerp(a, b, s));  // nearly equal: lerp is exact enough
    const double theta = std::acos(std::min(cosTheta, 1.0));
    const double wa = std::sin((1 - s) * theta) / std::sin(theta), wb = std::sin(s * theta) / std::sin(theta);
    KeyValue out;
    for (int i = 0; i < 4; ++i) out[std::size_t(i)] = float(wa * a[std::size_t(i)] + wb * b[std::size_t(i)]);
    return normalized(out);
}

Vec3 xyz(const KeyValue& v) { return {v[0], v[1], v[2]}; }

}  // namespace

KeyValue sampleTrack(const Track& track, double seconds, bool quaternion) {
    const std::size_t n = track.times.size();
    PN_CHECK(n > 0);
    const bool cubic = track.interpolation == KeyInterpolation::CubicSpline;
    auto value = [&](std::size_t k) { return track.values[cubic ? 3 * k + 1 : k]; };
    auto finish = [&](KeyValue v) { return quaternion ? normalized(v) : v; };
    if (!(seconds > track.times[0])) return finish(value(0));
    if (seconds >= track.times[n - 1]) return finish(value(n - 1));
    const std::size_t k = std::size_t(std::upper_bound(track.times.begin(), track.times.end(), float(seconds)) -
                                      track.times.begin()) - 1;
    const double t0 = track.times[k], t1 = track.times[k + 1], dt = t1 - t0;
    const double s = std::clamp((seconds - t0) / dt, 0.0, 1.0);
    switch (track.interpolation) {
        case KeyInterpolation::Step: return finish(value(k));
        case KeyInterpolation::Linear: return quaternion ? slerp(value(k), value(k + 1), s) : lerp(value(k), value(k + 1), s);
        case KeyInterpolation::CubicSpline: {
            // Hermite: p0, its out-tangent b0, p1 and its in-tangent a1, tangents scaled by dt.
            const KeyValue &p0 = value(k), &b0 = track.values[3 * k + 2], &p1 = value(k + 1), &a1 = track.values[3 * (k + 1)];
            const double s2 = s * s, s3 = s2 * s;
            const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
            KeyValue out;
            for (std::size_t i = 0; i < 4; ++i)
                out[i] = float(h00 * p0[i] + h10 * dt * b0[i] + h01 * p1[i] + h11 * dt * a1[i]);
            return finish(out);
        }
    }
    return finish(value(k));
}

Affine trsTransform(Vec3 translation, const KeyValue& rotation, Vec3 scale) {
    const KeyValue q = normalized(rotation);
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    const double s[3] = {scale.x, scale.y, scale.z};
    Affine a;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a.m[i][j] = float(r[i][j] * s[j]);
    a.m[0][3] = translation.x;
    a.m[1][3] = translation.y;
    a.m[2][3] = translation.z;
    return a;
}

Affine chainTransform(const std::vector<NodeMotion>& chain, double seconds) {
    Affine world;
    for (const NodeMotion& node : chain) {
        if (node.scripted) {
            world = world * motionTransform(*node.scripted, node.fixed, seconds);
            continue;
        }
        if (!node.trs) {
            world = world * node.fixed;
            continue;
        }
        const Vec3 t = node.translationTrack.present() ? xyz(sampleTrack(node.translationTrack, seconds, false))
                                                       : node.translation;
        const KeyValue r = node.rotationTrack.present() ? sampleTrack(node.rotationTrack, seconds, true) : node.rotation;
        const Vec3 s = node.scaleTrack.present() ? xyz(sampleTrack(node.scaleTrack, seconds, false)) : node.scale;
        world = world * trsTransform(t, r, s);
    }
    return world;
}

// Both: the linear parts multiply (later's applied last), the translations add.
Affine composeEdits(const Affine& later, const Affine& earlier) {
    Affine out = later * earlier;
    for (int i = 0; i < 3; ++i) out.m[i][3] = later.m[i][3] + earlier.m[i][3];
    return out;
}

Affine editedTransform(const Affine& edit, const Affine& animated) { return composeEdits(edit, animated); }

void validateTrack(const Track& track, const std::string& where) {
    const std::size_t perKey = track.interpolation == KeyInterpolation::CubicSpline ? 3 : 1;
    if (track.values.size() != track.times.size() * perKey)
        throw Error(where + ": " + std::to_string(track.times.size()) + " key times but " +
                    std::to_string(track.values.size()) + " values (" + std::to_string(perKey) + " per key expected)");
    for (std::size_t k = 0; k < track.times.size(); ++k)
        if (!std::isfinite(track.times[k]) || (k > 0 && !(track.times[k] > track.times[k - 1])))
            throw Error(where + ": key times must be finite and strictly increasing (key " + std::to_string(k) + ")");
    for (const KeyValue& v : track.values)
        for (float c : v)
            if (!std::isfinite(c)) throw Error(where + ": a key value is not finite");
}

}  // namespace penumbra
