// Typed, bounds-checked views of glTF accessors: an accessor's bytes are checked against its
// buffer view and buffer before a view is made, so reading element i < count is always in range.
#pragma once

#include <tiny_gltf.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace penumbra::gltf {

struct AccessorView {
    const unsigned char* data = nullptr;
    std::size_t count = 0;
    std::size_t stride = 0;
    int componentType = 0;
    int components = 0;
    bool normalized = false;

    double component(std::size_t i, int c) const {
        const unsigned char* p = data + i * stride;
        switch (componentType) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: {
                float f;
                std::memcpy(&f, p + 4 * c, 4);
                return f;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
                std::uint32_t u;
                std::memcpy(&u, p + 4 * c, 4);
                return u;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                std::uint16_t u;
                std::memcpy(&u, p + 2 * c, 2);
                return normalized ? u / 65535.0 : u;
            }
            case TINYGLTF_COMPONENT_TYPE_SHORT: {
                std::int16_t s;
                std::memcpy(&s, p + 2 * c, 2);
                return normalized ? std::max(s / 32767.0, -1.0) : s;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
                const std::uint8_t u = p[c];
                return normalized ? u / 255.0 : u;
            }
            case TINYGLTF_COMPONENT_TYPE_BYTE: {
                std::int8_t s;
                std::memcpy(&s, p + c, 1);
                return normalized ? std::max(s / 127.0, -1.0) : s;
            }
        }
        return 0;
    }
};

// The view of accessor `index` of `model`, which must have `wantComponents` components per
// element; throws Error saying where (`where`) and what is wrong otherwise. Sparse accessors are
// refused.
AccessorView readAccessor(const tinygltf::Model& model, int index, const std::string& where, int wantComponents);

}  // namespace penumbra::gltf
