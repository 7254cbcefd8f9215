// The C++ meaning of the GLSL types used in shaders/shared/types.h.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/vec.h"

namespace penumbra::gpu_types {
using uint = std::uint32_t;
using vec2 = penumbra::Vec2;
using vec3 = penumbra::Vec3;
using vec4 = penumbra::Vec4;
}  // namespace penumbra::gpu_types
