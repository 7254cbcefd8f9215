// Runs a test kernel (shaders/test/*.comp) over a scene: the scene uploaded, the frame uniforms
// filled for it as the renderers fill them, an input buffer at PN_BINDING_SCRATCH and an output
// buffer at PN_BINDING_SCRATCH2, one thread per item; the kernel specialised for `features`.
#pragma once

#include <cstring>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "gpu/commands.h"
#include "render/frame_uniforms.h"
#include "render/scene_pipeline.h"

namespace penumbra::test {

template <typename Out, typename In>
std::vector<Out> runSceneKernel(const gpu::Context& ctx, const Scene& scene, const SceneArrays& arrays,
                                const std::string& kernel, std::span<const In> input, std::size_t outCount,
                                shader::PassPush push, const RenderSettings& settings = {},
                                const std::function<void(shader::FrameUniforms&)>& editFrame = {},
                                KernelSpec spec = {}) {
    gpu::Commands commands(ctx);
    GpuScene gpuScene(ctx, commands, arrays);
    shader::FrameUniforms frame =
        makeSceneFrameUniforms(scene.camera, scene.background, scene.environment, settings, gpuScene);
    if (editFrame) editFrame(frame);
    gpu::Buffer frameBuffer(ctx, sizeof(frame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryKind::HostVisible);
    std::memcpy(frameBuffer.mapped(), &frame, sizeof(frame));
    gpu::Buffer in = gpu::uploadStorageBuffer<In>(ctx, commands, input);
    gpu::Buffer out(ctx, outCount * sizeof(Out), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                    gpu::MemoryKind::DeviceLocal);
    auto pipeline =
        makeScenePipeline(ctx, kernel, gpuScene, frameBuffer, {PN_BINDING_SCRATCH, PN_BINDING_SCRATCH2}, spec);
    pipeline->bind(PN_BINDING_SCRATCH, in);
    pipeline->bind(PN_BINDING_SCRATCH2, out);
    commands.run([&](VkCommandBuffer cmd) {
        pipeline->dispatch(cmd, static_cast<std::uint32_t>((push.itemCount + PN_LINEAR_GROUP - 1) / PN_LINEAR_GROUP), 1, 1,
                           &push);
        gpu::computeBarrier(cmd);
    });
    return gpu::downloadBuffer<Out>(ctx, commands, out, outCount);
}

}  // namespace penumbra::test
