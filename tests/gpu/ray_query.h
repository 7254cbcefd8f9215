// Traces a batch of rays with the real traversal shader (shaders/test/ray_query.comp): closest
// hit and any-hit per ray, for comparison with the CPU reference.
#pragma once

#include <cstring>
#include <optional>
#include <vector>

#include "gpu/commands.h"
#include "render/frame_uniforms.h"
#include "render/scene_pipeline.h"
#include "render/walks.h"

namespace penumbra::test {

struct GpuHits {
    std::vector<shader::HitRecord> closest;
    std::vector<bool> occluded;
};

// spec: the kernel's specialisation (PN_OPTION_CULL_BACKFACES among its options to cull back faces).
inline GpuHits traceOnGpu(const gpu::Context& ctx, const SceneArrays& arrays, const std::vector<shader::RayDesc>& rays,
                          Accel accel, KernelSpec spec = {}) {
    gpu::Commands commands(ctx);
    // Arrays built for --accel wide keep the binary nodes on the host; the other walks need them
    // uploaded (before the wide ones, which the wide walk then finds after them).
    std::optional<SceneArrays> withBinary;
    if (accel != Accel::Wide && !arrays.binaryNodesOnGpu) {
        withBinary = arrays;
        withBinary->binaryNodesOnGpu = true;
    }
    // The stackless and per-object walks need their records, built only for their --accel.
    const bool needsRecords = (accel == Accel::Stackless && arrays.stacklessNodes.empty() && !arrays.nodes.empty()) ||
                              (accel == Accel::Objects && arrays.objectBoxes.empty() && !arrays.triVerts.empty());
    if (needsRecords) {
        if (!withBinary) withBinary = arrays;
        buildWalkRecords(*withBinary, accel);
    }
    GpuScene scene(ctx, commands, withBinary ? *withBinary : arrays);
    // The kernel specialised for this walk, as a render made with it would be.
    scene.walk = accel == Accel::Wide && scene.wideNodeCount == 0 ? PN_ACCEL_BVH : walkInfo(accel).shaderId;
    RenderSettings settings;
    settings.accel = accel;
    shader::FrameUniforms frame = makeFrameUniforms(Camera{}, Vec3{0}, settings, scene.lightNodeCount, scene.triCount, scene.nodeCount);
    frame.instanceCount = scene.instanceCount;  // two-level scenes (0: the flat BVH)
    frame.topRoot = scene.topRoot;
    if (frame.accel == PN_ACCEL_WIDE && scene.wideNodeCount == 0) frame.accel = PN_ACCEL_BVH;  // as the renderer does
    gpu::Buffer frameBuffer(ctx, sizeof(frame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryKind::HostVisible);
    std::memcpy(frameBuffer.mapped(), &frame, sizeof(frame));
    gpu::Buffer rayBuffer = gpu::uploadStorageBuffer<shader::RayDesc>(ctx, commands, rays);
    gpu::Buffer hitBuffer(ctx, rays.size() * 2 * sizeof(shader::HitRecord),
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryKind::DeviceLocal);
    auto pipeline = makeScenePipeline(ctx, "test_ray_query", scene, frameBuffer, {PN_BINDING_SCRATCH, PN_BINDING_SCRATCH2},
                                      spec);
    pipeline->bind(PN_BINDING_SCRATCH, rayBuffer);
    pipeline->bind(PN_BINDING_SCRATCH2, hitBuffer);
    shader::PassPush push{0, 0, static_cast<std::uint32_t>(rays.size()), 0};
    commands.run([&](VkCommandBuffer cmd) {
        pipeline->dispatch(cmd, static_cast<std::uint32_t>((rays.size() + PN_LINEAR_GROUP - 1) / PN_LINEAR_GROUP), 1, 1, &push);
        gpu::computeBarrier(cmd);
    });
    auto records = gpu::downloadBuffer<shader::HitRecord>(ctx, commands, hitBuffer, rays.size() * 2);
    GpuHits out;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        out.closest.push_back(records[2 * i]);
        out.occluded.push_back(records[2 * i + 1].triangle != 0);
    }
    return out;
}

}  // namespace penumbra::test
