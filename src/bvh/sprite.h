// Sprites as BVH primitives: a sprite occupies a TriVerts slot flagged PN_TRI_SPRITE (layout in
// shared/types.h), bounded by the vertical cylinder its card sweeps as it turns. Only the GPU
// intersects them (lib/sprite.glsl): a sprite turns to face each ray's origin and is alpha
// tested, which the CPU reference does not model; it reports no hit on them.
#pragma once

#include "shared/types.h"

namespace penumbra::bvh {

inline bool isSprite(const shader::TriVerts& slot) { return (slot.flags & PN_TRI_SPRITE) != 0; }

}  // namespace penumbra::bvh
