// Fuzzes the Assimp importer (assimp_loader.cpp and the Assimp readers behind it). The input is
// an extension hint on the first line ("stl", "dae", "off", ...), then the model's bytes; the
// hint picks Assimp's reader as a file name would. Inputs over 256 KiB are skipped: Assimp
// believes the counts of several formats and parses slowly, and libFuzzer learns nothing from
// size alone. Errors are expected; crashes, hangs and sanitizer reports are bugs (ours, or
// Assimp's to report upstream).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/error.h"
#include "scene/io/assimp_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > (std::size_t(256) << 10)) return 0;
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    const std::size_t newline = input.find('\n');
    if (newline == std::string_view::npos || newline > 8) return 0;
    const std::string hint(input.substr(0, newline));
    if (!penumbra::isAssimpExtension("." + hint)) return 0;
    try {
        penumbra::Scene scene = penumbra::loadAssimpFromMemory(input.substr(newline + 1), "fuzz." + hint, hint);
        (void)scene.triangleCount();
    } catch (const penumbra::Error&) {
    }
    return 0;
}
