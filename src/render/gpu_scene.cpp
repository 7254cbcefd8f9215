#include "render/gpu_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <optional>
#include <span>

#include "bvh/cache.h"
#include "bvh/child_pairs.h"
#include "bvh/sphere.h"
#include "bvh/sprite.h"
#include "bvh/triangle.h"
#include "bvh/wide.h"
#include "core/error.h"
#include "render/env_table.h"
#include "render/gpu_bvh_build.h"
#include "render/instance_arrays.h"
#include "render/light_grid.h"
#include "render/light_list.h"
#include "render/scene_limits.h"
#include "render/sphere_lights.h"
#include "render/tuning.h"
#include "render/walks.h"
#include "scene/environment.h"
#include "scene/objects.h"
#include "scene/instances.h"
#include "shared/constants.h"

namespace penumbra {

Vec3 absorptionCoefficient(const Material& m) {
    if (!(m.absorptionDistance > 0) || !std::isfinite(m.absorptionDistance)) return Vec3{0.0f};
    Vec3 sigma;
    // A colour of 0 would be an infinite coefficient; 1e-4 of the light left is as dark as it needs to be.
    for (int k = 0; k < 3; ++k) sigma[k] = -std::log(std::clamp(m.absorptionColor[k], 1e-4f, 1.0f)) / m.absorptionDistance;
    return sigma;
}

namespace {

std::uint32_t wrapCode(Wrap w) {
    switch (w) {
        case Wrap::ClampToEdge: return PN_WRAP_CLAMP;
        case Wrap::MirroredRepeat: return PN_WRAP_MIRROR;
        default: return PN_WRAP_REPEAT;
    }
}

void packTexture(const TextureRef& ref, std::uint32_t& index, std::uint32_t& wrap) {
    index = ref.present() ? std::uint32_t(ref.texture) : PN_NO_TEXTURE;
    wrap = wrapCode(ref.wrapU) | (wrapCode(ref.wrapV) << 8) | (ref.filter == Filter::Nearest ? PN_SAMPLER_NEAREST : 0u);
}

// A sprite's slot (layout at PN_TRI_SPRITE in shared/types.h).
shader::TriVerts toSpriteVerts(const Sprite& s) {
    shader::TriVerts out{};
    out.v0 = s.position;
    out.flags = PN_TRI_SPRITE;
    out.e1 = Vec3{s.left, s.right, s.bottom};
    // The facing as Doom measures angles: counter-clockwise (seen from above) from +x toward -z.
    out.e2 = Vec3{s.top, std::atan2(-s.facing.z, s.facing.x), float(s.rotations)};
    return out;
}

}  // namespace

shader::Material toGpuMaterial(const Material& m) {
    shader::Material gm{};
    gm.albedo = m.albedo;
    gm.emission = m.emission;
    gm.flags = m.isEmissive() ? PN_MATERIAL_EMISSIVE : 0u;
    if (!m.twoSided) gm.flags |= PN_MATERIAL_ONE_SIDED;
    if (m.skyPortal) gm.flags |= PN_MATERIAL_SKY_PORTAL;
    if (m.emissionHiddenFromCamera) gm.flags |= PN_MATERIAL_HIDDEN_EMISSION;
    gm.alphaCutoff = m.alphaCutoff;
    if (m.alphaCutoff > 0 && m.albedoTexture.present()) gm.flags |= PN_MATERIAL_ALPHA_TESTED;
    gm.metallic = std::clamp(m.metallic, 0.0f, 1.0f);
    gm.roughness = std::clamp(m.roughness, 0.0f, 1.0f);
    gm.ior = std::max(m.ior, 1.0f);
    gm.transmission = std::clamp(m.transmission, 0.0f, 1.0f);
    gm.specular = std::clamp(m.specular, 0.0f, 1.0f);
    gm.absorption = absorptionCoefficient(m);
    packTexture(m.albedoTexture, gm.albedoTexture, gm.albedoWrap);
    packTexture(m.metallicRoughnessTexture, gm.metallicRoughnessTexture, gm.metallicRoughnessWrap);
    packTexture(m.normalTexture, gm.normalTexture, gm.normalWrap);
    packTexture(m.emissionTexture, gm.emissionTexture, gm.emissionWrap);
    return gm;
}

namespace {

std::size_t binaryNodesUploaded(const SceneArrays& a) { return a.binaryNodesOnGpu ? a.nodes.size() : 0; }

// The node buffer: the binary walk's records (bvh/child_pairs.h; unless the binary nodes stay on
// the host), then the wide nodes (lib/wide_bvh.glsl finds them at uvec4 nodeCount * 4, nodeCount
// being the binary records uploaded). A WideNode is 80 bytes, 1.25 records; the tail is padded.
std::vector<shader::BvhPair> nodeBufferContents(const SceneArrays& a) {
    const std::size_t binary = binaryNodesUploaded(a);
    const std::size_t wideBytes = a.wideNodes.size() * sizeof(shader::WideNode);
    std::vector<shader::BvhPair> out(binary + (wideBytes + sizeof(shader::BvhPair) - 1) / sizeof(shader::BvhPair));
    bvh::writeChildPairs(a.nodes, 0, std::span(out).first(binary));
    if (wideBytes > 0) std::memcpy(reinterpret_cast<char*>(out.data() + binary), a.wideNodes.data(), wideBytes);
    return out;
}

// Converts the scene's punctual lights (those without power are left out); moves[i] says whether
// out[i] moves every frame.
void addPunctualLights(const Scene& scene, std::vector<shader::PunctualLight>& out, std::vector<bool>& moves) {
    // The environment's sun first, so the scene's own last light (the viewer's torch) stays last.
    std::vector<Light> lights = distantLights(scene.environment);
    lights.insert(lights.end(), scene.lights.begin(), scene.lights.end());
    for (const Light& l : lights) {
        if (isSphereLight(l)) continue;  // in the sphere-light table instead
        shader::PunctualLight p{};
        p.position = l.position;
        p.intensity = l.color * l.intensity;
        p.range = l.range;
        p.direction = normalize(l.direction);
        p.type = l.type == LightType::Point ? PN_LIGHT_POINT : (l.type == LightType::Spot ? PN_LIGHT_SPOT : PN_LIGHT_DIRECTIONAL);
        p.cosOuter = std::cos(l.outerConeRadians);
        p.cosInner = std::cos(l.innerConeRadians);
        // 1 - cos, written so that a tiny radius (the sun's 0.0047 rad) keeps its precision.
        const double halfSin = std::sin(0.5 * double(l.angularRadius));
        if (l.type == LightType::Directional) p.coneOneMinusCos = float(2 * halfSin * halfSin);
        if (!(luminance(p.intensity) > 0) || !isFinite(p.position) || !isFinite(p.intensity)) continue;
        out.push_back(p);
        moves.push_back(l.moves);
    }
}

// Mean luminance of the environment over the sphere of directions (intensity 1): the map's,
// weighted by each texel's solid angle, or the constant background's.
float environmentLuminance(const Scene& scene) {
    if (!scene.environment.map) return luminance(scene.background);
    const EnvironmentMap& map = *scene.environment.map;
    double sum = 0;
    for (int y = 0; y < map.height; ++y) {
        const double solidAngle = envTexelSolidAngle(std::uint32_t(y), std::uint32_t(map.width), std::uint32_t(map.height));
        for (int x = 0; x < map.width; ++x) sum += luminance(map.radiance[std::size_t(y) * map.width + x]) * solidAngle;
    }
    return float(sum / (4 * kPi));
}

// Every light, for the unified sampler; sets TriAttribs::lightIndex of emissive primitives.
void addLightList(const Scene& scene, std::span<const EmissiveTriangle> emissive,
                  const std::vector<bool>& punctualMoves, SceneArrays& out) {
    LightListInput in;
    in.triangles.assign(emissive.begin(), emissive.end());
    in.spheres = out.sphereLights;
    in.punctual = out.punctual;
    in.punctualMoves = punctualMoves;
    out.envLuminance = environmentLuminance(scene);
    in.environment = scene.environment.sampled && scene.environment.intensity > 0 && out.envLuminance > 0;
    LightList list = buildLightList(in);
    for (shader::TriAttribs& a : out.triAttribs) a.lightIndex = PN_NO_LIGHT;
    for (auto [slot, ref] : list.primitiveLights) out.triAttribs[slot].lightIndex = ref;
    out.lightRefs = std::move(list.refs);
    out.lightNodes = std::move(list.nodes);
    out.lightTree = std::move(list.tree);
    out.topLightCount = list.topCount;
}

// The light grid over where shading points lie (the world's BVH, or its top level), unless the
// tuning leaves it out (the plain walk, for measurements) or sets its options.
void addLightGrid(SceneArrays& out) {
    if (!renderTuning().lightGrid || out.nodes.empty()) return;
    const LightGridOptions& options = renderTuning().lightGridOptions;
    const shader::BvhNode& root = out.nodes[out.instances.empty() ? 0 : out.topRoot];
    Aabb bounds;
    bounds.grow(root.boundsMin);
    bounds.grow(root.boundsMax);
    out.lightGrid = buildLightGrid(out.lightTree, bounds, options);
}

// The light grid's first word in the light tree's buffer (0: no grid): after the tree's records,
// rounded up to a whole LightGridHeader so that the shaders read the header as one
// (shared/lights.h).
std::uint32_t lightGridWord(const SceneArrays& a) {
    if (a.lightGrid.empty()) return 0;
    const std::size_t treeWords = a.lightTree.size() * (sizeof(shader::LightTreeNode) / 4);
    return static_cast<std::uint32_t>((treeWords + PN_LIGHT_GRID_PREFIXES - 1) / PN_LIGHT_GRID_PREFIXES * PN_LIGHT_GRID_PREFIXES);
}

// The light tree's buffer: its records, then the light grid's words.
std::vector<std::uint32_t> lightTreeBufferContents(const SceneArrays& a) {
    std::vector<std::uint32_t> words(a.lightTree.size() * (sizeof(shader::LightTreeNode) / 4));
    if (!a.lightTree.empty()) std::memcpy(words.data(), a.lightTree.data(), a.lightTree.size() * sizeof(shader::LightTreeNode));
    if (!a.lightGrid.empty()) words.resize(lightGridWord(a), 0u);
    words.insert(words.end(), a.lightGrid.begin(), a.lightGrid.end());
    return words;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The scene the arrays are built from, when it is not the input itself. Emitters stay world-space
// triangles in the light BVH, so instances of emissive meshes are baked into the world (keptFrom:
// the input's number of each instance left); PENUMBRA_FORCE_INSTANCES=1 instead makes the world's
// meshes one instance (RenderTuning::forceInstances), to measure the two-level traversal on any scene.
std::optional<Scene> sceneToBuild(const Scene& input, std::vector<std::uint32_t>& keptFrom) {
    std::optional<Scene> baked;
    if (renderTuning().forceInstances) {
        baked = input;
        instanceWorldMeshes(*baked);
        bakeEmissiveInstances(*baked);
    } else if (std::any_of(input.instances.begin(), input.instances.end(), [&](const Instance& i) {
                   return prototypeIsEmissive(input, input.prototypes[i.prototype]);
               })) {
        baked = input;
        bakeEmissiveInstances(*baked, &keptFrom);
    }
    return baked;
}

// The primitives in the numbering the builder sees: the triangles, then the spheres, then the
// sprites.
struct Primitives {
    std::vector<SceneTriangle> tris;
    std::vector<bvh::Triangle> geometry;  // tris' corners
    RenderSpheres spheres;
    std::vector<Material> materials;  // the scene's, then the spheres' extra ones
    std::size_t firstSprite = 0, count = 0;
};

Primitives gatherPrimitives(const Scene& scene) {
    Primitives p;
    p.tris = flattenTriangles(scene);
    p.spheres = renderSpheres(scene);
    p.materials = scene.materials;
    p.materials.insert(p.materials.end(), p.spheres.extraMaterials.begin(), p.spheres.extraMaterials.end());
    p.firstSprite = p.tris.size() + p.spheres.spheres.size();
    p.count = p.firstSprite + scene.sprites.size();
    if (p.count >= PN_NO_HIT) throw Error("scene '" + scene.name + "' has too many triangles");
    p.geometry.resize(p.tris.size());
    for (std::size_t i = 0; i < p.tris.size(); ++i) p.geometry[i] = {p.tris[i].p[0], p.tris[i].p[1], p.tris[i].p[2]};
    return p;
}

// The spheres' boxes, then the sprites': the primitives after the triangles.
std::vector<Aabb> extraPrimitiveBounds(const Scene& scene, const Primitives& prims) {
    std::vector<Aabb> extraBounds;
    extraBounds.reserve(prims.spheres.spheres.size() + scene.sprites.size());
    for (const Sphere& s : prims.spheres.spheres) extraBounds.push_back(bvh::sphereBounds(s.center, s.radius));
    for (const Sprite& s : scene.sprites) extraBounds.push_back(spriteBounds(s));
    return extraBounds;
}

// Every primitive's box in the order the builders number them: triangles, then the extra boxes.
std::vector<Aabb> primitiveBounds(std::span<const bvh::Triangle> tris, std::span<const Aabb> extra) {
    std::vector<Aabb> boxes;
    boxes.reserve(tris.size() + extra.size());
    for (const bvh::Triangle& t : tris) boxes.push_back(bvh::bounds(t));
    boxes.insert(boxes.end(), extra.begin(), extra.end());
    return boxes;
}

// Builds the BVH (through the BVH cache, which the command line turns on: bvh/cache.h), the wide
// tree when asked for, and the statistics, into out; returns the primitive of each leaf slot.
std::vector<std::uint32_t> buildTree(const Scene& scene, const Primitives& prims, const bvh::BuildOptions& options,
                                     Accel accel, const GpuBvhBuilder* gpuBuilder, SceneArrays& out) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Aabb> extraBounds = extraPrimitiveBounds(scene, prims);
    bvh::Bvh tree;
    if (gpuBuilder) {
        GpuBvhBuild built = gpuBuilder->build(primitiveBounds(prims.geometry, extraBounds), options);
        tree = std::move(built.bvh);
        out.bvhBuiltOnGpu = built.onGpu;
        out.gpuBuildMilliseconds = built.gpuMilliseconds;
    } else {
        bvh::CachedBuild built = bvh::buildCached(prims.geometry, extraBounds, options);
        tree = std::move(built.bvh);
        out.bvhFromCache = built.fromCache;
    }
    out.buildMilliseconds = millisecondsSince(start);
    if (accel == Accel::Wide && scene.instances.empty()) {
        // The wide tree reorders the primitives, so it comes before anything indexes them.
        const auto wideStart = std::chrono::steady_clock::now();
        bvh::WideBvh wide = bvh::collapseToWide(tree);
        out.wideNodes = std::move(wide.nodes);
        out.wideDepth = wide.maxDepth;
        out.wideMilliseconds = millisecondsSince(wideStart);
        out.binaryNodesOnGpu = out.wideNodes.empty();  // an empty scene's walk is the binary one
    }
    out.stats = bvh::computeStats(tree, options);
    out.nodes = std::move(tree.nodes);
    return std::move(tree.primOrder);
}

// The luminance of a sampled emissive triangle's material: the light tree's power estimate.
// Emission textures scale the light by their mean (over an animation's frames, computed once per
// texture); a sky portal passes on the environment's mean from above.
class EmitterLuminance {
public:
    explicit EmitterLuminance(const Scene& scene)
        : scene_(scene),
          textureMeans_(scene.textures.size(), -1.0f),
          skyPortal_(skyPortalRadiance(scene.environment, scene.background)) {}

    float operator()(const Material& m) {
        if (m.skyPortal) return luminance(skyPortal_ + m.emission);
        float texture = 1.0f;
        if (m.emissionTexture.present()) {
            float& mean = textureMeans_[std::size_t(m.emissionTexture.texture)];
            if (mean < 0) mean = meanLuminanceOverFrames(scene_.textures, std::size_t(m.emissionTexture.texture));
            texture = mean;
        }
        return luminance(m.emission) * texture;
    }

private:
    const Scene& scene_;
    std::vector<float> textureMeans_;  // -1: not computed yet
    Vec3 skyPortal_;
};

void putSprite(const Sprite& sprite, std::size_t slot, SceneArrays& out) {
    out.triVerts[slot] = toSpriteVerts(sprite);
    out.triAttribs[slot] = {};
    out.triAttribs[slot].materialId = sprite.material;
    out.triAttribs[slot].area = (sprite.right - sprite.left) * (sprite.top - sprite.bottom);
    // Not an object the viewer edits, and never a sampled light.
}

// Sphere k of the render spheres: those past the scene's own are light spheres, not objects the
// user can edit.
void putSphere(const Scene& scene, const Sphere& sphere, std::size_t k, std::size_t slot, SceneArrays& out) {
    if (k < scene.spheres.size()) out.primitiveObject[slot] = sphereObject(scene, k);
    out.triVerts[slot] = bvh::toSphereVerts(sphere.center, sphere.radius);
    out.triAttribs[slot] = {};
    out.triAttribs[slot].materialId = sphere.material;
    out.triAttribs[slot].area = 4.0f * kPiF * sphere.radius * sphere.radius;
}

// What filling the leaf slots gathers for the lights.
struct LeafSlots {
    std::vector<EmissiveTriangle> emissive;  // the sampled emissive triangles
    std::vector<std::uint32_t> sphereSlots;  // the slot of each render sphere
};

// Fills out's per-primitive arrays in leaf order (primOrder[i]: the primitive in slot i).
LeafSlots fillLeafSlots(const Scene& scene, const Primitives& prims, std::span<const std::uint32_t> primOrder,
                        SceneArrays& out) {
    out.triVerts.resize(prims.count);
    out.triAttribs.resize(prims.count);
    out.primitiveObject.assign(prims.count, kNoObject);
    std::vector<std::uint32_t> triangleMesh;  // mesh of each triangle, in flattenTriangles' order
    triangleMesh.reserve(prims.tris.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m)
        triangleMesh.insert(triangleMesh.end(), scene.meshes[m].triangleCount(), std::uint32_t(m));
    EmitterLuminance emitterLuminance(scene);
    LeafSlots found;
    found.sphereSlots.resize(prims.spheres.spheres.size());
    for (std::size_t i = 0; i < primOrder.size(); ++i) {
        const std::uint32_t prim = primOrder[i];
        if (prim >= prims.firstSprite) {
            putSprite(scene.sprites[prim - prims.firstSprite], i, out);
        } else if (prim >= prims.tris.size()) {
            const std::size_t k = prim - prims.tris.size();
            found.sphereSlots[k] = static_cast<std::uint32_t>(i);
            putSphere(scene, prims.spheres.spheres[k], k, i, out);
        } else {
            const SceneTriangle& t = prims.tris[prim];
            out.primitiveObject[i] = triangleMesh[prim];
            out.triVerts[i] = bvh::toTriVerts(prims.geometry[prim]);
            out.triVerts[i].uvIndex = bvh::appendTriUvs(t, out.triUvs);
            out.triAttribs[i] = bvh::toTriAttribs(t);
            const Material& m = scene.materials[t.material];
            if (m.isEmissive() && m.lightSampled && out.triAttribs[i].area > 0)
                found.emissive.push_back({static_cast<std::uint32_t>(i), {t.p[0], t.p[1], t.p[2]}, emitterLuminance(m)});
        }
    }
    return found;
}

// Every texture's texels, one RGBA8 texel per word, in one array.
void addTextures(const Scene& scene, SceneArrays& out) {
    for (const Texture& t : scene.textures) {
        const std::size_t texels = std::size_t(t.width) * std::size_t(t.height);
        if (out.texels.size() + texels > std::size_t(UINT32_MAX))
            throw Error("scene '" + scene.name + "' has more texture data than fits in one buffer (4 Gi texels)");
        shader::TextureInfo info{};
        info.firstTexel = static_cast<std::uint32_t>(out.texels.size());
        info.width = std::uint32_t(t.width);
        info.height = std::uint32_t(t.height);
        info.flags = t.srgb ? PN_TEXTURE_SRGB : 0u;
        info.frameCount = std::uint32_t(std::max(t.animation.frames, 1));
        info.frame = std::uint32_t(std::max(t.animation.frame, 0));
        info.secondsPerFrame = t.animation.secondsPerFrame;
        out.textures.push_back(info);
        const std::size_t first = out.texels.size();
        out.texels.resize(first + texels);
        std::memcpy(out.texels.data() + first, t.rgba.data(), texels * 4);
    }
}

// Traversal checks alpha only where the flag says so, keeping the common path cheap; likewise a
// transmissive triangle is flagged to keep its back face under --cull-backfaces.
void markAlphaTested(SceneArrays& out) {
    for (std::size_t i = 0; i < out.triVerts.size(); ++i) {
        if (bvh::isSphere(out.triVerts[i]) || bvh::isSprite(out.triVerts[i])) continue;
        const shader::Material& m = out.materials[out.triAttribs[i].materialId];
        if (m.flags & PN_MATERIAL_ALPHA_TESTED) out.triVerts[i].flags |= PN_TRI_ALPHA_TESTED;
        if (m.transmission > 0) out.triVerts[i].flags |= PN_TRI_KEEP_BACK;
    }
}

}  // namespace

std::vector<Aabb> worldPrimitiveBounds(const Scene& input) {
    std::vector<std::uint32_t> keptFrom;
    const std::optional<Scene> baked = sceneToBuild(input, keptFrom);
    const Scene& scene = baked ? *baked : input;
    const Primitives prims = gatherPrimitives(scene);
    return primitiveBounds(prims.geometry, extraPrimitiveBounds(scene, prims));
}

SceneArrays buildSceneArrays(const Scene& input, const bvh::BuildOptions& options, Accel accel,
                             const GpuBvhBuilder* gpuBuilder) {
    input.validate();
    std::vector<std::uint32_t> keptFrom;  // the input's number of each instance left after baking
    const std::optional<Scene> baked = sceneToBuild(input, keptFrom);
    const Scene& scene = baked ? *baked : input;
    const Primitives prims = gatherPrimitives(scene);

    SceneArrays out;
    const std::vector<std::uint32_t> primOrder = buildTree(scene, prims, options, accel, gpuBuilder, out);
    const LeafSlots slots = fillLeafSlots(scene, prims, primOrder, out);
    std::vector<bool> punctualMoves;
    addPunctualLights(scene, out.punctual, punctualMoves);
    out.sphereLights = buildSphereLightTable(scene, prims.spheres, prims.materials, slots.sphereSlots);
    addLightList(scene, slots.emissive, punctualMoves, out);
    out.sphereCount = static_cast<std::uint32_t>(prims.spheres.spheres.size());

    addTextures(scene, out);
    if (scene.environment.map) {
        const auto start = std::chrono::steady_clock::now();
        out.env = buildEnvTable(*scene.environment.map);
        out.envBuildMilliseconds = millisecondsSince(start);
    }
    for (const Material& m : prims.materials) out.materials.push_back(toGpuMaterial(m));
    appendInstanceLevels(scene, out, options);
    // Instances keep the input scene's numbers (what the viewer moves them by).
    if (!keptFrom.empty())
        for (shader::Instance& i : out.instances)
            if (i.id != PN_NO_HIT) i.id = keptFrom.at(i.id);
    markAlphaTested(out);
    addLightGrid(out);
    buildWalkRecords(out, accel);
    return out;
}

std::size_t binaryWalkBytes(const SceneArrays& a) { return binaryNodesUploaded(a) * sizeof(shader::BvhPair); }

std::size_t deviceBytes(const SceneArrays& a) {
    auto bytes = [](const auto& v) { return v.size() * sizeof(v[0]); };
    return binaryWalkBytes(a) + bytes(a.wideNodes) + bytes(a.triVerts) + bytes(a.triAttribs) + bytes(a.triUvs) + bytes(a.materials) + bytes(a.lightRefs) +
           bytes(a.lightNodes) + bytes(a.lightTree) + bytes(a.lightGrid) + bytes(a.textures) + bytes(a.texels) + bytes(a.punctual) + bytes(a.sphereLights) +
           bytes(a.env.alias) + bytes(a.env.radiance) + bytes(a.instances) + bytes(a.stacklessNodes) + bytes(a.objectBoxes) +
           bytes(a.objectPrims);
}

GpuScene::GpuScene(const gpu::Context& ctx, gpu::Commands& commands, const SceneArrays& a)
    // The device's limits are checked before the first buffer is made (render/scene_limits.h).
    : nodes((checkSceneFitsDevice(ctx, a), gpu::uploadStorageBuffer<shader::BvhPair>(ctx, commands, nodeBufferContents(a)))),
      triVerts(gpu::uploadStorageBuffer<shader::TriVerts>(ctx, commands, a.triVerts)),
      triAttribs(gpu::uploadStorageBuffer<shader::TriAttribs>(ctx, commands, a.triAttribs)),
      triUvs(gpu::uploadStorageBuffer<shader::TriUvs>(ctx, commands, a.triUvs)),
      materials(gpu::uploadStorageBuffer<shader::Material>(ctx, commands, a.materials)),
      lightRefs(gpu::uploadStorageBuffer<shader::LightRef>(ctx, commands, a.lightRefs)),
      lightNodes(gpu::uploadStorageBuffer<shader::LightNode>(ctx, commands, a.lightNodes)),
      lightTree(gpu::uploadStorageBuffer<std::uint32_t>(ctx, commands, lightTreeBufferContents(a))),
      textures(gpu::uploadStorageBuffer<shader::TextureInfo>(ctx, commands, a.textures)),
      texels(gpu::uploadStorageBuffer<std::uint32_t>(ctx, commands, a.texels)),
      punctual(gpu::uploadStorageBuffer<shader::PunctualLight>(ctx, commands, a.punctual)),
      sphereLights(gpu::uploadStorageBuffer<shader::SphereLight>(ctx, commands, a.sphereLights)),
      envTable(gpu::uploadStorageBuffer<shader::EnvAlias>(ctx, commands, a.env.alias)),
      envTexels(gpu::uploadStorageBuffer<Vec4>(ctx, commands, a.env.radiance)),
      instances(gpu::uploadStorageBuffer<shader::Instance>(ctx, commands, a.instances)),
      stacklessNodes(gpu::uploadStorageBuffer<shader::StacklessNode>(ctx, commands, a.stacklessNodes)),
      objectBoxes(gpu::uploadStorageBuffer<shader::ObjectBox>(ctx, commands, a.objectBoxes)),
      objectPrims(gpu::uploadStorageBuffer<std::uint32_t>(ctx, commands, a.objectPrims)),
      walk(a.walk),
      instanceCount(static_cast<std::uint32_t>(a.instances.size())),
      topRoot(a.topRoot),
      nodeCount(static_cast<std::uint32_t>(binaryNodesUploaded(a))),
      wideNodeCount(static_cast<std::uint32_t>(a.wideNodes.size())),
      triCount(static_cast<std::uint32_t>(a.triVerts.size())),
      lightNodeCount(static_cast<std::uint32_t>(a.lightTree.size())),
      lightGridOffset(lightGridWord(a)),
      topLightCount(a.topLightCount),
      lightRefCount(static_cast<std::uint32_t>(a.lightRefs.size())),
      punctualCount(static_cast<std::uint32_t>(a.punctual.size())),
      sphereCount(a.sphereCount),
      sphereLightCount(static_cast<std::uint32_t>(a.sphereLights.size())),
      envWidth(a.env.width),
      envHeight(a.env.height),
      envLuminance(a.envLuminance) {}

std::size_t GpuScene::deviceBytes() const {
    return nodes.size() + triVerts.size() + triAttribs.size() + triUvs.size() + materials.size() + lightRefs.size() + lightNodes.size() +
           lightTree.size() + textures.size() + texels.size() + punctual.size() + sphereLights.size() + envTable.size() + envTexels.size() +
           instances.size() + stacklessNodes.size() + objectBoxes.size() + objectPrims.size();
}

}  // namespace penumbra
