// The scene as the GPU sees it: BVH nodes, hot and cold triangle arrays in leaf order,
// materials, the light alias table and the sphere-light table. Built on the CPU (BVH included), uploaded once.
#pragma once

#include <vector>

#include "bvh/builder.h"
#include "bvh/stats.h"
#include "gpu/buffer.h"
#include "gpu/commands.h"
#include "render/env_table.h"
#include "render/scene_arrays.h"
#include "render/settings.h"
#include "scene/scene.h"
#include "shared/types.h"

namespace penumbra {

class GpuBvhBuilder;

// The GPU form of one material (what buildSceneArrays stores in SceneArrays::materials).
shader::Material toGpuMaterial(const Material& m);

// Beer-Lambert coefficient per metre of a material's absorption colour and distance (0: clear).
Vec3 absorptionCoefficient(const Material& m);

// accel Wide also collapses a flat scene's BVH into the wide one (which renumbers the primitives)
// and leaves the binary nodes off the GPU; the viewer and the other walks pass Bvh or Brute.
// gpuBuilder: the flat world's tree is built on the GPU (--bvh-build gpu, render/gpu_bvh_build.h)
// instead of through bvh::buildCached; instances' bottom and top levels stay the CPU's.
SceneArrays buildSceneArrays(const Scene& scene, const bvh::BuildOptions& options = {}, Accel accel = Accel::Bvh,
                             const GpuBvhBuilder* gpuBuilder = nullptr);
// The boxes of the primitives the flat world's tree is built over, in the builders' order (what
// buildSceneArrays gives either builder): for comparing builds (bench and info --bvh-build gpu).
std::vector<Aabb> worldPrimitiveBounds(const Scene& scene);
// The same as a command asks for it: the tree built where `where` says, on ctx's GPU for Gpu.
SceneArrays buildSceneArrays(const gpu::Context& ctx, const Scene& scene, Accel accel, BvhBuild where);

// Bytes the arrays take once uploaded (what GpuScene::deviceBytes reports after the upload).
std::size_t deviceBytes(const SceneArrays& arrays);
// The part of them that is the binary walk's records (a BvhPair per node; 0 when the binary
// nodes stay on the host).
std::size_t binaryWalkBytes(const SceneArrays& arrays);

class GpuScene {
public:
    GpuScene(const gpu::Context& ctx, gpu::Commands& commands, const SceneArrays& arrays);

    gpu::Buffer nodes, triVerts, triAttribs, triUvs, materials, lightRefs, lightNodes, lightTree, textures, texels, punctual, sphereLights,
        envTable, envTexels, instances, stacklessNodes, objectBoxes, objectPrims;
    // The walk the scene's kernels are specialised for (SceneArrays::walk); a test may set it to
    // PN_WALK_ANY to pick the walk per ray with FrameUniforms.accel.
    std::uint32_t walk = PN_WALK_ANY;
    std::uint32_t instanceCount = 0, topRoot = 0;  // 0 instances: one flat BVH (FrameUniforms.instanceCount)
    std::uint32_t nodeCount = 0, wideNodeCount = 0, triCount = 0, lightNodeCount = 0, lightGridOffset = 0, topLightCount = 0, lightRefCount = 0, punctualCount = 0,
                  sphereCount = 0, sphereLightCount = 0, envWidth = 0, envHeight = 0;
    float envLuminance = 0;

    std::size_t deviceBytes() const;
};

}  // namespace penumbra
