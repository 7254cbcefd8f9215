// glTF 2.0 (.gltf, .glb, data URIs) through tinygltf (Debian's libtinygltf.so): the model is
// read by gltf_model.cpp, and turned into a Scene here: materials and textures, the node
// hierarchy (gltf_node.cpp: local transforms), cameras and lights, geometry (gltf_accessor.cpp:
// checked accessor views), instancing and animations. Every index tinygltf hands back is checked
// before it is used.
#include "scene/io/gltf.h"

#include <tiny_gltf.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <system_error>

#include "core/error.h"
#include "core/log.h"
#include "scene/face_check.h"
#include "scene/io/gltf_accessor.h"
#include "scene/io/gltf_model.h"
#include "scene/io/gltf_node.h"
#include "scene/io/normals.h"
#include "scene/io/texture_io.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

constexpr std::size_t kMaxNodeDepth = 256;   // deeper node chains are refused
constexpr std::size_t kMaxNodeVisits = std::size_t(1) << 20;
constexpr std::size_t kMaxOutputVertices = std::size_t(1) << 27;  // over all instances
constexpr std::size_t kMaxOutputIndices = std::size_t(3) << 27;

using gltf::AccessorView;
using gltf::clampName;
using gltf::readAccessor;
using tinygltf::Model;

double extNumber(const tinygltf::ExtensionMap& ext, const char* name, const char* key, double fallback) {
    auto it = ext.find(name);
    if (it == ext.end() || !it->second.IsObject() || !it->second.Has(key)) return fallback;
    const tinygltf::Value& v = it->second.Get(key);
    if (!v.IsNumber()) return fallback;
    double d = v.GetNumberAsDouble();
    return std::isfinite(d) ? d : fallback;
}

float clamp01(double v) { return std::isfinite(v) ? float(std::clamp(v, 0.0, 1.0)) : 0.0f; }

// An RGB array of an extension's key, each channel clamped to [0, 1].
Vec3 extColor(const tinygltf::ExtensionMap& ext, const char* name, const char* key, Vec3 fallback) {
    auto it = ext.find(name);
    if (it == ext.end() || !it->second.IsObject() || !it->second.Has(key)) return fallback;
    const tinygltf::Value& v = it->second.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 3) return fallback;
    Vec3 c;
    for (int k = 0; k < 3; ++k) {
        const tinygltf::Value& e = v.Get(k);
        if (!e.IsNumber()) return fallback;
        c[k] = clamp01(e.GetNumberAsDouble());
    }
    return c;
}

class GltfImporter {
public:
    GltfImporter(const Model& model, std::string name) : model_(model), name_(std::move(name)) {}

    Scene run() {
        scene_.name = name_;
        for (std::size_t i = 0; i < model_.materials.size(); ++i) scene_.materials.push_back(material(int(i)));
        readAnimations();
        traverse();
        placeMeshes();
        if (scene_.meshes.empty() && scene_.instances.empty() && skipped_.total() > 0)
            throw Error(name_ + ": no face can be rendered: the file has " + skipped_.describe());
        if (scene_.meshes.empty() && scene_.instances.empty())
            throw Error(name_ + ": the glTF scene has no triangles (no mesh with TRIANGLES primitives is reachable)");
        skipped_.warn(name_);
        if (scene_.materials.empty()) defaultMaterial();
        if (!cameraSet_) scene_.camera = cameraFittingBounds(scene_.bounds());
        scene_.validate();
        return std::move(scene_);
    }

private:
    // ---- materials and textures ----

    std::uint32_t defaultMaterial() {
        if (defaultMaterial_ < 0) {
            defaultMaterial_ = int(scene_.materials.size());
            Material m;
            m.name = "default";
            m.albedo = Vec3{1.0f};  // glTF's default material: white, metallic 1, roughness 1
            m.metallic = 1.0f;
            scene_.materials.push_back(m);
        }
        return std::uint32_t(defaultMaterial_);
    }

    static Wrap wrap(int mode) {
        switch (mode) {
            case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return Wrap::ClampToEdge;
            case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return Wrap::MirroredRepeat;
        }
        return Wrap::Repeat;
    }

    int image(int index, bool srgb) {
        auto key = std::make_pair(index, srgb);
        if (auto it = imageCache_.find(key); it != imageCache_.end()) return it->second;
        const tinygltf::Image& img = model_.images[std::size_t(index)];
        std::string label = !img.name.empty() ? img.name : !img.uri.empty() ? img.uri : "image " + std::to_string(index);
        label = clampName(label);
        std::string_view bytes;
        std::string why = "no image data (file missing?)";
        if (img.bufferView >= 0) {
            if (std::size_t(img.bufferView) >= model_.bufferViews.size()) {
                why = "bufferView " + std::to_string(img.bufferView) + " does not exist";
            } else {
                const tinygltf::BufferView& bv = model_.bufferViews[std::size_t(img.bufferView)];
                if (bv.buffer < 0 || std::size_t(bv.buffer) >= model_.buffers.size()) {
                    why = "buffer " + std::to_string(bv.buffer) + " does not exist";
                } else {
                    const auto& buf = model_.buffers[std::size_t(bv.buffer)].data;
                    if (bv.byteLength > buf.size() || bv.byteOffset > buf.size() - bv.byteLength)
                        why = "bufferView " + std::to_string(img.bufferView) + " lies outside its buffer";
                    else
                        bytes = {reinterpret_cast<const char*>(buf.data()) + bv.byteOffset, bv.byteLength};
                }
            }
        } else if (!img.image.empty()) {
            bytes = {reinterpret_cast<const char*>(img.image.data()), img.image.size()};
        }
        std::optional<Texture> tex;
        if (!bytes.empty()) tex = decodeTexture(bytes, label, srgb, &why);
        if (!tex) {
            logWarning(name_ + ": image " + std::to_string(index) + " ('" + label + "'): " + why + "; using a checker");
            tex = missingTexture(label);
        }
        tex->srgb = srgb;
        const int slot = int(scene_.textures.size());
        scene_.textures.push_back(std::move(*tex));
        imageCache_.emplace(key, slot);
        return slot;
    }

    TextureRef texture(const tinygltf::TextureInfo& info, int texCoord, const tinygltf::ExtensionMap& ext,
                       bool srgb, const std::string& where) {
        return textureRef(info.index, texCoord, ext, srgb, where);
    }

    TextureRef textureRef(int index, int texCoord, const tinygltf::ExtensionMap& ext, bool srgb,
                          const std::string& where) {
        TextureRef ref;
        if (index < 0) return ref;
        if (std::size_t(index) >= model_.textures.size())
            throw Error(where + ": texture " + std::to_string(index) + " does not exist");
        if (texCoord != 0) warnOnce("only TEXCOORD_0 is read; textures using other sets are sampled with set 0");
        if (ext.count("KHR_texture_transform")) warnOnce("KHR_texture_transform is ignored");
        const tinygltf::Texture& t = model_.textures[std::size_t(index)];
        if (t.source < 0 || std::size_t(t.source) >= model_.images.size()) {
            warnOnce("texture " + std::to_string(index) + " has no image this loader can read; it is ignored");
            return ref;
        }
        if (t.sampler >= 0) {
            if (std::size_t(t.sampler) >= model_.samplers.size())
                throw Error(where + ": texture " + std::to_string(index) + " uses sampler " +
                            std::to_string(t.sampler) + ", which does not exist");
            const tinygltf::Sampler& s = model_.samplers[std::size_t(t.sampler)];
            ref.wrapU = wrap(s.wrapS);
            ref.wrapV = wrap(s.wrapT);
            // Magnification decides the look up close (pixel art asks for NEAREST); minification
            // has no effect without mipmaps.
            if (s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) ref.filter = Filter::Nearest;
        }
        ref.texture = image(t.source, srgb);
        return ref;
    }

    Material material(int index) {
        const tinygltf::Material& g = model_.materials[std::size_t(index)];
        const std::string where = name_ + ": material " + std::to_string(index) + " ('" + clampName(g.name) + "')";
        Material m;
        m.name = g.name.empty() ? "material " + std::to_string(index) : g.name;
        const auto& pbr = g.pbrMetallicRoughness;
        std::array<double, 4> base{1, 1, 1, 1};
        if (pbr.baseColorFactor.size() == 4) std::copy(pbr.baseColorFactor.begin(), pbr.baseColorFactor.end(), base.begin());
        m.albedo = {clamp01(base[0]), clamp01(base[1]), clamp01(base[2])};
        m.metallic = clamp01(pbr.metallicFactor);
        m.roughness = clamp01(pbr.roughnessFactor);
        Vec3 emissive{};
        if (g.emissiveFactor.size() == 3)
            for (int k = 0; k < 3; ++k) emissive[k] = float(g.emissiveFactor[std::size_t(k)]);
        const double strength = extNumber(g.extensions, "KHR_materials_emissive_strength", "emissiveStrength", 1.0);
        for (int k = 0; k < 3; ++k) {
            const float e = float(double(emissive[k]) * strength);
            m.emission[k] = std::isfinite(e) && e > 0 ? e : 0.0f;
        }
        m.transmission = clamp01(extNumber(g.extensions, "KHR_materials_transmission", "transmissionFactor", 0.0));
        const double ior = extNumber(g.extensions, "KHR_materials_ior", "ior", 1.5);
        m.ior = ior >= 1.0 ? float(std::min(ior, 4.0)) : 1.5f;  // 0 ("no refraction") and junk -> default
        m.twoSided = g.doubleSided;
        // Every glTF dielectric has a specular layer (KHR_materials_specular scales it).
        m.specular = clamp01(extNumber(g.extensions, "KHR_materials_specular", "specularFactor", 1.0));
        const double attenuationDistance =
            extNumber(g.extensions, "KHR_materials_volume", "attenuationDistance", 0.0);
        if (attenuationDistance > 0) {
            m.absorptionDistance = float(std::min(attenuationDistance, 1e9));
            m.absorptionColor = extColor(g.extensions, "KHR_materials_volume", "attenuationColor", Vec3{1.0f});
        }
        if (g.alphaMode == "MASK") {
            m.alphaCutoff = std::isfinite(g.alphaCutoff) ? float(std::clamp(g.alphaCutoff, 1e-4, 1.0)) : 0.5f;
        } else if (g.alphaMode == "BLEND") {
            m.opacity = clamp01(base[3]);
        }
        m.albedoTexture = texture(pbr.baseColorTexture, pbr.baseColorTexture.texCoord,
                                  pbr.baseColorTexture.extensions, true, where);
        m.metallicRoughnessTexture = texture(pbr.metallicRoughnessTexture, pbr.metallicRoughnessTexture.texCoord,
                                             pbr.metallicRoughnessTexture.extensions, false, where);
        m.normalTexture = textureRef(g.normalTexture.index, g.normalTexture.texCoord, g.normalTexture.extensions,
                                     false, where);
        m.emissionTexture = texture(g.emissiveTexture, g.emissiveTexture.texCoord, g.emissiveTexture.extensions,
                                    true, where);
        return m;
    }

    void warnOnce(const std::string& text) {
        if (warned_.insert(text).second) logWarning(name_ + ": " + text);
    }

    // ---- nodes ----

    std::vector<int> roots() {
        std::vector<int> out;
        if (!model_.scenes.empty()) {
            std::size_t s = 0;
            if (model_.defaultScene >= 0 && std::size_t(model_.defaultScene) < model_.scenes.size())
                s = std::size_t(model_.defaultScene);
            else if (model_.defaultScene >= 0)
                warnOnce("default scene " + std::to_string(model_.defaultScene) + " does not exist; using scene 0");
            return model_.scenes[s].nodes;
        }
        // No scene: every node that is nobody's child.
        std::vector<char> isChild(model_.nodes.size(), 0);
        for (const tinygltf::Node& n : model_.nodes)
            for (int c : n.children)
                if (c >= 0 && std::size_t(c) < model_.nodes.size()) isChild[std::size_t(c)] = 1;
        for (std::size_t i = 0; i < model_.nodes.size(); ++i)
            if (!isChild[i]) out.push_back(int(i));
        return out;
    }

    std::string nodeWhere(int index) const {
        std::string w = name_ + ": node " + std::to_string(index);
        if (index >= 0 && std::size_t(index) < model_.nodes.size() && !model_.nodes[std::size_t(index)].name.empty())
            w += " ('" + clampName(model_.nodes[std::size_t(index)].name) + "')";
        return w;
    }

    void traverse() {
        struct Frame {
            int node;
            Affine world;
            std::size_t next = 0;  // next child to visit
        };
        std::vector<char> onPath(model_.nodes.size(), 0);
        std::vector<Frame> stack;
        std::size_t visits = 0;
        auto enter = [&](int node, const Affine& parent, int from) {
            if (node < 0 || std::size_t(node) >= model_.nodes.size())
                throw Error((from < 0 ? name_ + ": scene" : nodeWhere(from)) + " refers to node " + std::to_string(node) +
                            ", which does not exist (" + std::to_string(model_.nodes.size()) + " nodes)");
            if (onPath[std::size_t(node)])
                throw Error(nodeWhere(node) + " is its own ancestor: the node hierarchy has a cycle");
            if (stack.size() >= kMaxNodeDepth)
                throw Error(nodeWhere(node) + " is nested more than " + std::to_string(kMaxNodeDepth) + " levels deep");
            if (++visits > kMaxNodeVisits)
                throw Error(name_ + ": the node hierarchy instantiates more than " + std::to_string(kMaxNodeVisits) +
                            " nodes");
            const std::string where = nodeWhere(node);
            const tinygltf::Node& n = model_.nodes[std::size_t(node)];
            Affine world = parent * gltf::nodeTransform(n, where);
            onPath[std::size_t(node)] = 1;
            if (!animated_.empty() && n.mesh >= 0) {  // the node chain, for animated instances
                path_.clear();
                for (const Frame& f : stack) path_.push_back(f.node);
                path_.push_back(node);
            }
            visitNode(node, n, world, where);
            stack.push_back({node, world, 0});
        };
        for (int root : roots()) {
            enter(root, Affine{}, -1);
            while (!stack.empty()) {
                Frame& top = stack.back();
                const tinygltf::Node& n = model_.nodes[std::size_t(top.node)];
                if (top.next < n.children.size()) {
                    const int child = n.children[top.next++];
                    const Affine world = top.world;  // `top` may move when the stack grows
                    enter(child, world, top.node);
                } else {
                    onPath[std::size_t(top.node)] = 0;
                    stack.pop_back();
                }
            }
        }
    }

    void visitNode(int index, const tinygltf::Node& n, const Affine& world, const std::string& where) {
        if (n.mesh >= 0) {
            if (std::size_t(n.mesh) >= model_.meshes.size())
                throw Error(where + ": mesh " + std::to_string(n.mesh) + " does not exist");
            pending_.push_back({index, n.mesh, world, where, animatedPath() ? path_ : std::vector<int>{}});
        } else if (n.mesh < -1) {
            throw Error(where + ": mesh " + std::to_string(n.mesh) + " does not exist");
        }
        if (n.camera >= 0 && !cameraSet_) {
            if (std::size_t(n.camera) >= model_.cameras.size())
                throw Error(where + ": camera " + std::to_string(n.camera) + " does not exist");
            useCamera(model_.cameras[std::size_t(n.camera)], world, where);
        }
        if (auto it = n.extensions.find("KHR_lights_punctual"); it != n.extensions.end()) {
            const tinygltf::Value& v = it->second;
            if (!v.IsObject() || !v.Has("light") || !v.Get("light").IsNumber())
                throw Error(where + ": KHR_lights_punctual needs a light index");
            const double li = v.Get("light").GetNumberAsDouble();
            if (!(li >= 0 && li < double(model_.lights.size())) || li != std::floor(li))
                throw Error(where + ": light " + std::to_string(li) + " does not exist");
            addLight(model_.lights[std::size_t(li)], world, where);
        }
    }

    void useCamera(const tinygltf::Camera& cam, const Affine& world, const std::string& where) {
        if (cam.type != "perspective") {
            warnOnce("camera type '" + clampName(cam.type) + "' is not supported; only perspective cameras are used");
            return;
        }
        const double yfov = cam.perspective.yfov;
        const Vec3 pos = world.point({0, 0, 0});
        const Vec3 forward = normalize(world.vector({0, 0, -1}));
        const Vec3 up = normalize(world.vector({0, 1, 0}));
        Camera c;
        c.position = pos;
        c.lookAt = pos + forward;
        c.up = up;
        c.fovYDegrees = float(radiansToDegrees(yfov));
        if (!(yfov > 0 && c.fovYDegrees < 179.0f) || !isFinite(pos) || !isFinite(c.lookAt) || dot(forward, forward) == 0 ||
            length(cross(forward, up)) < 1e-4f) {
            logWarning(where + ": camera has an unusable transform or field of view; it is ignored");
            return;
        }
        scene_.camera = c;
        cameraSet_ = true;
    }

    void addLight(const tinygltf::Light& g, const Affine& world, const std::string& where) {
        Light l;
        l.name = g.name;
        if (g.type == "point")
            l.type = LightType::Point;
        else if (g.type == "spot")
            l.type = LightType::Spot;
        else if (g.type == "directional")
            l.type = LightType::Directional;
        else
            throw Error(where + ": light type '" + clampName(g.type) + "' is not point, spot or directional");
        l.position = world.point({0, 0, 0});
        l.direction = normalize(world.vector({0, 0, -1}));
        if (g.color.size() == 3) l.color = {float(g.color[0]), float(g.color[1]), float(g.color[2])};
        l.intensity = float(g.intensity);
        l.range = float(g.range);
        l.innerConeRadians = float(g.spot.innerConeAngle);
        l.outerConeRadians = float(g.spot.outerConeAngle);
        if (!isFinite(l.position) || !isFinite(l.color) || minComponent(l.color) < 0 || !std::isfinite(l.intensity) ||
            l.intensity < 0 || !std::isfinite(l.range) || l.range < 0 ||
            (l.type != LightType::Point && dot(l.direction, l.direction) == 0))
            throw Error(where + ": light '" + clampName(g.name) + "' has an invalid colour, intensity, range or transform");
        if (l.type == LightType::Spot) {
            if (!std::isfinite(l.innerConeRadians) || !std::isfinite(l.outerConeRadians))
                throw Error(where + ": spot light cone angles must be finite");
            l.outerConeRadians = std::clamp(l.outerConeRadians, 1e-4f, 1.5707963f);
            l.innerConeRadians = std::clamp(l.innerConeRadians, 0.0f, l.outerConeRadians);
        }
        scene_.lights.push_back(l);
    }

    // ---- geometry ----

    struct LocalPrimitive {
        std::vector<Vec3> positions, normals;
        std::vector<Vec2> uvs;
        std::vector<std::uint32_t> indices;
    };

    const LocalPrimitive* decode(int meshIndex, int primIndex, const std::string& where) {
        auto key = std::make_pair(meshIndex, primIndex);
        if (auto it = primCache_.find(key); it != primCache_.end()) return it->second.get();
        const tinygltf::Primitive& p = model_.meshes[std::size_t(meshIndex)].primitives[std::size_t(primIndex)];
        auto out = std::make_unique<LocalPrimitive>();
        const auto pos = p.attributes.find("POSITION");
        if (pos == p.attributes.end()) {
            logWarning(where + ": no POSITION attribute; skipped");
            return primCache_.emplace(key, nullptr).first->second.get();
        }
        const AccessorView pv = readAccessor(model_, pos->second, where + " POSITION", 3);
        if (pv.count >= std::numeric_limits<std::uint32_t>::max()) throw Error(where + ": too many vertices");
        out->positions.resize(pv.count);
        for (std::size_t i = 0; i < pv.count; ++i) {
            Vec3 v{float(pv.component(i, 0)), float(pv.component(i, 1)), float(pv.component(i, 2))};
            if (!isFinite(v))
                throw Error(where + ": POSITION (accessor " + std::to_string(pos->second) + ") vertex " +
                            std::to_string(i) + " is not finite");
            out->positions[i] = v;
        }
        if (auto it = p.attributes.find("NORMAL"); it != p.attributes.end()) {
            const AccessorView nv = readAccessor(model_, it->second, where + " NORMAL", 3);
            if (nv.count != pv.count) throw Error(where + ": NORMAL and POSITION counts differ");
            out->normals.resize(nv.count);
            for (std::size_t i = 0; i < nv.count; ++i) {
                Vec3 n{float(nv.component(i, 0)), float(nv.component(i, 1)), float(nv.component(i, 2))};
                out->normals[i] = isFinite(n) ? n : Vec3{};
            }
        }
        if (auto it = p.attributes.find("TEXCOORD_0"); it != p.attributes.end()) {
            const AccessorView tv = readAccessor(model_, it->second, where + " TEXCOORD_0", 2);
            if (tv.count != pv.count) throw Error(where + ": TEXCOORD_0 and POSITION counts differ");
            out->uvs.resize(tv.count);
            for (std::size_t i = 0; i < tv.count; ++i) {
                Vec2 uv{float(tv.component(i, 0)), float(tv.component(i, 1))};
                out->uvs[i] = (std::isfinite(uv.x) && std::isfinite(uv.y)) ? uv : Vec2{};
            }
        }
        if (p.indices >= 0) {
            const AccessorView iv = readAccessor(model_, p.indices, where + " indices", 1);
            if (iv.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                iv.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                iv.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
                throw Error(where + ": indices must be unsigned integers");
            const std::size_t n = iv.count - iv.count % 3;
            if (iv.count % 3) logWarning(where + ": index count is not a multiple of 3; the rest is ignored");
            out->indices.resize(n);
            for (std::size_t i = 0; i < n; ++i) {
                const double d = iv.component(i, 0);
                if (d >= double(pv.count))
                    throw Error(where + ": index " + std::to_string(std::uint64_t(d)) + " (element " + std::to_string(i) +
                                " of accessor " + std::to_string(p.indices) + ") is past the " +
                                std::to_string(pv.count) + " vertices");
                out->indices[i] = std::uint32_t(d);
            }
        } else {
            if (pv.count % 3) logWarning(where + ": vertex count is not a multiple of 3; the rest is ignored");
            const std::size_t n = pv.count - pv.count % 3;
            out->indices.resize(n);
            for (std::size_t i = 0; i < n; ++i) out->indices[i] = std::uint32_t(i);
        }
        return primCache_.emplace(key, std::move(out)).first->second.get();
    }

    // A mesh that one node uses is baked into world space; one that several nodes use becomes a
    // prototype (stored once, in the mesh's own space) and an instance per node (Scene::instances).
    void placeMeshes() {
        std::map<int, int> uses;
        for (const PendingMesh& p : pending_) ++uses[p.mesh];
        std::map<int, std::uint32_t> prototypeOf;
        for (const PendingMesh& p : pending_) {
            const Affine placement = p.world;
            const float det = placement.determinant();
            const bool invertible = std::abs(det) > 1e-12f && std::isfinite(1.0f / det);
            const bool animated = !p.path.empty();
            if ((uses[p.mesh] < 2 && !animated) || !invertible) {
                addMesh(p.node, p.mesh, p.world, p.where, scene_.meshes);
                continue;
            }
            auto it = prototypeOf.find(p.mesh);
            if (it == prototypeOf.end()) {
                Prototype proto;
                proto.name = model_.meshes[std::size_t(p.mesh)].name;
                addMesh(p.node, p.mesh, Affine{}, p.where, proto.meshes);
                const auto index = proto.meshes.empty() ? kNoPrototype : std::uint32_t(scene_.prototypes.size());
                if (!proto.meshes.empty()) scene_.prototypes.push_back(std::move(proto));
                it = prototypeOf.emplace(p.mesh, index).first;
            }
            if (it->second == kNoPrototype) continue;
            if (animated) scene_.instanceAnimations.push_back({std::uint32_t(scene_.instances.size()), chainOf(p.path)});
            scene_.instances.push_back({it->second, placement});
        }
    }

    // ---- animations (scene/node_animation.h): every channel of every animation plays at once ----

    bool animatedPath() const {
        for (int node : path_)
            if (animated_.count(node)) return true;
        return false;
    }

    void readAnimations() {
        for (std::size_t a = 0; a < model_.animations.size(); ++a) {
            const tinygltf::Animation& anim = model_.animations[a];
            const std::string where = name_ + ": animation " + std::to_string(a);
            for (std::size_t c = 0; c < anim.channels.size(); ++c) {
                const tinygltf::AnimationChannel& ch = anim.channels[c];
                const std::string at = where + " channel " + std::to_string(c);
                if (ch.target_path == "weights") {
                    warnOnce("morph target animations (weights) are not supported; they are ignored");
                    continue;
                }
                if (ch.target_path != "translation" && ch.target_path != "rotation" && ch.target_path != "scale")
                    throw Error(at + ": unknown target path '" + clampName(ch.target_path) + "'");
                if (ch.target_node < 0 || std::size_t(ch.target_node) >= model_.nodes.size())
                    throw Error(at + ": target node " + std::to_string(ch.target_node) + " does not exist");
                if (ch.sampler < 0 || std::size_t(ch.sampler) >= anim.samplers.size())
                    throw Error(at + ": sampler " + std::to_string(ch.sampler) + " does not exist");
                if (!model_.nodes[std::size_t(ch.target_node)].matrix.empty())
                    throw Error(at + ": it animates node " + std::to_string(ch.target_node) +
                                ", which has a matrix (glTF allows animating TRS nodes only)");
                const bool rotation = ch.target_path == "rotation";
                Track track = readTrack(anim.samplers[std::size_t(ch.sampler)], rotation ? 4 : 3, at);
                NodeTracks& tracks = animated_[ch.target_node];
                (rotation ? tracks.rotation : ch.target_path == "scale" ? tracks.scale : tracks.translation) = std::move(track);
            }
        }
    }

    Track readTrack(const tinygltf::AnimationSampler& sampler, int components, const std::string& where) {
        Track track;
        if (sampler.interpolation == "STEP") track.interpolation = KeyInterpolation::Step;
        else if (sampler.interpolation == "CUBICSPLINE") track.interpolation = KeyInterpolation::CubicSpline;
        else if (sampler.interpolation.empty() || sampler.interpolation == "LINEAR") track.interpolation = KeyInterpolation::Linear;
        else throw Error(where + ": unknown interpolation '" + clampName(sampler.interpolation) + "'");
        const AccessorView in = readAccessor(model_, sampler.input, where + " input", 1);
        const AccessorView out = readAccessor(model_, sampler.output, where + " output", components);
        if (in.count == 0) throw Error(where + ": the sampler has no keys");
        for (std::size_t k = 0; k < in.count; ++k) track.times.push_back(float(in.component(k, 0)));
        for (std::size_t k = 0; k < out.count; ++k) {
            KeyValue v{0, 0, 0, 0};
            for (int i = 0; i < components; ++i) v[std::size_t(i)] = float(out.component(k, i));
            track.values.push_back(v);
        }
        validateTrack(track, where);
        return track;
    }

    std::vector<NodeMotion> chainOf(const std::vector<int>& path) const {
        std::vector<NodeMotion> chain;
        for (int index : path) {
            const tinygltf::Node& n = model_.nodes[std::size_t(index)];
            NodeMotion m;
            const auto it = animated_.find(index);
            if (it == animated_.end()) {
                m.fixed = gltf::nodeTransform(n, nodeWhere(index));
            } else {
                m.trs = true;
                if (n.translation.size() == 3) m.translation = {float(n.translation[0]), float(n.translation[1]), float(n.translation[2])};
                if (n.rotation.size() == 4)
                    m.rotation = {float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]), float(n.rotation[3])};
                if (n.scale.size() == 3) m.scale = {float(n.scale[0]), float(n.scale[1]), float(n.scale[2])};
                m.translationTrack = it->second.translation;
                m.rotationTrack = it->second.rotation;
                m.scaleTrack = it->second.scale;
            }
            chain.push_back(std::move(m));
        }
        return chain;
    }

    void addMesh(int node, int meshIndex, const Affine& world, const std::string& where, std::vector<Mesh>& into) {
        const tinygltf::Mesh& mesh = model_.meshes[std::size_t(meshIndex)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
            addPrimitive(node, meshIndex, int(p), world,
                         where + ", mesh " + std::to_string(meshIndex) + " ('" + clampName(mesh.name) + "') primitive " +
                             std::to_string(p),
                         into);
    }

    void addPrimitive(int, int meshIndex, int primIndex, const Affine& world, const std::string& where,
                      std::vector<Mesh>& into) {
        const tinygltf::Primitive& p = model_.meshes[std::size_t(meshIndex)].primitives[std::size_t(primIndex)];
        if (p.mode != -1 && p.mode != TINYGLTF_MODE_TRIANGLES) {
            warnOnce("primitives with mode " + std::to_string(p.mode) + " (not TRIANGLES) are skipped");
            return;
        }
        std::uint32_t materialIndex;
        if (p.material < 0) {
            materialIndex = defaultMaterial();
        } else if (std::size_t(p.material) < model_.materials.size()) {
            materialIndex = std::uint32_t(p.material);
        } else {
            throw Error(where + ": material " + std::to_string(p.material) + " does not exist");
        }
        const LocalPrimitive* local = decode(meshIndex, primIndex, where);
        if (!local || local->indices.empty()) return;
        outVertices_ += local->positions.size();
        outIndices_ += local->indices.size();
        if (outVertices_ > kMaxOutputVertices || outIndices_ > kMaxOutputIndices)
            throw Error(name_ + ": the scene expands to more than " + std::to_string(kMaxOutputIndices / 3) +
                        " triangles (through node instancing)");

        Mesh m;
        const tinygltf::Mesh& gm = model_.meshes[std::size_t(meshIndex)];
        m.name = (gm.name.empty() ? "mesh " + std::to_string(meshIndex) : gm.name) + "/" + std::to_string(primIndex);
        m.material = materialIndex;
        m.positions.resize(local->positions.size());
        for (std::size_t i = 0; i < local->positions.size(); ++i) {
            m.positions[i] = world.point(local->positions[i]);
            if (!isFinite(m.positions[i]))
                throw Error(where + ": vertex " + std::to_string(i) + " is not finite after the node transform");
        }
        const float det = world.determinant();
        m.normals.resize(local->normals.size());
        for (std::size_t i = 0; i < local->normals.size(); ++i) {
            const Vec3 t = world.normal(local->normals[i]);
            m.normals[i] = isFinite(t) ? t : Vec3{};
        }
        m.uvs = local->uvs;
        m.indices = local->indices;
        if (det < 0)  // mirrored: keep counter-clockwise front faces
            for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) std::swap(m.indices[t + 1], m.indices[t + 2]);
        dropBadTriangles(m, skipped_);
        if (!m.indices.empty()) into.push_back(std::move(m));
    }

    static constexpr std::uint32_t kNoPrototype = 0xffffffffu;
    struct PendingMesh {
        int node;
        int mesh;
        Affine world;
        std::string where;
        std::vector<int> path;  // root to node, when a node on it is animated (else empty)
    };
    std::vector<PendingMesh> pending_;  // mesh uses in traversal order, placed by placeMeshes
    struct NodeTracks {
        Track translation, rotation, scale;
    };
    std::map<int, NodeTracks> animated_;  // by node
    std::vector<int> path_;               // the node being visited and its ancestors, root first

    const Model& model_;
    std::string name_;
    SkippedFaces skipped_;
    Scene scene_;
    int defaultMaterial_ = -1;
    bool cameraSet_ = false;
    std::map<std::pair<int, bool>, int> imageCache_;
    std::map<std::pair<int, int>, std::unique_ptr<LocalPrimitive>> primCache_;
    std::set<std::string> warned_;
    std::size_t outVertices_ = 0, outIndices_ = 0;
};

}  // namespace

Scene loadGltfFromMemory(std::string_view bytes, const std::filesystem::path& baseDir, const std::string& name) {
    const tinygltf::Model model = gltf::parseModel(bytes, baseDir, name);
    return GltfImporter(model, name).run();
}

Scene loadGltf(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error("cannot open glTF file '" + path.string() + "': " +
                    (std::filesystem::exists(path, ec) ? "it is not a regular file" : "no such file"));
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw Error("cannot read '" + path.string() + "': " + ec.message());
    if (size > gltf::kMaxFileBytes) throw Error("'" + path.string() + "' is larger than 2 GiB");
    std::ifstream in(path, std::ios::binary);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    if (!in || !in.read(bytes.data(), static_cast<std::streamsize>(size))) throw Error("cannot read '" + path.string() + "'");
    return loadGltfFromMemory(bytes, path.parent_path(), path.filename().string());
}

}  // namespace penumbra
