// What every header of shaders/shared/ that declares a struct needs first: the C++ meaning of the
// GLSL types and the PN_STRUCT macros. Layouts follow std430 by hand: each vec3 is followed by a
// 4-byte scalar so that nothing is padded implicitly, and the C++ side checks every size and
// offset with static_asserts beside each struct (tests/unit/layout_test.cpp checks the GLSL side).
#ifndef PENUMBRA_SHADER_PRELUDE_H
#define PENUMBRA_SHADER_PRELUDE_H

#ifdef __cplusplus
#include "core/gpu_types.h"
#define PN_STRUCT(name) struct alignas(16) name
// A struct whose widest member is a vec2 (std430 base alignment 8) or a scalar (4): std430 packs
// its array elements at its own size, with no rounding to 16 bytes.
#define PN_STRUCT8(name) struct alignas(8) name
#define PN_STRUCT4(name) struct alignas(4) name
namespace penumbra::shader {
using namespace penumbra::gpu_types;
}  // namespace penumbra::shader
#else
#define PN_STRUCT(name) struct name
#define PN_STRUCT8(name) struct name
#define PN_STRUCT4(name) struct name
#endif

#endif
