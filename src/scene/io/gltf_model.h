// Reading glTF 2.0 bytes (.gltf JSON or .glb) into a tinygltf model, with the limits that keep
// a malformed file from exhausting the stack or memory. tinygltf gets file-system callbacks that
// read only below the asset's folder (no shell expansion, no writes) and an image callback that
// keeps the encoded bytes, so images are decoded later, once, by texture_io.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace penumbra::gltf {

constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(2) << 30;  // tinygltf takes 32-bit lengths

// The model in `bytes`; external buffers and images are read relative to `baseDir`, never above
// it. Throws Error naming `name` when the bytes are not a glTF that tinygltf can read.
tinygltf::Model parseModel(std::string_view bytes, const std::filesystem::path& baseDir, const std::string& name);

// A name or message from the file, safe to print: at most 80 characters, control characters '?'.
std::string clampName(std::string s);

}  // namespace penumbra::gltf
