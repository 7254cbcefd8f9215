// The 30-bit Morton code of a point (Karras 2012, section 4; the bit interleaving of Morton 1966),
// written once for the CPU's Morton build (bvh/morton_build.cpp) and the GPU's (shaders/lbvh_*.comp)
// so both sort primitives along the same curve. Valid GLSL and C++.
#ifndef PENUMBRA_SHADER_MORTON_H
#define PENUMBRA_SHADER_MORTON_H

#include "shared/prelude.h"
#include "shared/inline.h"

#ifdef __cplusplus
namespace penumbra::shader {
#endif

#define PN_MORTON_CELLS 1024  // cells per axis: 10 bits each, 30 in all

// The 10 low bits of v spread to every third bit.
PN_INLINE uint pnSpreadBits(uint v) {
    v &= 0x3ffu;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

// The cell of an offset from the centres' lower corner. One scale for the three axes (cubic
// cells): a thin scene's short axis then gets fewer distinct codes, so the splits follow its long
// axes as SAH would. Written with comparisons, not clamp(), so that NaN lands in cell 0 on both
// sides alike.
PN_INLINE uint pnMortonCell(float offset, float scale) {
    float c = offset * scale;
    if (!(c > 0.0f)) return 0u;
    if (c > float(PN_MORTON_CELLS - 1)) return uint(PN_MORTON_CELLS - 1);
    return uint(c);
}

// scale = PN_MORTON_CELLS / (the longest side of the centres' bounds), 0 when they are a point.
PN_INLINE uint pnMortonCode(vec3 offset, float scale) {
    return (pnSpreadBits(pnMortonCell(offset.x, scale)) << 2) | (pnSpreadBits(pnMortonCell(offset.y, scale)) << 1) |
           pnSpreadBits(pnMortonCell(offset.z, scale));
}

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif

#endif
