#include "gpu/shaders.h"

#include <string>

#include "core/error.h"

namespace penumbra::gpu {

std::span<const std::uint32_t> shaderCode(std::string_view name) {
    for (std::size_t i = 0; i < embedded::kShaderCount; ++i)
        if (name == embedded::kShaders[i].name)
            return {embedded::kShaders[i].words, embedded::kShaders[i].wordCount};
    throw Error("no embedded shader named '" + std::string(name) + "' (the build is incomplete)");
}

}  // namespace penumbra::gpu
