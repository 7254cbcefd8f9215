// The host/shader layout check, both ways: the C++ offsets (static_asserts in types.h pin them
// at compile time) must equal the offsets glslc actually gave each member, read back from the
// embedded SPIR-V's OpMemberDecorate Offset decorations.
#include <gtest/gtest.h>

#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "gpu/shaders.h"
#include "shared/types.h"
#include "shared/accel_layouts.h"
#include "shared/lbvh.h"

namespace penumbra {
namespace {

using Offsets = std::map<std::string, std::map<std::uint32_t, std::uint32_t>>;  // struct -> member -> offset

Offsets readMemberOffsets(std::span<const std::uint32_t> spv) {
    constexpr std::uint32_t kOpName = 5, kOpMemberDecorate = 72, kDecorationOffset = 35;
    std::map<std::uint32_t, std::string> names;
    std::map<std::uint32_t, std::map<std::uint32_t, std::uint32_t>> byId;
    for (std::size_t i = 5; i < spv.size();) {
        std::uint32_t count = spv[i] >> 16, op = spv[i] & 0xffff;
        if (count == 0 || i + count > spv.size()) break;
        if (op == kOpName) names[spv[i + 1]] = reinterpret_cast<const char*>(&spv[i + 2]);
        if (op == kOpMemberDecorate && spv[i + 3] == kDecorationOffset) byId[spv[i + 1]][spv[i + 2]] = spv[i + 4];
        i += count;
    }
    Offsets out;
    for (auto& [id, members] : byId)
        if (names.count(id)) out[names[id]] = members;
    return out;
}

// The array stride glslc gave each runtime array of a named struct (a buffer's `T items[]`).
std::map<std::string, std::uint32_t> readArrayStrides(std::span<const std::uint32_t> spv) {
    constexpr std::uint32_t kOpName = 5, kOpTypeRuntimeArray = 29, kOpDecorate = 71, kDecorationArrayStride = 6;
    std::map<std::uint32_t, std::string> names;
    std::map<std::uint32_t, std::uint32_t> elementOf, strideOf;  // array id -> element id, stride
    for (std::size_t i = 5; i < spv.size();) {
        std::uint32_t count = spv[i] >> 16, op = spv[i] & 0xffff;
        if (count == 0 || i + count > spv.size()) break;
        if (op == kOpName) names[spv[i + 1]] = reinterpret_cast<const char*>(&spv[i + 2]);
        if (op == kOpTypeRuntimeArray) elementOf[spv[i + 1]] = spv[i + 2];
        if (op == kOpDecorate && count == 4 && spv[i + 2] == kDecorationArrayStride) strideOf[spv[i + 1]] = spv[i + 3];
        i += count;
    }
    std::map<std::string, std::uint32_t> out;
    for (auto [array, element] : elementOf)
        if (names.count(element) && strideOf.count(array)) out[names[element]] = strideOf[array];
    return out;
}

void expectMembers(const Offsets& spv, const std::string& name, const std::vector<std::uint32_t>& cpp) {
    auto it = spv.find(name);
    if (it == spv.end()) return;  // not used by this shader
    for (std::uint32_t m = 0; m < cpp.size(); ++m) {
        auto member = it->second.find(m);
        if (member != it->second.end()) {
            EXPECT_EQ(member->second, cpp[m]) << name << " member " << m << " differs between C++ and GLSL";
        }
    }
}

TEST(Layout, GlslOffsetsMatchCppOffsetsInEveryEmbeddedShader) {
    using namespace shader;
    int structsChecked = 0, envStructsChecked = 0;
    for (const char* shaderName :
         {"trace", "wave_start", "wave_args", "wave_shade", "wave_shadow", "raybench", "test_ray_query",
          "test_sphere_light_sample", "test_bsdf_sample", "test_env_sample"}) {
        Offsets spv = readMemberOffsets(gpu::shaderCode(shaderName));
        expectMembers(spv, "BvhNode", {0, offsetof(BvhNode, firstOrRight), offsetof(BvhNode, boundsMax), offsetof(BvhNode, triCount)});
        expectMembers(spv, "TriVerts", {0, offsetof(TriVerts, flags), offsetof(TriVerts, e1), 28, offsetof(TriVerts, e2), 44});
        expectMembers(spv, "TriAttribs", {0, offsetof(TriAttribs, lightIndex), offsetof(TriAttribs, area), offsetof(TriAttribs, n0),
                                          offsetof(TriAttribs, n1), offsetof(TriAttribs, n2)});
        expectMembers(spv, "TriUvs", {0, offsetof(TriUvs, uv1), offsetof(TriUvs, uv2)});
        expectMembers(spv, "Material", {0, offsetof(Material, flags), offsetof(Material, emission), offsetof(Material, alphaCutoff),
                                        offsetof(Material, absorption), offsetof(Material, ior), offsetof(Material, metallic),
                                        offsetof(Material, roughness), offsetof(Material, transmission),
                                        offsetof(Material, specular), offsetof(Material, albedoTexture),
                                        offsetof(Material, albedoWrap), offsetof(Material, metallicRoughnessTexture),
                                        offsetof(Material, metallicRoughnessWrap), offsetof(Material, normalTexture),
                                        offsetof(Material, normalWrap), offsetof(Material, emissionTexture),
                                        offsetof(Material, emissionWrap)});
        expectMembers(spv, "TextureInfo", {0, offsetof(TextureInfo, width), offsetof(TextureInfo, height), offsetof(TextureInfo, flags),
                                           offsetof(TextureInfo, frameCount), offsetof(TextureInfo, frame),
                                           offsetof(TextureInfo, secondsPerFrame), offsetof(TextureInfo, pad0)});
        expectMembers(spv, "LightRef", {0, offsetof(LightRef, index), offsetof(LightRef, trailLo), offsetof(LightRef, trailHi)});
        expectMembers(spv, "LightNode", {0, offsetof(LightNode, phi), offsetof(LightNode, boundsMax), offsetof(LightNode, cosThetaO),
                                         offsetof(LightNode, axis), offsetof(LightNode, cosThetaE), offsetof(LightNode, childOrLight),
                                         offsetof(LightNode, twoSided), offsetof(LightNode, sinThetaO), offsetof(LightNode, minDistance2)});
        expectMembers(spv, "LightTreeNode", {0, offsetof(LightTreeNode, radius), offsetof(LightTreeNode, axis),
                                             offsetof(LightTreeNode, phi), offsetof(LightTreeNode, cosThetaO),
                                             offsetof(LightTreeNode, sinThetaO), offsetof(LightTreeNode, cosThetaE),
                                             offsetof(LightTreeNode, childOrLight)});
        expectMembers(spv, "LightGridHeader", {0, offsetof(LightGridHeader, inverseCellSize), offsetof(LightGridHeader, cellsX),
                                               offsetof(LightGridHeader, cellsY), offsetof(LightGridHeader, cellsZ),
                                               offsetof(LightGridHeader, clusterCount), offsetof(LightGridHeader, levels),
                                               offsetof(LightGridHeader, firstTable), offsetof(LightGridHeader, firstMass),
                                               offsetof(LightGridHeader, firstTree), offsetof(LightGridHeader, pad)});
        expectMembers(spv, "FrameUniforms",
                      {0, offsetof(FrameUniforms, tanHalfFovY), offsetof(FrameUniforms, cameraRight), offsetof(FrameUniforms, aspect),
                       offsetof(FrameUniforms, cameraUp), offsetof(FrameUniforms, width), offsetof(FrameUniforms, cameraForward),
                       offsetof(FrameUniforms, height), offsetof(FrameUniforms, maxBounces), offsetof(FrameUniforms, rouletteStart),
                       offsetof(FrameUniforms, lightNodeCount), offsetof(FrameUniforms, triCount), offsetof(FrameUniforms, nodeCount),
                       offsetof(FrameUniforms, accel), offsetof(FrameUniforms, seed), offsetof(FrameUniforms, samplesPerPass),
                       offsetof(FrameUniforms, background), offsetof(FrameUniforms, punctualCount),
                       offsetof(FrameUniforms, lensRadius), offsetof(FrameUniforms, focusDistance),
                       offsetof(FrameUniforms, sphereLightCount),
                       offsetof(FrameUniforms, envWidth), offsetof(FrameUniforms, envIntensity),
                       offsetof(FrameUniforms, envRotation), offsetof(FrameUniforms, envHeight),
                       offsetof(FrameUniforms, misMode),
                       offsetof(FrameUniforms, instanceCount), offsetof(FrameUniforms, time),
                       offsetof(FrameUniforms, topLightCount), offsetof(FrameUniforms, envLuminance),
                       offsetof(FrameUniforms, lightRefCount), offsetof(FrameUniforms, lightPickUniform),
                       offsetof(FrameUniforms, topRoot), offsetof(FrameUniforms, lightGridOffset), offsetof(FrameUniforms, shadowRouletteShare),
                       offsetof(FrameUniforms, textureSaturation), offsetof(FrameUniforms, renderDistance),
                       offsetof(FrameUniforms, flags)});
        expectMembers(spv, "Instance", {0, offsetof(Instance, worldToObject), offsetof(Instance, rootNode),
                                        offsetof(Instance, firstPrimitive), offsetof(Instance, primitiveCount),
                                        offsetof(Instance, id)});
        expectMembers(spv, "PunctualLight", {0, offsetof(PunctualLight, type), offsetof(PunctualLight, intensity),
                                             offsetof(PunctualLight, range), offsetof(PunctualLight, direction),
                                             offsetof(PunctualLight, cosOuter), offsetof(PunctualLight, cosInner),
                                             offsetof(PunctualLight, pad2), offsetof(PunctualLight, coneOneMinusCos),
                                             offsetof(PunctualLight, pad1)});
        expectMembers(spv, "EnvAlias", {0, offsetof(EnvAlias, alias), offsetof(EnvAlias, pdf), offsetof(EnvAlias, pad)});
        expectMembers(spv, "SphereLight", {0, offsetof(SphereLight, radius), offsetof(SphereLight, radiance),
                                           offsetof(SphereLight, pad2), offsetof(SphereLight, spotDirection),
                                           offsetof(SphereLight, cosOuter), offsetof(SphereLight, cosInner),
                                           offsetof(SphereLight, pad3), offsetof(SphereLight, primitive),
                                           offsetof(SphereLight, pad0)});
        expectMembers(spv, "PassPush", {0, 4, 8, offsetof(PassPush, countRays), offsetof(PassPush, tileX),
                                        offsetof(PassPush, tileY), offsetof(PassPush, tileWidth), 28,
                                        offsetof(PassPush, waveStride), offsetof(PassPush, waveBounce), 40, 44});
        expectMembers(spv, "WaveControl", {0, offsetof(WaveControl, shadowCount), offsetof(WaveControl, shadowLive),
                                           offsetof(WaveControl, extendGroups), offsetof(WaveControl, shadowGroups)});
        expectMembers(spv, "RayCounters", {0, 4, offsetof(RayCounters, invalidSamples), offsetof(RayCounters, primitivesTested),
                                             offsetof(RayCounters, closestHits), offsetof(RayCounters, shadowBlocked), 24});
        expectMembers(spv, "RayDesc", {0, offsetof(RayDesc, tMax), offsetof(RayDesc, direction), 28});
        expectMembers(spv, "HitRecord", {0, offsetof(HitRecord, triangle), 8, offsetof(HitRecord, v)});
        expectMembers(spv, "SurfacePoint", {0, offsetof(SurfacePoint, valid), offsetof(SurfacePoint, normal), 28});
        expectMembers(spv, "BsdfTestQuery", {0, offsetof(BsdfTestQuery, entering), offsetof(BsdfTestQuery, wi), 28});
        expectMembers(spv, "BsdfTestResult", {0, offsetof(BsdfTestResult, pdf), offsetof(BsdfTestResult, value),
                                              offsetof(BsdfTestResult, isDelta)});
        for (const char* s : {"BvhNode", "TriVerts", "FrameUniforms", "Material", "BsdfTestQuery", "BsdfTestResult", "Instance"})
            structsChecked += int(spv.count(s));
        envStructsChecked += int(spv.count("EnvAlias"));
    }
    // The reflection must actually have found the structs, or this test proves nothing.
    EXPECT_GE(structsChecked, 12);
    EXPECT_EQ(readMemberOffsets(gpu::shaderCode("trace")).count("SphereLight"), 1u);
    EXPECT_EQ(readMemberOffsets(gpu::shaderCode("trace")).count("LightGridHeader"), 1u);
    EXPECT_GE(envStructsChecked, 2);  // the tracer and the environment test kernel
}

// The structs packed below 16 bytes of alignment (PN_STRUCT8/PN_STRUCT4) must still be arrays of
// exactly sizeof(T) in GLSL, or every element after the first would be read from the wrong place.
TEST(Layout, TriangleArraysHaveTheCppStride) {
    using namespace shader;
    const std::map<std::string, std::uint32_t> strides = readArrayStrides(gpu::shaderCode("trace"));
    const std::pair<const char*, std::size_t> expected[] = {
        {"TriVerts", sizeof(TriVerts)}, {"TriAttribs", sizeof(TriAttribs)}, {"TriUvs", sizeof(TriUvs)},
        // The header is read as element lightGridOffset / PN_LIGHT_GRID_PREFIXES of an array.
        {"LightGridHeader", 4 * PN_LIGHT_GRID_PREFIXES}};
    for (auto [name, size] : expected) {
        auto it = strides.find(name);
        ASSERT_NE(it, strides.end()) << name << " has no runtime array in the trace kernel";
        EXPECT_EQ(it->second, size) << name;
    }
}

// The stackless walk's and --accel objects' records (shared/accel_layouts.h), in the test kernel,
// which carries every walk (PN_WALK_ANY), and in the trace kernel: offsets and array strides.
TEST(Layout, WalkRecordsMatchInTheKernelsThatWalkThem) {
    using namespace shader;
    for (const char* shaderName : {"test_ray_query", "trace"}) {
        SCOPED_TRACE(shaderName);
        const std::span<const std::uint32_t> code = gpu::shaderCode(shaderName);
        const Offsets spv = readMemberOffsets(code);
        ASSERT_EQ(spv.count("StacklessNode"), 1u);
        ASSERT_EQ(spv.count("ObjectBox"), 1u);
        expectMembers(spv, "StacklessNode", {0, offsetof(StacklessNode, escape), offsetof(StacklessNode, boundsMax),
                                             offsetof(StacklessNode, leaf)});
        expectMembers(spv, "ObjectBox", {0, offsetof(ObjectBox, first), offsetof(ObjectBox, boundsMax), offsetof(ObjectBox, count),
                                         offsetof(ObjectBox, instance), offsetof(ObjectBox, listed), offsetof(ObjectBox, pad0),
                                         offsetof(ObjectBox, pad1)});
        const std::map<std::string, std::uint32_t> strides = readArrayStrides(code);
        EXPECT_EQ(strides.at("StacklessNode"), sizeof(StacklessNode));
        EXPECT_EQ(strides.at("ObjectBox"), sizeof(ObjectBox));
    }
}

TEST(Layout, ViewerStructsMatchInTheViewerShaders) {
    using namespace shader;
    std::map<std::string, int> found;
    for (const char* shaderName : {"gbuffer", "temporal", "atrous", "tonemap", "heatmap", "boxes"}) {
        Offsets spv = readMemberOffsets(gpu::shaderCode(shaderName));
        expectMembers(spv, "GBufferTexel", {0, offsetof(GBufferTexel, depth), offsetof(GBufferTexel, albedo),
                                            offsetof(GBufferTexel, surfaceId), offsetof(GBufferTexel, motion),
                                            offsetof(GBufferTexel, prevDepth), offsetof(GBufferTexel, flags)});
        expectMembers(spv, "HistoryTexel", {0, offsetof(HistoryTexel, samples), offsetof(HistoryTexel, moment1),
                                            offsetof(HistoryTexel, moment2), offsetof(HistoryTexel, meanVariance),
                                            offsetof(HistoryTexel, pad1)});
        expectMembers(spv, "ViewerUniforms",
                      {0, offsetof(ViewerUniforms, prevTanHalfFovY), offsetof(ViewerUniforms, prevCameraRight),
                       offsetof(ViewerUniforms, prevAspect), offsetof(ViewerUniforms, prevCameraUp),
                       offsetof(ViewerUniforms, historyValid), offsetof(ViewerUniforms, prevCameraForward),
                       offsetof(ViewerUniforms, cameraMoved), offsetof(ViewerUniforms, exposure),
                       offsetof(ViewerUniforms, toneMapper), offsetof(ViewerUniforms, debugMode),
                       offsetof(ViewerUniforms, samplesPerFrame), offsetof(ViewerUniforms, clampSigma),
                       offsetof(ViewerUniforms, depthTolerance), offsetof(ViewerUniforms, normalTolerance),
                       offsetof(ViewerUniforms, maxHistory), offsetof(ViewerUniforms, sigmaLuminance),
                       offsetof(ViewerUniforms, sigmaNormal), offsetof(ViewerUniforms, sigmaDepth),
                       offsetof(ViewerUniforms, heatMax), offsetof(ViewerUniforms, denoise),
                       offsetof(ViewerUniforms, debugOpacity), offsetof(ViewerUniforms, debugInset)});
        expectMembers(spv, "HeatCounters", {0, offsetof(HeatCounters, maxTris), offsetof(HeatCounters, maxLeafDepth),
                                            offsetof(HeatCounters, maxLeafTris)});
        expectMembers(spv, "FrameUniforms", {0, offsetof(FrameUniforms, tanHalfFovY), offsetof(FrameUniforms, cameraRight)});
        expectMembers(spv, "PassPush", {0, offsetof(PassPush, mode), offsetof(PassPush, itemCount), offsetof(PassPush, countRays)});
        expectMembers(spv, "BoxOverlayPush", {0, offsetof(BoxOverlayPush, lineWidth), offsetof(BoxOverlayPush, pad0),
                                              offsetof(BoxOverlayPush, pad1)});
        expectMembers(spv, "BvhNode", {0, offsetof(BvhNode, firstOrRight), offsetof(BvhNode, boundsMax),
                                       offsetof(BvhNode, triCount)});
        for (const auto& [name, members] : spv) found[name] += 1;
    }
    // Each viewer struct is used by at least one of these shaders; the check above saw it.
    for (const char* s : {"GBufferTexel", "HistoryTexel", "ViewerUniforms", "HeatCounters", "BoxOverlayPush"})
        EXPECT_GE(found[s], 1) << s << " not found in any viewer shader";
}

// The GPU BVH build's records (shared/lbvh.h) as its kernels see them.
TEST(Layout, GpuBvhBuildRecordsMatchInItsKernels) {
    using namespace shader;
    const Offsets emit = readMemberOffsets(gpu::shaderCode("lbvh_emit"));
    ASSERT_EQ(emit.count("LbvhNode"), 1u);
    ASSERT_EQ(emit.count("LbvhState"), 1u);
    ASSERT_EQ(emit.count("LbvhPush"), 1u);
    expectMembers(emit, "LbvhNode", {0, offsetof(LbvhNode, parent), offsetof(LbvhNode, boundsMax), offsetof(LbvhNode, left),
                                     offsetof(LbvhNode, right), offsetof(LbvhNode, first), offsetof(LbvhNode, leaves),
                                     offsetof(LbvhNode, emitNodes), offsetof(LbvhNode, cost), offsetof(LbvhNode, collapsed),
                                     offsetof(LbvhNode, pad0), offsetof(LbvhNode, pad1)});
    expectMembers(emit, "LbvhState", {0, offsetof(LbvhState, maxDepth), offsetof(LbvhState, centreMax),
                                      offsetof(LbvhState, emitted)});
    expectMembers(emit, "LbvhPush", {0, offsetof(LbvhPush, shift), offsetof(LbvhPush, blockCount), offsetof(LbvhPush, flip),
                                     offsetof(LbvhPush, traversalCost), offsetof(LbvhPush, intersectCost),
                                     offsetof(LbvhPush, maxLeaf), offsetof(LbvhPush, pass)});
    EXPECT_EQ(readArrayStrides(gpu::shaderCode("lbvh_emit")).at("LbvhNode"), sizeof(LbvhNode));
}

}  // namespace
}  // namespace penumbra
