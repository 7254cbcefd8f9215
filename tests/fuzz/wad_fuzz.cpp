// libFuzzer target for the WAD loader: any input must load or throw penumbra::Error.
#include <cstdint>
#include <string_view>

#include "core/error.h"
#include "scene/io/wad/wad_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view bytes(reinterpret_cast<const char*>(data), size);
    try {
        penumbra::wadMapNames(bytes);
        penumbra::Scene scene = penumbra::loadWadFromMemory(bytes, "", "fuzz.wad");
        (void)scene;
    } catch (const penumbra::Error&) {
    }
    return 0;
}
