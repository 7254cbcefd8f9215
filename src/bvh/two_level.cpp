#include "bvh/two_level.h"

#include "core/error.h"
#include "core/parallel.h"

namespace penumbra::bvh {
namespace {

Affine fromRows(const Vec4 rows[3]) {
    Affine a;
    for (int i = 0; i < 3; ++i) {
        a.m[i][0] = rows[i].x;
        a.m[i][1] = rows[i].y;
        a.m[i][2] = rows[i].z;
        a.m[i][3] = rows[i].w;
    }
    return a;
}

void toRows(const Affine& a, Vec4 rows[3]) {
    for (int i = 0; i < 3; ++i) rows[i] = Vec4{a.m[i][0], a.m[i][1], a.m[i][2], a.m[i][3]};
}

Ray toObject(const shader::Instance& instance, const Ray& ray) {
    const Affine w = worldToObject(instance);
    return Ray{w.point(ray.origin), w.vector(ray.direction), ray.tMax};
}

}  // namespace

shader::Instance makeInstance(const Affine& objectToWorld, std::uint32_t rootNode, std::uint32_t firstPrimitive,
                              std::uint32_t primitiveCount, std::uint32_t id) {
    shader::Instance out{};
    toRows(objectToWorld, out.objectToWorld);
    toRows(objectToWorld.inverse(), out.worldToObject);
    out.rootNode = rootNode & ~PN_INSTANCE_IDENTITY;
    const Affine identity;
    bool isIdentity = true;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) isIdentity = isIdentity && objectToWorld.m[i][j] == identity.m[i][j];
    if (isIdentity) out.rootNode |= PN_INSTANCE_IDENTITY;
    out.firstPrimitive = firstPrimitive;
    out.primitiveCount = primitiveCount;
    out.id = id;
    return out;
}

Affine objectToWorld(const shader::Instance& instance) { return fromRows(instance.objectToWorld); }
Affine worldToObject(const shader::Instance& instance) { return fromRows(instance.worldToObject); }

std::uint32_t appendBottomLevel(std::vector<shader::BvhNode>& nodes, const Bvh& bottom, std::uint32_t primitiveBase) {
    PN_CHECK(!bottom.nodes.empty());
    const auto base = static_cast<std::uint32_t>(nodes.size());
    for (shader::BvhNode n : bottom.nodes) {
        n.firstOrRight += n.triCount > 0 ? primitiveBase : base;
        nodes.push_back(n);
    }
    return base;
}

void appendTopLevel(std::span<const Aabb> instanceBounds, std::vector<shader::BvhNode>& nodes,
                    TopLevelScratch& scratch, BuildThreads threads) {
    if (instanceBounds.empty()) return;
    // Many instances: the Morton build, several times faster than binned SAH for a somewhat
    // worse tree, keeps a per-frame rebuild within budget (docs/PERFORMANCE.md "Top-level rebuild").
    if (instanceBounds.size() > kMortonTopLevelAbove) {
        appendMorton(instanceBounds, nodes, scratch.morton, threads);
        return;
    }
    BuildOptions options;
    options.maxLeafSize = 1;  // a leaf is one instance, so traversal enters it directly
    const Bvh top = build(instanceBounds, options);
    const auto base = static_cast<std::uint32_t>(nodes.size());
    for (shader::BvhNode n : top.nodes) {
        if (n.triCount > 0) {
            PN_CHECK(n.triCount == 1);
            n.firstOrRight = top.primOrder[n.firstOrRight];
        } else {
            n.firstOrRight += base;
        }
        nodes.push_back(n);
    }
}

std::vector<shader::BvhNode> buildTopLevel(std::span<const Aabb> instanceBounds, std::uint32_t nodeBase) {
    std::vector<shader::BvhNode> nodes;
    TopLevelScratch scratch;
    appendTopLevel(instanceBounds, nodes, scratch);
    for (shader::BvhNode& n : nodes)
        if (n.triCount == 0) n.firstOrRight += nodeBase;
    return nodes;
}

void replaceTopLevel(std::vector<shader::BvhNode>& nodes, std::uint32_t nodeBase,
                     std::span<const shader::Instance> instances, std::span<const Aabb> objectBounds,
                     TopLevelScratch& scratch, BuildThreads threads) {
    PN_CHECK(instances.size() == objectBounds.size() && nodeBase <= nodes.size());
    const std::size_t n = instances.size();
    scratch.worldBounds.resize(n);
    auto transformRange = [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i)
            scratch.worldBounds[i] = transformBounds(objectBounds[i], objectToWorld(instances[i]));
    };
    // Each box on its own, so chunks on the worker pool give the serial boxes.
    if (threads == BuildThreads::Pool && n >= 2 * kMortonParallelGrain)
        parallelFor(n, kMortonParallelGrain, transformRange);
    else
        transformRange(0, n);
    nodes.resize(nodeBase);
    appendTopLevel(scratch.worldBounds, nodes, scratch, threads);
}

Hit closestHit(const TwoLevelView& scene, const Ray& ray) {
    Hit hit;
    hit.t = ray.tMax;
    forEachLeaf(scene.nodes, scene.topRoot, ray, hit.t, [&](std::uint32_t first, std::uint32_t count) {
        PN_CHECK(count == 1 && first < scene.instances.size());
        const shader::Instance& instance = scene.instances[first];
        Ray local = toObject(instance, ray);
        local.tMax = hit.t;
        const Hit h = closestHitBelow(scene.nodes, scene.tris, instanceRoot(instance), local);
        if (h.triangle != PN_NO_HIT) {
            hit = h;
            hit.instance = first;
        }
        return false;
    });
    return hit;
}

bool anyHit(const TwoLevelView& scene, const Ray& ray) {
    bool found = false;
    const float tMax = ray.tMax;
    forEachLeaf(scene.nodes, scene.topRoot, ray, tMax, [&](std::uint32_t first, std::uint32_t count) {
        PN_CHECK(count == 1 && first < scene.instances.size());
        const shader::Instance& instance = scene.instances[first];
        return found = anyHitBelow(scene.nodes, scene.tris, instanceRoot(instance), toObject(instance, ray));
    });
    return found;
}

Hit closestHitBrute(const TwoLevelView& scene, const Ray& ray) {
    Hit hit;
    hit.t = ray.tMax;
    for (std::uint32_t k = 0; k < scene.instances.size(); ++k) {
        const shader::Instance& instance = scene.instances[k];
        PN_CHECK(std::uint64_t(instance.firstPrimitive) + instance.primitiveCount <= scene.tris.size());
        const Ray local = toObject(instance, ray);
        for (std::uint32_t i = instance.firstPrimitive; i < instance.firstPrimitive + instance.primitiveCount; ++i) {
            float t, u, v;
            if (intersectPrimitive(scene.tris[i], local, hit.t, t, u, v)) hit = {t, i, u, v, k};
        }
    }
    return hit;
}

}  // namespace penumbra::bvh
