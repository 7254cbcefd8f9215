#include "scene/object_motion.h"

#include <cmath>

#include "core/error.h"
#include "scene/node_animation.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

// The points visited in order during one period (Loop: closed; BackAndForth: there and back).
std::vector<Vec3> periodPoints(const ScriptedMotion& m) {
    std::vector<Vec3> points = m.path;
    if (m.repeat == MotionRepeat::Loop) points.push_back(m.path.front());
    if (m.repeat == MotionRepeat::BackAndForth)
        for (std::size_t i = m.path.size() - 1; i-- > 0;) points.push_back(m.path[i]);
    return points;
}

double polylineLength(const std::vector<Vec3>& points) {
    double total = 0;
    for (std::size_t i = 1; i < points.size(); ++i) total += double(length(points[i] - points[i - 1]));
    return total;
}

}  // namespace

Vec3 pathOffset(const ScriptedMotion& motion, double seconds) {
    if (motion.path.empty()) return Vec3{0};
    if (motion.path.size() < 2 || !(seconds > 0)) return motion.path.front();
    const std::vector<Vec3> points = periodPoints(motion);
    const double period = polylineLength(points);
    if (!(period > 0)) return motion.path.front();
    double s = seconds * double(motion.speed);
    if (motion.repeat == MotionRepeat::Once && s >= period) return points.back();
    s = std::fmod(s, period);
    for (std::size_t i = 1; i < points.size(); ++i) {
        const double segment = double(length(points[i] - points[i - 1]));
        if (s <= segment && segment > 0)
            return points[i - 1] + (points[i] - points[i - 1]) * float(s / segment);
        s -= segment;
    }
    return points.back();
}

Affine motionTransform(const ScriptedMotion& motion, const Affine& placement, double seconds) {
    Affine spin;
    if (motion.spinDegreesPerSecond != 0) {
        // The turn so far, wrapped to one revolution so long times keep their precision.
        const double degrees = std::fmod(double(motion.spinDegreesPerSecond) * seconds, 360.0);
        const double half = degreesToRadians(degrees) / 2;
        const Vec3 axis = normalize(motion.spinAxis) * float(std::sin(half));
        spin = trsTransform(Vec3{0}, KeyValue{axis.x, axis.y, axis.z, float(std::cos(half))}, Vec3{1});
    }
    return Affine::translation(pathOffset(motion, seconds)) * placement * spin;
}

void validateMotion(const ScriptedMotion& motion, const std::string& where) {
    for (std::size_t i = 0; i < motion.path.size(); ++i)
        if (!isFinite(motion.path[i]) || length(motion.path[i]) > 1e9f)
            throw Error(where + ": path point " + std::to_string(i) + " is not a finite position");
    if (!(motion.speed > 0) || !std::isfinite(motion.speed))
        throw Error(where + ": speed must be a finite number of metres per second > 0");
    if (!std::isfinite(motion.spinDegreesPerSecond) || !isFinite(motion.spinAxis))
        throw Error(where + ": spin must be finite");
    if (motion.spinDegreesPerSecond != 0 && !(length(motion.spinAxis) > 1e-6f))
        throw Error(where + ": the spin axis has no length");
}

}  // namespace penumbra
