// Two-level BVHs: bottom levels (one per unique mesh, built once, in object space) and a top level
// over instances of them with affine transforms, rebuilt whenever an instance moves. Bottom and
// top levels share one node array with absolute indices (layout at shader::Instance), so each
// level is walked like the flat BVH; traversal moves the ray into an instance's space on the way
// down. The CPU reference traversal here is the oracle for the shader's (lib/bvh.glsl).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bvh/builder.h"
#include "bvh/morton_build.h"
#include "bvh/traverse_cpu.h"
#include "core/aabb.h"
#include "core/transform.h"
#include "shared/types.h"

namespace penumbra::bvh {

// objectToWorld must be invertible (Scene::validate checks instances). rootNode's
// PN_INSTANCE_IDENTITY flag is set here from the transform (a flag passed in is ignored).
shader::Instance makeInstance(const Affine& objectToWorld, std::uint32_t rootNode, std::uint32_t firstPrimitive,
                              std::uint32_t primitiveCount, std::uint32_t id);
// The bottom level's root (rootNode without its PN_INSTANCE_IDENTITY flag).
inline std::uint32_t instanceRoot(const shader::Instance& instance) { return instance.rootNode & ~PN_INSTANCE_IDENTITY; }
Affine objectToWorld(const shader::Instance& instance);
Affine worldToObject(const shader::Instance& instance);

// Appends a bottom level built over primitives that go to slots [primitiveBase, ...): its node
// indices become absolute (interior: + nodes.size(); leaves: + primitiveBase). Returns its root.
std::uint32_t appendBottomLevel(std::vector<shader::BvhNode>& nodes, const Bvh& bottom, std::uint32_t primitiveBase);

// The top level over instances with these world bounds, its node indices starting at nodeBase;
// each leaf holds one instance (firstOrRight = its index in instanceBounds, triCount = 1). Empty
// for no instances. Binned SAH up to kMortonTopLevelAbove instances, the Morton build above.
inline constexpr std::size_t kMortonTopLevelAbove = 2048;
std::vector<shader::BvhNode> buildTopLevel(std::span<const Aabb> instanceBounds, std::uint32_t nodeBase);

// What a per-frame top-level rebuild keeps between frames, so a warm rebuild allocates nothing.
struct TopLevelScratch {
    std::vector<Aabb> worldBounds;
    MortonScratch morton;
};

// The same top level appended to `nodes` (its root at the old nodes.size()).
void appendTopLevel(std::span<const Aabb> instanceBounds, std::vector<shader::BvhNode>& nodes,
                    TopLevelScratch& scratch, BuildThreads threads = BuildThreads::Pool);

// The per-frame rebuild: nodes from nodeBase on are replaced by the top level over `instances`,
// instance i's box being objectBounds[i] (its bottom level's, object space) through its
// objectToWorld. The root is nodeBase (when there are instances). Many instances are boxed and
// built on TBB's worker pool (kMortonParallelGrain), the same nodes to the bit as BuildThreads::One.
void replaceTopLevel(std::vector<shader::BvhNode>& nodes, std::uint32_t nodeBase,
                     std::span<const shader::Instance> instances, std::span<const Aabb> objectBounds,
                     TopLevelScratch& scratch, BuildThreads threads = BuildThreads::Pool);

// A two-level scene as the GPU sees it: every level's nodes, the primitive slots, the instances
// and the top level's root.
struct TwoLevelView {
    std::span<const shader::BvhNode> nodes;
    std::span<const shader::TriVerts> tris;
    std::span<const shader::Instance> instances;
    std::uint32_t topRoot = 0;
};

// Closest hit with t in (0, ray.tMax) over every instance (t is the world ray's: directions are
// transformed without normalising); Hit::instance names the instance hit.
Hit closestHit(const TwoLevelView& scene, const Ray& ray);
bool anyHit(const TwoLevelView& scene, const Ray& ray);
// Every primitive of every instance, in order; the oracle for the two above.
Hit closestHitBrute(const TwoLevelView& scene, const Ray& ray);

}  // namespace penumbra::bvh
