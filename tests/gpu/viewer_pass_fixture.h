// Shared set-up for tests of the viewer's image passes: host-visible per-pixel buffers the test
// fills and reads directly, frame and viewer uniforms for a small image, and a submit helper.
#pragma once

#include <cstring>
#include <functional>
#include <memory>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "render/frame_uniforms.h"
#include "shared/types.h"

namespace penumbra::test {

class ViewerPassTest : public GpuTest {
protected:
    void setUpImage(std::uint32_t w, std::uint32_t h, const Camera& cam = defaultCamera()) {
        width = w;
        height = h;
        commands = std::make_unique<gpu::Commands>(*ctx);
        frame = storage(sizeof(shader::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        viewer = storage(sizeof(shader::ViewerUniforms));
        setCamera(cam);
        viewerUniforms = {};
        setPreviousCamera(frameUniforms);  // a still camera unless a test moves it
        viewerUniforms.samplesPerFrame = 1;
        viewerUniforms.clampSigma = 0.0f;  // no clamping unless a test asks for it
        viewerUniforms.depthTolerance = 0.1f;
        viewerUniforms.normalTolerance = 0.9f;
        viewerUniforms.maxHistory = 1e9f;
        viewerUniforms.sigmaLuminance = 4.0f;
        viewerUniforms.sigmaNormal = 128.0f;
        viewerUniforms.sigmaDepth = 1.0f;
        writeViewer();
    }

    static Camera defaultCamera() {
        Camera c;
        c.position = {0, 0, 0};
        c.lookAt = {0, 0, 1};
        c.up = {0, 1, 0};
        c.fovYDegrees = 40;
        return c;
    }

    void setCamera(const Camera& cam) {
        RenderSettings s;
        s.width = width;
        s.height = height;
        frameUniforms = makeFrameUniforms(cam, Vec3{0}, s, 0, 0, 0);
        std::memcpy(frame.mapped(), &frameUniforms, sizeof(frameUniforms));
    }
    // The previous camera, as the viewer passes it: the frame uniforms of that camera.
    void setPreviousCamera(const shader::FrameUniforms& prev) { penumbra::setPreviousCamera(viewerUniforms, prev); }
    void writeViewer() { std::memcpy(viewer.mapped(), &viewerUniforms, sizeof(viewerUniforms)); }

    gpu::Buffer storage(VkDeviceSize bytes, VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {
        gpu::Buffer b(*ctx, bytes, usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                      gpu::MemoryKind::HostVisible);
        std::memset(b.mapped(), 0, bytes);
        return b;
    }
    template <typename T>
    gpu::Buffer pixels() { return storage(VkDeviceSize(width) * height * sizeof(T)); }
    // A buffer of `bytes` per pixel (a layout named by a size in shared/types.h, like the guide).
    gpu::Buffer pixelBytes(VkDeviceSize bytes) { return storage(VkDeviceSize(width) * height * bytes); }
    template <typename T>
    static T* view(const gpu::Buffer& b) { return static_cast<T*>(b.mapped()); }

    void submit(const std::function<void(VkCommandBuffer)>& record) {
        commands->run([&](VkCommandBuffer cmd) {
            gpu::computeBarrier(cmd);
            record(cmd);
            gpu::computeBarrier(cmd);
        });
    }

    std::uint32_t width = 0, height = 0;
    std::unique_ptr<gpu::Commands> commands;
    gpu::Buffer frame, viewer;
    shader::FrameUniforms frameUniforms{};
    shader::ViewerUniforms viewerUniforms{};
};

inline shader::GBufferTexel surfaceTexel(float depth, Vec3 normal = {0, 0, -1}, Vec3 albedo = Vec3{0.5f},
                                         std::uint32_t id = 1) {
    shader::GBufferTexel g{};
    g.normal = normal;
    g.depth = depth;
    g.prevDepth = depth;  // a still point: as deep in the previous camera (motion vectors zero)
    g.albedo = albedo;
    g.surfaceId = id;
    return g;
}

}  // namespace penumbra::test
