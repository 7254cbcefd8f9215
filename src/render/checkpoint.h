// Checkpoint files of final renders (--checkpoint, --resume): what ProgressiveRender needs to
// continue exactly where a render stopped, tied by a key to the scene and settings it was made
// with. Written atomically; read with every size checked against the header before use, and a
// checksum over the whole, so a truncated, corrupt or foreign file is one clear error.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "render/adaptive.h"
#include "render/progressive.h"
#include "render/renderer.h"

namespace penumbra {

using RenderKey = std::array<std::uint64_t, 2>;  // XXH3-128

// A hash of everything that decides the image: the uploaded scene (BVH, triangles, materials,
// textures, lights, environment), the frame constants (camera, image size, seed, bounces, the
// scene moment's camera included) and the adaptive settings. Budgets (--spp, --time-limit) are
// left out: a checkpoint may be continued with a larger budget.
RenderKey renderKey(const Renderer& renderer, const AdaptiveSettings& adaptive);

std::string encodeCheckpoint(const RenderSnapshot& snapshot, const RenderKey& key);
// Throws Error naming `name` and what is wrong: not a checkpoint, another version, truncated,
// corrupt (checksum), made for another scene or settings (key), another image size.
RenderSnapshot decodeCheckpoint(std::string_view bytes, const RenderKey& key, std::uint32_t width,
                                std::uint32_t height, const std::string& name);

void writeCheckpoint(const std::filesystem::path& path, const RenderSnapshot& snapshot, const RenderKey& key);
RenderSnapshot readCheckpoint(const std::filesystem::path& path, const RenderKey& key, std::uint32_t width,
                              std::uint32_t height);

}  // namespace penumbra
