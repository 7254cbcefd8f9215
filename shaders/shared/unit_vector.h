// Unit vectors in one 32-bit word (the shading normals in TriAttribs): the octahedral map of
// Cigolle et al. 2014 ("A Survey of Efficient Representations for Independent Unit Vectors"),
// two 16-bit signed normalised coordinates. The vector is projected onto the octahedron
// |x| + |y| + |z| = 1, whose lower half is folded out over the corners of the square [-1, 1]^2;
// the round trip is within 1e-4 radians. Valid GLSL and C++; the host packs, both sides unpack.
#ifndef PENUMBRA_SHADER_UNIT_VECTOR_H
#define PENUMBRA_SHADER_UNIT_VECTOR_H

#ifdef __cplusplus
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/gpu_types.h"
namespace penumbra::shader {
using namespace penumbra::gpu_types;
using std::abs;
#ifndef PN_INLINE
#define PN_INLINE inline
#endif
// GLSL's unpackSnorm2x16 (GLSL 4.60, section 8.4): x from the low half, y from the high one.
inline vec2 unpackSnorm2x16(uint p) {
    auto f = [](uint bits) { return std::clamp(float(std::int16_t(std::uint16_t(bits))) / 32767.0f, -1.0f, 1.0f); };
    return vec2{f(p & 0xffffu), f(p >> 16)};
}
#else
#ifndef PN_INLINE
#define PN_INLINE
#endif
#endif

PN_INLINE float pnSignNotZero(float x) { return x < 0.0f ? -1.0f : 1.0f; }

PN_INLINE vec3 unpackUnitVector(uint p) {
    vec2 e = unpackSnorm2x16(p);
    vec3 n = vec3(e.x, e.y, 1.0f - abs(e.x) - abs(e.y));
    if (n.z < 0.0f) {
        float x = n.x;
        n.x = (1.0f - abs(n.y)) * pnSignNotZero(x);
        n.y = (1.0f - abs(x)) * pnSignNotZero(n.y);
    }
    return normalize(n);
}

#ifdef __cplusplus
// The inverse of unpackUnitVector, for any non-zero vector (its direction); a zero or non-finite
// one packs as +z. Rounds each coordinate to the nearest 16-bit step (GLSL's packSnorm2x16).
inline uint packUnitVector(vec3 n) {
    const float s = abs(n.x) + abs(n.y) + abs(n.z);
    if (!(s > 0.0f) || !std::isfinite(s)) return 0u;
    float x = n.x / s, y = n.y / s;
    if (n.z < 0.0f) {
        const float fx = (1.0f - abs(y)) * pnSignNotZero(x);
        y = (1.0f - abs(x)) * pnSignNotZero(y);
        x = fx;
    }
    auto q = [](float c) { return uint(std::uint16_t(std::int16_t(std::lround(std::clamp(c, -1.0f, 1.0f) * 32767.0f)))); };
    return q(x) | (q(y) << 16);
}
}  // namespace penumbra::shader
#endif
#endif
