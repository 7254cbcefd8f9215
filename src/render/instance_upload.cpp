#include "render/instance_upload.h"

#include <algorithm>
#include <cstring>
#include <span>

#include "bvh/child_pairs.h"
#include "core/error.h"
#include "shared/accel_layouts.h"

namespace penumbra {
namespace {

std::size_t topNodeCount(const SceneArrays& a) { return a.nodes.size() - std::min<std::size_t>(a.bottomNodeCount, a.nodes.size()); }

// Lays the parts out one after another in the staging buffer and records each part's copy.
class StagedCopies {
public:
    StagedCopies(VkCommandBuffer cmd, const gpu::Buffer& staging, VkDeviceSize offset)
        : cmd_(cmd), staging_(staging), at_(offset) {}
    // Reserves `bytes` of staging for dst at dstOffset; returns where to write them.
    void* add(const gpu::Buffer& dst, VkDeviceSize dstOffset, VkDeviceSize bytes) {
        PN_CHECK(at_ + bytes <= staging_.size() && dstOffset + bytes <= dst.size());
        void* where = static_cast<std::uint8_t*>(staging_.mapped()) + at_;
        const VkBufferCopy region{at_, dstOffset, bytes};
        if (bytes > 0) vkCmdCopyBuffer(cmd_, staging_.get(), dst.get(), 1, &region);
        at_ += bytes;
        return where;
    }

private:
    VkCommandBuffer cmd_;
    const gpu::Buffer& staging_;
    VkDeviceSize at_;
};

template <typename T>
VkDeviceSize bytesOf(std::size_t count) { return VkDeviceSize(count) * sizeof(T); }

}  // namespace

VkDeviceSize instanceUploadBytes(const SceneArrays& a) {
    if (a.instances.empty()) return 0;
    const std::size_t top = topNodeCount(a);
    return bytesOf<shader::Instance>(a.instances.size()) + (a.binaryNodesOnGpu ? bytesOf<shader::BvhPair>(top) : 0) +
           (a.stacklessNodes.empty() ? 0 : bytesOf<shader::StacklessNode>(top)) +
           bytesOf<shader::ObjectBox>(a.objectBoxes.size());
}

void recordInstanceUpload(VkCommandBuffer cmd, const SceneArrays& a, const GpuScene& scene, const gpu::Buffer& staging,
                          VkDeviceSize offset) {
    if (a.instances.empty()) return;
    StagedCopies copies(cmd, staging, offset);
    const std::size_t top = topNodeCount(a);
    std::memcpy(copies.add(scene.instances, 0, bytesOf<shader::Instance>(a.instances.size())), a.instances.data(),
                bytesOf<shader::Instance>(a.instances.size()));
    // Two-level scenes keep the binary records on the GPU (the wide tree is for flat scenes only).
    if (a.binaryNodesOnGpu) {
        auto* pairs = static_cast<shader::BvhPair*>(
            copies.add(scene.nodes, bytesOf<shader::BvhPair>(a.bottomNodeCount), bytesOf<shader::BvhPair>(top)));
        bvh::writeChildPairs(a.nodes, a.bottomNodeCount, std::span(pairs, top));
    }
    if (!a.stacklessNodes.empty()) {
        const VkDeviceSize bytes = bytesOf<shader::StacklessNode>(top);
        std::memcpy(copies.add(scene.stacklessNodes, bytesOf<shader::StacklessNode>(a.bottomNodeCount), bytes),
                    a.stacklessNodes.data() + a.bottomNodeCount, bytes);
    }
    if (!a.objectBoxes.empty()) {
        const VkDeviceSize bytes = bytesOf<shader::ObjectBox>(a.objectBoxes.size());
        std::memcpy(copies.add(scene.objectBoxes, 0, bytes), a.objectBoxes.data(), bytes);
    }
}

}  // namespace penumbra
