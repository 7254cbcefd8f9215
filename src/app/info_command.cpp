// penumbra info [SCENE]: Vulkan devices, which one would be chosen, limits; with a scene, its
// size and BVH statistics.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/info_ranks.h"
#include "app/render_ranks.h"
#include "render/bvh_build_compare.h"
#include "render/gpu_scene.h"
#include "render/light_grid.h"
#include "render/light_tree.h"
#include "scene/instances.h"
#include "render/walks.h"

namespace penumbra::app {
namespace {

struct InfoArgs {
    std::string scene;
    std::string map;
    std::string device;
    EnvironmentSpec env;
    WadOptions wad;
    std::string accel = "bvh";
    BvhBuild bvhBuild = BvhBuild::Cpu;
    bool mpi = false;
};

// --bvh-build gpu: the GPU's build time (its timestamps) and its tree's SAH cost beside the CPU's.
void printGpuBuild(const gpu::Context& ctx, const Scene& scene) {
    const BvhBuildComparison c = compareBvhBuilds(ctx, worldPrimitiveBounds(scene), 5);
    if (!c.onGpu) return;  // the warning said the CPU built it
    std::printf("  bvh built on the GPU in %.3f ms (%s, median of %d builds, GPU timestamps), SAH cost %.2f beside the "
                "CPU build's %.2f (%.2fx)\n",
                c.gpuMilliseconds, ctx.info().name.c_str(), c.repeats, c.gpuSahCost, c.cpuSahCost,
                c.cpuSahCost > 0 ? c.gpuSahCost / c.cpuSahCost : 0.0);
}

void printScene(const std::string& name, const std::string& map, const EnvironmentSpec& env, const WadOptions& wad,
                Accel accel, BvhBuild where) {
    const auto start = std::chrono::steady_clock::now();
    Scene scene = loadScene(name, map, {}, nullptr, env, wad);
    const double loadMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const std::size_t cpuBytes = sceneBytes(scene);
    const std::unique_ptr<gpu::Context> ctx = where == BvhBuild::Gpu ? openDevice("") : nullptr;
    SceneArrays arrays = ctx ? buildSceneArrays(*ctx, scene, accel, where) : buildSceneArrays(scene, {}, accel);
    const bvh::BvhStats& s = arrays.stats;
    const std::size_t tris = arrays.triVerts.size();
    const std::size_t gpuBytes = deviceBytes(arrays);
    const LightTreeDepth lightDepth = lightTreeDepth(arrays.lightTree);
    std::printf("scene %s: %zu triangles, %zu materials, %zu lights (%u sampled one by one, the rest in a light BVH "
                "of %zu nodes, leaves at depth %.1f on average, %u at most, root 1), loaded in %.0f ms\n",
                scene.name.c_str(), tris, scene.materials.size(), arrays.lightRefs.size(), arrays.topLightCount,
                arrays.lightTree.size(), lightDepth.mean, lightDepth.max, loadMs);
    if (!arrays.lightGrid.empty()) {
        const shader::LightGridHeader grid = lightGridHeader(arrays.lightGrid);
        std::printf("  light grid: %u clusters picked from %ux%ux%u cells x %u normal bins, %.1f MB\n", grid.clusterCount,
                    grid.cellsX, grid.cellsY, grid.cellsZ, PN_LIGHT_GRID_BINS, double(arrays.lightGrid.size()) * 4.0 / 1e6);
    }
    std::printf("  bvh: %zu nodes, %zu leaves, depth %zu, largest leaf %zu, SAH cost %.2f, %s in %.2f ms\n", s.nodes,
                s.leaves, s.maxDepth, s.maxLeafSize, s.sahCost,
                arrays.bvhFromCache    ? "read from the cache"
                : arrays.bvhBuiltOnGpu ? "built on the GPU (wall clock: kernels made, boxes sent, tree read back)"
                                       : "built",
                arrays.buildMilliseconds);
    if (ctx) printGpuBuild(*ctx, scene);
    if (!arrays.wideNodes.empty())
        std::printf("  wide bvh (--accel wide): %zu nodes of %zu bytes, depth %u, %.1f bytes per primitive, collapsed in "
                    "%.2f ms\n",
                    arrays.wideNodes.size(), sizeof(shader::WideNode), arrays.wideDepth,
                    tris ? double(arrays.wideNodes.size() * sizeof(shader::WideNode)) / double(tris) : 0.0,
                    arrays.wideMilliseconds);
    if (!arrays.stacklessNodes.empty())
        std::printf("  stackless (--accel stackless): %zu threaded nodes of %zu bytes, %.1f bytes per primitive (the "
                    "binary walk's records stay uploaded beside them)\n",
                    arrays.stacklessNodes.size(), sizeof(shader::StacklessNode),
                    tris ? double(arrays.stacklessNodes.size() * sizeof(shader::StacklessNode)) / double(tris) : 0.0);
    if (!arrays.objectBoxes.empty())
        std::printf("  objects (--accel objects): %zu boxes of %zu bytes%s\n", arrays.objectBoxes.size(),
                    sizeof(shader::ObjectBox), arrays.instances.empty() ? ", one per scene object"
                                                                : ", one per scene object of the world, one per moved instance");
    std::printf("  %zu textures, %zu punctual lights, %u spheres and %zu sprites (in the triangle count), %zu sphere lights\n",
                scene.textures.size(), arrays.punctual.size(), arrays.sphereCount, scene.sprites.size(),
                arrays.sphereLights.size());
    if (scene.environment.map)
        std::printf("  environment %s: %dx%d, intensity %g, rotation %g deg, sampling table built in %.2f ms%s\n",
                    scene.environment.map->name.c_str(), scene.environment.map->width, scene.environment.map->height,
                    double(scene.environment.intensity), double(scene.environment.rotationDegrees),
                    arrays.envBuildMilliseconds, scene.environment.sun ? ", plus a sun disk" : "");
    if (!scene.instances.empty()) {
        const auto placed = std::count_if(arrays.instances.begin(), arrays.instances.end(),
                                          [](const shader::Instance& i) { return i.id != PN_NO_HIT; });
        std::printf("  instances: %zu placing %zu triangles; %zu two-level over %u unique meshes (one bottom-level BVH "
                    "each; the bvh line above is the world's own level), top level of %zu nodes\n",
                    scene.instances.size(), instancedTriangleCount(scene), std::size_t(placed), arrays.uniqueMeshes,
                    arrays.nodes.size() - arrays.bottomNodeCount);
        if (std::size_t(placed) < scene.instances.size())
            std::printf("  %zu instances of emissive or empty meshes are baked into world meshes\n",
                        scene.instances.size() - std::size_t(placed));
    }
    std::printf("  cpu memory (scene model): %zu bytes (%.1f per triangle)\n", cpuBytes,
                tris ? double(cpuBytes) / double(tris) : 0.0);
    std::printf("  gpu memory (--accel %s): %zu bytes (%.1f per triangle)\n", accelName(accel), gpuBytes,
                tris ? double(gpuBytes) / double(tris) : 0.0);
    // The node array each walk reads, the hot triangle array (TriVerts) and the cold one.
    const double binaryBytes = double(binaryWalkBytes(arrays));
    const double wideBytes = double(arrays.wideNodes.size() * sizeof(shader::WideNode));
    const double hotBytes = double(arrays.triVerts.size() * sizeof(shader::TriVerts));
    const double coldBytes = double(arrays.triAttribs.size() * sizeof(shader::TriAttribs));
    const double uvBytes = double(arrays.triUvs.size() * sizeof(shader::TriUvs));
    if (tris)
        std::printf("  gpu memory per triangle: binary nodes %.1f, wide nodes %.1f, triangle positions %.1f, attributes "
                    "%.1f, texture coordinates %.1f (%zu triangles have any), the rest %.1f\n",
                    binaryBytes / double(tris), wideBytes / double(tris), hotBytes / double(tris),
                    coldBytes / double(tris), uvBytes / double(tris), arrays.triUvs.size() - 1,
                    (double(gpuBytes) - binaryBytes - wideBytes - hotBytes - coldBytes - uvBytes) / double(tris));
}

void runInfo(const InfoArgs& args) {
    const Accel accel = parseAccel(args.accel);  // a usage error before anything is printed
    if (std::unique_ptr<distributed::Comm> comm = startRanks(args.mpi)) {
        printRanksInfo(*comm, args.device);
        if (comm->primary() && !args.scene.empty()) printScene(args.scene, args.map, args.env, args.wad, accel, args.bvhBuild);
        return;
    }
    std::string error;
    std::vector<gpu::DeviceInfo> devices = gpu::Context::listDevices(&error);
    if (devices.empty()) std::printf("no Vulkan devices: %s\n", error.empty() ? "none found" : error.c_str());
    for (const gpu::DeviceInfo& d : devices) {
        std::printf("device %u: %s (%s), Vulkan %s, %s, %.1f GiB device-local%s%s\n", d.index, d.name.c_str(),
                    gpu::deviceTypeName(d.type), gpu::versionString(d.apiVersion).c_str(), d.driverInfo.c_str(),
                    double(d.deviceLocalBytes) / (1u << 30), d.suitable ? "" : ", unusable: ",
                    d.suitable ? "" : d.unsuitableWhy.c_str());
    }
    if (!devices.empty()) {
        auto ctx = openDevice(args.device);
        const VkPhysicalDeviceLimits& l = ctx->info().limits;
        std::printf("chosen: device %u, %s\n", ctx->info().index, ctx->info().name.c_str());
        std::printf("  max workgroup invocations %u, max storage buffer range %u bytes, timestamps %s (%.3f ns/tick)\n",
                    l.maxComputeWorkGroupInvocations, l.maxStorageBufferRange,
                    ctx->timestampsSupported() ? "yes" : "no", double(l.timestampPeriod));
    }
    if (!args.scene.empty()) printScene(args.scene, args.map, args.env, args.wad, accel, args.bvhBuild);
}

}  // namespace

void registerInfo(CLI::App& app, Action& action) {
    auto args = std::make_shared<InfoArgs>();
    CLI::App* cmd = app.add_subcommand("info", "list Vulkan devices and the one chosen; with a scene, its statistics");
    cmd->add_option("scene", args->scene, "built-in scene or scene file");
    cmd->add_option("--map", args->map, "level of a .wad file");
    addDeviceOption(*cmd, args->device);
    cmd->add_option("--accel", args->accel, "the walk whose GPU memory to report (builds its records): " + walkNameList());
    addBvhBuildOption(*cmd, args->bvhBuild);
    cmd->add_flag("--mpi", args->mpi, "list every rank's host and device (implied when started by mpirun)");
    addBvhCacheOption(*cmd);
    addEnvironmentOptions(*cmd, args->env);
    addWadOptions(*cmd, args->wad);
    cmd->callback([args, &action] { action = [args] { runInfo(*args); }; });
}

}  // namespace penumbra::app
