// Fuzzes the PLY importer: the input is a PLY file (ASCII or binary, or gzip-compressed).
// Errors are expected; crashes, hangs, sanitizer reports and runaway memory are bugs.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.h"
#include "scene/io/ply.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        penumbra::Scene scene = penumbra::loadPlyFromMemory(
            std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.ply");
        (void)scene.triangleCount();
    } catch (const penumbra::Error&) {
    }
    return 0;
}
