// The scene as arrays in the GPU's layouts, on the host (render/gpu_scene.h builds and uploads
// them). Plain data: tools, tests and the two-level code (render/instance_arrays.h) use it without
// the upload.
#pragma once

#include <cstdint>
#include <vector>

#include "bvh/stats.h"
#include "bvh/two_level.h"
#include "core/aabb.h"
#include "render/env_table.h"
#include "shared/types.h"
#include "shared/accel_layouts.h"

namespace penumbra {

// The host-side arrays, kept separate from the upload so tests and tools can use them on the CPU.
struct SceneArrays {
    std::vector<shader::BvhNode> nodes;  // always on the host (picking, overlays, statistics)
    // The compressed wide BVH over the same primitive order (bvh/wide.h), built only for --accel
    // wide (buildSceneArrays' accel) and only for flat scenes: two-level scenes walk the binary tree.
    std::vector<shader::WideNode> wideNodes;
    // Whether `nodes` go to the GPU. The node buffer holds them (if so), then the wide nodes: with
    // the wide tree only its walk runs, so the binary nodes stay on the host (a third of the memory).
    bool binaryNodesOnGpu = true;
    // The other walks' records (render/walks.h buildWalkRecords), each only for its own --accel:
    // the binary nodes threaded with escape indices (stackless), and a box per object (objects).
    std::vector<shader::StacklessNode> stacklessNodes;
    std::vector<shader::ObjectBox> objectBoxes;
    std::vector<std::uint32_t> objectPrims;  // the flat scenes' objects' primitive slots
    // The walk these arrays were built for, which the kernels are specialised for (PN_ACCEL_*;
    // PN_WALK_ANY: every walk, chosen per ray by FrameUniforms.accel).
    std::uint32_t walk = PN_WALK_ANY;
    std::uint32_t wideDepth = 0;
    double wideMilliseconds = 0;  // collapsing the binary tree
    std::vector<shader::TriVerts> triVerts;      // leaf order; triangles and spheres (PN_TRI_SPHERE)
    std::vector<shader::TriAttribs> triAttribs;  // leaf order
    // Texture coordinates of the triangles that have any, at TriVerts::uvIndex; entry 0 is the
    // all-zero one the others share, so the array is never empty (bvh::appendTriUvs).
    std::vector<shader::TriUvs> triUvs = std::vector<shader::TriUvs>(1);
    std::vector<shader::Material> materials;
    // The unified light sampler's lights and light BVH (render/light_list.h).
    std::vector<shader::LightRef> lightRefs;
    std::vector<shader::LightNode> lightNodes;    // the top-level lights' bounds
    std::vector<shader::LightTreeNode> lightTree; // the light BVH (LightList::tree)
    // Its clusters' pick tables over the scene (render/light_grid.h); uploaded after the tree's
    // records in the same buffer. Empty: the shaders walk the tree's importance levels.
    std::vector<std::uint32_t> lightGrid;
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
    // The rest tree's root (render/rest_tree.h), among the nodes before the top level; PN_NO_HIT
    // for none. Frames walk it alone while every instance is at rest.
    std::uint32_t restRoot = PN_NO_HIT;
    std::uint32_t topRoot = 0;
    std::uint32_t uniqueMeshes = 0;     // bottom levels built for prototypes
    bvh::TopLevelScratch topLevelScratch;  // host only: reused by every top-level rebuild
    // Host only (never uploaded, so traversal stays lean): for each primitive in leaf order, the
    // scene object it came from, numbered as sceneObjectOf/objectPrimitive in picking.h.
    std::vector<std::uint32_t> primitiveObject;
    EnvTable env;  // empty without an environment map
    bvh::BvhStats stats{};
    double buildMilliseconds = 0;
    bool bvhFromCache = false;
    // --bvh-build gpu: the tree came from the GPU (false: the CPU's, also when the GPU's was too
    // deep), and the GPU's timestamps around its kernels (-1: none).
    bool bvhBuiltOnGpu = false;
    double gpuBuildMilliseconds = -1;  // read from the BVH cache (buildMilliseconds then times the read)
    double envBuildMilliseconds = 0;
};

}  // namespace penumbra
