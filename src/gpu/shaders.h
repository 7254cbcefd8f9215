// SPIR-V compiled from shaders/ at build time and embedded in the binary (cmake/Shaders.cmake).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace penumbra::gpu {

struct EmbeddedShader {
    const char* name;  // path under shaders/ with '/' turned to '_' and no extension: "trace", "test_ray_query"
    const std::uint32_t* words;
    std::size_t wordCount;
};

namespace embedded {
extern const EmbeddedShader kShaders[];
extern const std::size_t kShaderCount;
}  // namespace embedded

// Throws Error if no shader has that name (a build problem, not a user one).
std::span<const std::uint32_t> shaderCode(std::string_view name);

}  // namespace penumbra::gpu
