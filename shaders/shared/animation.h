// Which frame of an animated texture is on show at a moment, written once for the host (which
// must know when the image changes) and the shaders (which pick the frame). Valid GLSL and C++.
#ifndef PENUMBRA_SHADER_ANIMATION_H
#define PENUMBRA_SHADER_ANIMATION_H

#ifdef __cplusplus
#include <cmath>

#include "core/gpu_types.h"
namespace penumbra::shader {
using namespace penumbra::gpu_types;
using std::floor;
using std::min;
#endif
#include "shared/inline.h"

// Frames shown since time 0 at `time` seconds, each for `secondsPerFrame`: the animation clock's
// tick. 0 for a still texture (no positive frame time) or a time that is not a number >= 0.
PN_INLINE uint animationTick(float time, float secondsPerFrame) {
    if (!(secondsPerFrame > 0.0f) || !(time >= 0.0f)) return 0u;
    return uint(min(floor(time / secondsPerFrame), 4294967040.0f));
}

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
