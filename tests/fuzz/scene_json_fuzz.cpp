// Fuzz target: Penumbra's JSON scene files.
#include <cstdint>
#include <string_view>

#include "core/error.h"
#include "scene/io/scene_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        penumbra::SceneFileSettings settings;
        penumbra::loadSceneJsonFromText(std::string_view(reinterpret_cast<const char*>(data), size),
                                        "/nonexistent-fuzz-dir", "fuzz.json", &settings);
    } catch (const penumbra::Error&) {
        // Rejecting bad input with a message is the correct outcome.
    }
    return 0;
}
