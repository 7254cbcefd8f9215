// Fuzzes the OBJ importer. The input is OBJ text, then optionally a NUL byte and MTL text (used
// for any `mtllib`). Textures are looked up in a folder that does not exist, so they become the
// checker. Errors are expected; crashes, hangs and sanitizer reports are bugs.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.h"
#include "scene/io/obj.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const std::size_t nul = bytes.find('\0');
    std::string_view obj = bytes.substr(0, nul);
    std::string_view mtl = nul == std::string_view::npos ? std::string_view{} : bytes.substr(nul + 1);
    try {
        penumbra::Scene scene = penumbra::loadObjFromMemory(obj, mtl, "/nonexistent-penumbra-fuzz", "fuzz.obj");
        (void)scene.triangleCount();
    } catch (const penumbra::Error&) {
    }
    return 0;
}
