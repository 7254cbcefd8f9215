// A BVH built on the GPU (`--bvh-build gpu`): Morton codes, a radix sort, Karras 2012's hierarchy
// emitted in parallel, bounds and SAH collapse bottom-up, then the depth-first BvhNode array of
// bvh/builder.h (shaders/lbvh_*.comp; layouts in shaders/shared/lbvh.h). The tree is read back,
// so every walk (binary, wide, stackless, objects) is made from it exactly as from the CPU's.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "bvh/builder.h"
#include "core/aabb.h"
#include "gpu/context.h"

namespace penumbra {

struct GpuBvhBuild {
    bvh::Bvh bvh;
    double gpuMilliseconds = 0;  // GPU timestamps around the build's kernels (-1: no timestamps)
    bool onGpu = true;           // false: too deep for the walks, built on the CPU instead (a warning said so)
};

class GpuBvhBuilder {
public:
    explicit GpuBvhBuilder(const gpu::Context& ctx);
    ~GpuBvhBuilder();
    GpuBvhBuilder(const GpuBvhBuilder&) = delete;
    GpuBvhBuilder& operator=(const GpuBvhBuilder&) = delete;

    // Leaves of at most options.maxLeafSize (up to PN_LBVH_MAX_LEAF) primitives, chosen by the
    // SAH weights of `options`; primOrder and leaf ranges as build() gives them.
    GpuBvhBuild build(std::span<const Aabb> primBounds, const bvh::BuildOptions& options = {}) const;

    // The build's radix sort alone, for tests: the stable order of `keys` (indices, ties in input order).
    std::vector<std::uint32_t> sortOrder(std::span<const std::uint32_t> keys) const;

private:
    struct Kernels;
    const gpu::Context& ctx_;
    std::unique_ptr<Kernels> kernels_;
};

}  // namespace penumbra
