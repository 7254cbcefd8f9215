#include "bvh/sphere.h"

#include <cmath>
#include <utility>

namespace penumbra::bvh {

Aabb sphereBounds(Vec3 center, float radius) {
    Aabb box;
    box.grow(center - Vec3{radius});
    box.grow(center + Vec3{radius});
    return box;
}

shader::TriVerts toSphereVerts(Vec3 center, float radius) {
    shader::TriVerts out{};
    out.v0 = center;
    out.flags = PN_TRI_SPHERE;
    out.e1 = Vec3{radius, 0, 0};
    return out;
}

bool intersectSphere(const shader::TriVerts& slot, const Ray& ray, float tMax, float& t) {
    const float r = slot.e1.x;
    const Vec3 d = ray.direction;
    const Vec3 f = ray.origin - slot.v0;
    const float a = dot(d, d);
    const float b = -dot(f, d);  // t = (b +- sqrt(disc)) / a
    const float c = dot(f, f) - r * r;
    // |f - (f.d / a) d|^2 is the squared distance of the centre from the line; unlike b^2 - ac it
    // does not lose all its digits when the ray passes far from a small sphere.
    const Vec3 perp = f + (b / a) * d;
    const float disc = a * (r * r - dot(perp, perp));
    if (!(disc >= 0.0f) || !(a > 0.0f)) return false;
    const float q = b >= 0.0f ? b + std::sqrt(disc) : b - std::sqrt(disc);
    if (q == 0.0f) return false;  // a tangent ray through the centre's foot at t = 0
    float t0 = c / q, t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > 0.0f && t0 < tMax) {
        t = t0;
        return true;
    }
    if (t1 > 0.0f && t1 < tMax) {
        t = t1;
        return true;
    }
    return false;
}

}  // namespace penumbra::bvh
