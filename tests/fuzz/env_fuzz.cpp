// Fuzz target: environment maps (.hdr RGBE and .exr), told apart by their magic numbers.
#include <cstdint>
#include <string_view>

#include "core/error.h"
#include "scene/io/env_load.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        penumbra::decodeEnvironmentMap(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
    } catch (const penumbra::Error&) {
        // Rejecting bad input with a message is the correct outcome.
    }
    return 0;
}
