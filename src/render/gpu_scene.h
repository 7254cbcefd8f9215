// The scene as the GPU sees it: BVH nodes, hot and cold triangle arrays in leaf order,
// materials, the light alias table and the sphere-light table. Built on the CPU (BVH included), uploaded once.
#pragma once

#include <vector>

#include "bvh/builder.h"
#include "bvh/stats.h"
#include "gpu/buffer.h"
#include "gpu/commands.h"
#include "render/env_table.h"
#include "scene/scene.h"
#include "shared/types.h"

namespace penumbra {

// The host-side arrays, kept separate from the upload so tests and tools can use them on the CPU.
struct SceneArrays {
    std::vector<shader::BvhNode> nodes;
    std::vector<shader::TriVerts> triVerts;      // leaf order; triangles and spheres (PN_TRI_SPHERE)
    std::vector<shader::TriAttribs> triAttribs;  // leaf order
    std::vector<shader::Material> materials;
    // The unified light sampler's lights and light BVH (render/light_list.h).
    std::vector<shader::LightRef> lightRefs;
    std::vector<shader::LightNode> lightNodes;
    std::uint32_t topLightCount = 0;
    float envLuminance = 0;  // mean luminance of the environment over directions (intensity 1)
    std::vector<shader::TextureInfo> textures;
    std::vector<std::uint32_t> texels;  // RGBA8, one texel per word
    std::vector<shader::PunctualLight> punctual;
    std::vector<shader::SphereLight> sphereLights;
    std::uint32_t sphereCount = 0;  // sphere slots among triVerts
    // Two levels (render/instance_arrays.h), only when the scene has instances: nodes holds the
    // world's flat BVH, then one bottom level per prototype, then (from topRoot) the top level.
    std::vector<shader::Instance> instances;
    std::vector<Aabb> instanceBounds;  // host only: each instance's bottom-level bounds, object space
    std::uint32_t bottomNodeCount = 0;  // nodes before the top level
    std::uint32_t topRoot = 0;
    std::uint32_t uniqueMeshes = 0;     // bottom levels built for prototypes
    // Host only (never uploaded, so traversal stays lean): for each primitive in leaf order, the
    // scene object it came from, numbered as sceneObjectOf/objectPrimitive in scene_objects.h.
    std::vector<std::uint32_t> primitiveObject;
    EnvTable env;  // empty without an environment map
    bvh::BvhStats stats{};
    double buildMilliseconds = 0;
    bool bvhFromCache = false;  // read from the BVH cache (buildMilliseconds then times the read)
    double envBuildMilliseconds = 0;
};

// The GPU form of one material (what buildSceneArrays stores in SceneArrays::materials).
shader::Material toGpuMaterial(const Material& m);

// Beer-Lambert coefficient per metre of a material's absorption colour and distance (0: clear).
Vec3 absorptionCoefficient(const Material& m);

SceneArrays buildSceneArrays(const Scene& scene, const bvh::BuildOptions& options = {});

// Bytes the arrays take once uploaded (what GpuScene::deviceBytes reports after the upload).
std::size_t deviceBytes(const SceneArrays& arrays);

class GpuScene {
public:
    GpuScene(const gpu::Context& ctx, gpu::Commands& commands, const SceneArrays& arrays);

    gpu::Buffer nodes, triVerts, triAttribs, materials, lightRefs, lightNodes, textures, texels, punctual, sphereLights,
        envTable, envTexels, instances;
    std::uint32_t instanceCount = 0, topRoot = 0;  // 0 instances: one flat BVH (FrameUniforms.instanceCount)
    std::uint32_t nodeCount = 0, triCount = 0, lightNodeCount = 0, topLightCount = 0, lightRefCount = 0, punctualCount = 0,
                  sphereCount = 0, sphereLightCount = 0, envWidth = 0, envHeight = 0;
    float envLuminance = 0;

    std::size_t deviceBytes() const;
};

}  // namespace penumbra
