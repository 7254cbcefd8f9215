// Fuzz target: render checkpoint files (render/checkpoint.h), as `penumbra render --resume` reads
// them. The key is taken from the input's own header when it has one, so inputs get past the key
// check to the size and checksum checks (a real resume would refuse a foreign key earlier).
#include <cstdint>
#include <cstring>
#include <string_view>

#include "core/error.h"
#include "render/checkpoint.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    penumbra::RenderKey key{0, 0};
    std::uint32_t width = 1, height = 1;
    if (size >= 40) {
        std::memcpy(key.data(), data + 16, sizeof key);  // the header's key, then width and height
        std::memcpy(&width, data + 32, sizeof width);
        std::memcpy(&height, data + 36, sizeof height);
    }
    try {
        penumbra::decodeCheckpoint(bytes, key, width, height, "fuzz");
    } catch (const penumbra::Error&) {
        // Rejecting bad input with a message is the correct outcome.
    }
    return 0;
}
