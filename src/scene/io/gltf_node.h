// A glTF node's local transform: its matrix, or translation * rotation * scale.
#pragma once

#include <tiny_gltf.h>

#include <string>

#include "core/transform.h"

namespace penumbra::gltf {

// Throws Error (saying `where`) when a value is not finite or an array has the wrong length; a
// zero rotation quaternion is the identity.
Affine nodeTransform(const tinygltf::Node& n, const std::string& where);

}  // namespace penumbra::gltf
