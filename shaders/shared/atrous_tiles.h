// How the a-trous passes map their work groups onto pixels, which the host (dispatch sizes) and
// atrous.comp both need, written once. Valid GLSL and C++; include after shared/types.h.
//
// A pass at step s filters with taps s pixels apart. A group of PN_TRACE_GROUP_X^2 threads owns
// not a block of neighbouring pixels but a lattice of pixels s apart, so all its 25-tap
// neighbourhoods fall on one (PN_TRACE_GROUP_X + 4)^2 lattice, which it reads once into shared
// memory. s x s groups, one per lattice phase, cover a square tile of PN_TRACE_GROUP_X * s pixels.
#ifndef PENUMBRA_SHADER_ATROUS_TILES_H
#define PENUMBRA_SHADER_ATROUS_TILES_H

#ifdef __cplusplus
namespace penumbra::shader {
#ifndef PN_INLINE
#define PN_INLINE inline
#endif
#else
#ifndef PN_INLINE
#define PN_INLINE
#endif
#endif

#define PN_ATROUS_LATTICE PN_TRACE_GROUP_X              // a group's lattice side, in pixels s apart
#define PN_ATROUS_APRON (PN_ATROUS_LATTICE + 4u)       // with the kernel's two taps each side

// Groups along an image side of `pixels` at step `step`: whole tiles, each `step` groups wide.
PN_INLINE uint atrousGroupCount(uint pixels, uint step) {
    uint tile = PN_ATROUS_LATTICE * step;
    return (pixels + tile - 1u) / tile * step;
}

// The pixel coordinate, along one axis, of lattice point `point` (may be negative: the apron)
// of group `group` at step `step`.
PN_INLINE int atrousLatticePixel(uint group, int point, uint step) {
    return int(group / step * PN_ATROUS_LATTICE * step + group % step) + point * int(step);
}

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
