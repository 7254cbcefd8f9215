#include "render/scene_limits.h"

#include "core/error.h"
#include "gpu/limits.h"
#include "render/gpu_scene.h"

namespace penumbra {
namespace {

template <typename T>
std::uint64_t bytesOf(const std::vector<T>& v) {
    return std::uint64_t(v.size()) * sizeof(T);
}

const char* const kFix = "use a smaller scene (fewer triangles, smaller textures) or another device (--device)";

}  // namespace

std::vector<SceneBufferSize> sceneBufferSizes(const SceneArrays& a) {
    return {{"BVH nodes", binaryWalkBytes(a) + bytesOf(a.wideNodes)},  // one buffer
            {"triangle positions", bytesOf(a.triVerts)},
            {"triangle attributes", bytesOf(a.triAttribs)},
            {"texture coordinates", bytesOf(a.triUvs)},
            {"materials", bytesOf(a.materials)},
            {"light references", bytesOf(a.lightRefs)},
            {"top-level light bounds", bytesOf(a.lightNodes)},
            {"light tree", bytesOf(a.lightTree) + bytesOf(a.lightGrid)},
            {"texture table", bytesOf(a.textures)},
            {"texels", bytesOf(a.texels)},
            {"punctual lights", bytesOf(a.punctual)},
            {"sphere lights", bytesOf(a.sphereLights)},
            {"environment sampling table", bytesOf(a.env.alias)},
            {"environment map", bytesOf(a.env.radiance)},
            {"instances", bytesOf(a.instances)}};
}

void checkSceneFitsDevice(const gpu::Context& ctx, const SceneArrays& arrays) {
    const gpu::MemoryLimits limits = gpu::memoryLimits(ctx);
    std::uint64_t total = 0;
    for (const SceneBufferSize& b : sceneBufferSizes(arrays)) {
        total += b.bytes;
        if (b.bytes > limits.maxStorageBufferRange)
            throw Error("the scene's " + std::string(b.name) + " take " + gpu::formatBytes(b.bytes) + ", more than " +
                        ctx.info().name + " allows for one storage buffer (maxStorageBufferRange " +
                        gpu::formatBytes(limits.maxStorageBufferRange) + "): " + kFix);
    }
    if (total > limits.deviceLocalBytes)
        throw Error("the scene takes " + gpu::formatBytes(total) + " on the GPU, more than the " +
                    gpu::formatBytes(limits.deviceLocalBytes) + " of device memory " + ctx.info().name + " has: " + kFix);
}

}  // namespace penumbra
