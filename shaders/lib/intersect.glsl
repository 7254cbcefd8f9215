// Ray-primitive tests shared by every traversal.
#ifndef PN_INTERSECT_GLSL
#define PN_INTERSECT_GLSL

const float PN_INFINITY = 1.0 / 0.0;
const float PN_SLAB_EXIT_SCALE = 1.0000003576278687;  // 1 + 2 * 3u / (1 - 3u), u = 2^-24

// Moller-Trumbore by Cramer's rule against precomputed edges; two-sided; accepts 0 < t < tMax.
// The geometric normal e1 x e2 is formed first so a triangle with repeated vertices has a
// determinant of exactly zero and never hits. The operation order is the CPU reference's
// (bvh/traverse_cpu.cpp), and `precise` stops the compiler fusing multiply-adds, so GPU and CPU
// compute the same t and tests can compare them tightly.
bool intersectTriangle(TriVerts tri, vec3 o, vec3 d, float tMax, out float t, out float u, out float v) {
    t = 0.0;
    u = 0.0;
    v = 0.0;
    precise vec3 n = cross(tri.e1, tri.e2);
    precise float det = -dot(d, n);
    if (det == 0.0) return false;
    precise float invDet = 1.0 / det;
    precise vec3 s = o - tri.v0;
    precise vec3 c = cross(s, d);
    precise float uu = dot(tri.e2, c) * invDet;
    if (!(uu >= 0.0 && uu <= 1.0)) return false;
    precise float vv = -dot(tri.e1, c) * invDet;
    if (!(vv >= 0.0 && uu + vv <= 1.0)) return false;
    precise float tt = dot(s, n) * invDet;
    if (!(tt > 0.0 && tt < tMax)) return false;
    t = tt;
    u = uu;
    v = vv;
    return true;
}

// Whether direction d sees the triangle's back (its normal e1 x e2, the counter-clockwise front,
// points along d): the sign of intersectTriangle's determinant, by the same operations in the same
// order, so back-face culling agrees with the CPU reference bit for bit. Edge-on is not a back.
bool facesAway(TriVerts tri, vec3 d) {
    precise vec3 n = cross(tri.e1, tri.e2);
    precise float det = -dot(d, n);
    return det < 0.0;
}

// The nearest root with t in (0, tMax) of |o + t d - c| = r for a PN_TRI_SPHERE slot (v0 = c,
// e1.x = r), in the numerically stable form of Ray Tracing Gems ch. 7: the discriminant comes
// from the centre's distance to the ray's line (not b^2 - ac, which loses every digit when a
// small sphere is far away), and the root nearer zero is c / q. A ray starting inside finds the
// exit. Same arithmetic, same order as the CPU reference (bvh/sphere.cpp).
bool intersectSphere(TriVerts sphere, vec3 o, vec3 d, float tMax, out float t) {
    t = 0.0;
    precise float r = sphere.e1.x;
    precise vec3 f = o - sphere.v0;
    precise float a = dot(d, d);
    precise float b = -dot(f, d);
    precise float c = dot(f, f) - r * r;
    precise vec3 perp = f + (b / a) * d;
    precise float disc = a * (r * r - dot(perp, perp));
    if (!(disc >= 0.0) || !(a > 0.0)) return false;
    precise float root = sqrt(disc);
    precise float q = b >= 0.0 ? b + root : b - root;
    if (q == 0.0) return false;
    precise float t0 = c / q;
    precise float t1 = q / a;
    float near = min(t0, t1), far = max(t0, t1);
    if (near > 0.0 && near < tMax) {
        t = near;
        return true;
    }
    if (far > 0.0 && far < tMax) {
        t = far;
        return true;
    }
    return false;
}

// 1/d with zero components replaced by a huge finite value, so the slab test never computes
// 0 * inf (NaN) for rays parallel to a slab.
vec3 safeInverse(vec3 d) {
    const float tiny = 1e-30;
    return 1.0 / vec3(abs(d.x) < tiny ? (d.x < 0.0 ? -tiny : tiny) : d.x,
                      abs(d.y) < tiny ? (d.y < 0.0 ? -tiny : tiny) : d.y,
                      abs(d.z) < tiny ? (d.z < 0.0 ? -tiny : tiny) : d.z);
}

// Entry distance into the box (0 when the origin is inside), or infinity on a miss or when the
// box starts beyond tMax.
float slabEntry(vec3 lo, vec3 hi, vec3 o, vec3 invD, float tMax) {
    vec3 t0 = (lo - o) * invD;
    vec3 t1 = (hi - o) * invD;
    vec3 tNear = min(t0, t1);
    vec3 tFar = max(t0, t1);
    float enter = max(max(tNear.x, tNear.y), max(tNear.z, 0.0));
    float leave = min(min(tFar.x, tFar.y), min(tFar.z, tMax));
    // Exits are widened by pbrt's 1 + 2 gamma(3) so rounding never culls a box whose triangle
    // the exact test would hit (the same constant as bvh::kSlabExitScale).
    return enter <= leave * PN_SLAB_EXIT_SCALE ? enter : PN_INFINITY;
}

#endif
