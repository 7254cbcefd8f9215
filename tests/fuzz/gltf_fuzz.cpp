// Fuzzes the glTF importer with .gltf JSON or .glb bytes. External files are looked up in a
// folder that does not exist; data URIs and GLB chunks are read. Errors are expected; crashes,
// hangs and sanitizer reports are bugs.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.h"
#include "scene/io/gltf.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view bytes(reinterpret_cast<const char*>(data), size);
    try {
        penumbra::Scene scene = penumbra::loadGltfFromMemory(bytes, "/nonexistent-penumbra-fuzz", "fuzz.gltf");
        (void)scene.triangleCount();
    } catch (const penumbra::Error&) {
    }
    return 0;
}
