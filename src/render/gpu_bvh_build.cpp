#include "render/gpu_bvh_build.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/log.h"
#include "gpu/buffer.h"
#include "gpu/commands.h"
#include "gpu/pipeline.h"
#include "gpu/timer.h"
#include "render/gpu_scene.h"
#include "shared/lbvh.h"

namespace penumbra {
namespace {

constexpr std::uint32_t kBindings = 10;  // PN_LBVH_BIND_BOXES .. PN_LBVH_BIND_DONE

// Every kernel gets the whole set (each declares the part it reads), so one binding list serves all.
std::array<gpu::BindingSpec, kBindings> bindingSpecs() {
    std::array<gpu::BindingSpec, kBindings> specs{};
    for (std::uint32_t b = 0; b < kBindings; ++b) specs[b] = {b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
    return specs;
}

gpu::ComputePipeline kernel(const gpu::Context& ctx, const char* name) {
    const auto specs = bindingSpecs();
    return gpu::ComputePipeline(ctx, name, specs, sizeof(shader::LbvhPush));
}

std::uint32_t groupsFor(std::uint64_t items, std::uint32_t groupSize) {
    return static_cast<std::uint32_t>((items + groupSize - 1) / groupSize);
}

// The build's buffers, in binding order, sized for n primitives (the boxes' is filled by the caller).
struct Buffers {
    std::array<gpu::Buffer, kBindings> all;
    Buffers(const gpu::Context& ctx, std::uint32_t count, std::uint32_t blocks) {
        const VkDeviceSize n = count;
        auto make = [&](VkDeviceSize bytes) {
            return gpu::Buffer(ctx, bytes,
                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                   VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                               gpu::MemoryKind::DeviceLocal);
        };
        all[PN_LBVH_BIND_BOXES] = make(n * sizeof(shader::BvhNode));
        all[PN_LBVH_BIND_STATE] = make(sizeof(shader::LbvhState));
        for (std::uint32_t b : {PN_LBVH_BIND_KEYS_A, PN_LBVH_BIND_VALUES_A, PN_LBVH_BIND_KEYS_B, PN_LBVH_BIND_VALUES_B})
            all[b] = make(n * sizeof(std::uint32_t));
        all[PN_LBVH_BIND_COUNTS] = make(VkDeviceSize(blocks) * PN_LBVH_RADIX * sizeof(std::uint32_t));
        all[PN_LBVH_BIND_NODES] = make((2 * n - 1) * sizeof(shader::LbvhNode));
        all[PN_LBVH_BIND_OUTPUT] = make((2 * n - 1) * sizeof(shader::BvhNode));
        all[PN_LBVH_BIND_DONE] = make((2 * n - 1) * sizeof(std::uint32_t));
    }
    const gpu::Buffer& operator[](std::uint32_t binding) const { return all[binding]; }
    void upload(const gpu::Context& ctx, gpu::Commands& commands, std::uint32_t binding, const void* data,
                VkDeviceSize bytes) {
        all[binding] = gpu::uploadStorageBuffer(ctx, commands, data, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    }
};

// A tree the GPU need not build: empty, or one leaf.
bvh::Bvh trivialTree(std::span<const Aabb> primBounds) {
    bvh::Bvh tree;
    if (primBounds.empty()) return tree;
    const Aabb box = bvh::sanitizedBounds(primBounds[0]);
    tree.nodes.push_back({box.lo, 0u, box.hi, 1u});
    tree.primOrder.push_back(0);
    return tree;
}

}  // namespace

struct GpuBvhBuilder::Kernels {
    gpu::ComputePipeline centres, morton, count, scan, scatter, hierarchy, leaves, bounds, emit;
    explicit Kernels(const gpu::Context& ctx)
        : centres(kernel(ctx, "lbvh_centres")), morton(kernel(ctx, "lbvh_morton")),
          count(kernel(ctx, "lbvh_radix_count")), scan(kernel(ctx, "lbvh_radix_scan")),
          scatter(kernel(ctx, "lbvh_radix_scatter")), hierarchy(kernel(ctx, "lbvh_hierarchy")),
          leaves(kernel(ctx, "lbvh_leaves")), bounds(kernel(ctx, "lbvh_bounds")), emit(kernel(ctx, "lbvh_emit")) {}

    void bindAll(const Buffers& buffers) {
        for (gpu::ComputePipeline* p : {&centres, &morton, &count, &scan, &scatter, &hierarchy, &leaves, &bounds, &emit})
            for (std::uint32_t b = 0; b < kBindings; ++b) p->bind(b, buffers[b]);
    }

    // The sort: PN_LBVH_RADIX_PASSES stable passes, ping-ponging between the A and B arrays.
    void recordSort(VkCommandBuffer cmd, shader::LbvhPush push) const {
        for (std::uint32_t pass = 0; pass < PN_LBVH_RADIX_PASSES; ++pass) {
            push.shift = pass * PN_LBVH_RADIX_BITS;
            push.flip = pass % 2;
            count.dispatch(cmd, push.blockCount, 1, 1, &push);
            gpu::computeBarrier(cmd);
            scan.dispatch(cmd, 1, 1, 1, &push);
            gpu::computeBarrier(cmd);
            scatter.dispatch(cmd, push.blockCount, 1, 1, &push);
            gpu::computeBarrier(cmd);
        }
    }

    // A level per pass: every interior node whose children finished in earlier passes finishes.
    void recordBounds(VkCommandBuffer cmd, shader::LbvhPush push) const {
        for (push.pass = 1; push.pass <= PN_LBVH_BOUNDS_PASSES; ++push.pass) {
            bounds.dispatch(cmd, groupsFor(push.count - 1, PN_LBVH_GROUP), 1, 1, &push);
            gpu::computeBarrier(cmd);
        }
    }

    void record(VkCommandBuffer cmd, const shader::LbvhPush& push) const {
        const std::uint32_t n = push.count;
        centres.dispatch(cmd, groupsFor(n, PN_LBVH_GROUP), 1, 1, &push);
        gpu::computeBarrier(cmd);
        morton.dispatch(cmd, groupsFor(n, PN_LBVH_GROUP), 1, 1, &push);
        gpu::computeBarrier(cmd);
        recordSort(cmd, push);
        hierarchy.dispatch(cmd, groupsFor(n - 1, PN_LBVH_GROUP), 1, 1, &push);
        gpu::computeBarrier(cmd);
        leaves.dispatch(cmd, groupsFor(n, PN_LBVH_GROUP), 1, 1, &push);
        gpu::computeBarrier(cmd);
        recordBounds(cmd, push);
        emit.dispatch(cmd, groupsFor(2ull * n - 1, PN_LBVH_GROUP), 1, 1, &push);
    }
};

GpuBvhBuilder::GpuBvhBuilder(const gpu::Context& ctx) : ctx_(ctx), kernels_(std::make_unique<Kernels>(ctx)) {}
GpuBvhBuilder::~GpuBvhBuilder() = default;

GpuBvhBuild GpuBvhBuilder::build(std::span<const Aabb> primBounds, const bvh::BuildOptions& options) const {
    if (primBounds.size() < 2) return {trivialTree(primBounds), 0.0, true};
    if (primBounds.size() >= PN_LBVH_NONE / 2) throw Error("too many primitives for the GPU BVH build");
    const auto n = static_cast<std::uint32_t>(primBounds.size());
    std::vector<shader::BvhNode> boxes(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const Aabb b = bvh::sanitizedBounds(primBounds[i]);
        boxes[i] = {b.lo, 0u, b.hi, 0u};
    }
    shader::LbvhPush push{};
    push.count = n;
    push.blockCount = groupsFor(n, PN_LBVH_GROUP);
    push.traversalCost = options.traversalCost;
    push.intersectCost = options.intersectCost;
    push.maxLeaf = static_cast<std::uint32_t>(std::clamp(options.maxLeafSize, 1, PN_LBVH_MAX_LEAF));

    gpu::Commands commands(ctx_);
    Buffers buffers(ctx_, n, push.blockCount);
    buffers.upload(ctx_, commands, PN_LBVH_BIND_BOXES, boxes.data(), boxes.size() * sizeof(boxes[0]));
    kernels_->bindAll(buffers);
    gpu::GpuTimer timer(ctx_, 1);
    if (timer.supported()) timer.reset();
    commands.run([&](VkCommandBuffer cmd) {
        const shader::LbvhState start{{~0u, ~0u, ~0u}, 0u, {0u, 0u, 0u}, 0u};
        vkCmdUpdateBuffer(cmd, buffers[PN_LBVH_BIND_STATE].get(), 0, sizeof(start), &start);
        gpu::computeBarrier(cmd);
        if (timer.supported()) timer.begin(cmd, 0);
        kernels_->record(cmd, push);
        if (timer.supported()) timer.end(cmd, 0);
    });

    GpuBvhBuild out;
    out.gpuMilliseconds = timer.supported() ? timer.milliseconds(0) : -1.0;
    const auto state = gpu::downloadBuffer<shader::LbvhState>(ctx_, commands, buffers[PN_LBVH_BIND_STATE], 1)[0];
    if (state.emitted == 0 || state.emitted > 2 * n - 1)
        throw Error("the GPU BVH build wrote " + std::to_string(state.emitted) + " nodes for " + std::to_string(n) +
                    " primitives");
    if (state.maxDepth > PN_BVH_MAX_DEPTH) {
        logWarning("the GPU-built BVH is " + std::to_string(state.maxDepth) + " levels deep (the walks allow " +
                   std::to_string(PN_BVH_MAX_DEPTH) + "); building it on the CPU instead");
        return {bvh::build(primBounds, options), out.gpuMilliseconds, false};
    }
    out.bvh.nodes = gpu::downloadBuffer<shader::BvhNode>(ctx_, commands, buffers[PN_LBVH_BIND_OUTPUT], state.emitted);
    out.bvh.primOrder = gpu::downloadBuffer<std::uint32_t>(ctx_, commands, buffers[PN_LBVH_BIND_VALUES_A], n);
    return out;
}

std::vector<std::uint32_t> GpuBvhBuilder::sortOrder(std::span<const std::uint32_t> keys) const {
    if (keys.empty()) return {};
    const auto n = static_cast<std::uint32_t>(keys.size());
    shader::LbvhPush push{};
    push.count = n;
    push.blockCount = groupsFor(n, PN_LBVH_GROUP);
    gpu::Commands commands(ctx_);
    Buffers buffers(ctx_, std::max(n, 2u), push.blockCount);
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    buffers.upload(ctx_, commands, PN_LBVH_BIND_KEYS_A, keys.data(), keys.size_bytes());
    buffers.upload(ctx_, commands, PN_LBVH_BIND_VALUES_A, order.data(), order.size() * sizeof(order[0]));
    kernels_->bindAll(buffers);
    commands.run([&](VkCommandBuffer cmd) { kernels_->recordSort(cmd, push); });
    return gpu::downloadBuffer<std::uint32_t>(ctx_, commands, buffers[PN_LBVH_BIND_VALUES_A], n);
}

SceneArrays buildSceneArrays(const gpu::Context& ctx, const Scene& scene, Accel accel, BvhBuild where) {
    if (where == BvhBuild::Cpu) return buildSceneArrays(scene, {}, accel);
    const GpuBvhBuilder builder(ctx);
    return buildSceneArrays(scene, {}, accel, &builder);
}

}  // namespace penumbra
