#include "scene/io/scene_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/log.h"
#include "core/transform.h"
#include "scene/animation.h"
#include "scene/face_check.h"
#include "scene/io/env_spec.h"
#include "scene/instances.h"
#include "scene/io/load.h"
#include "scene/merge.h"
#include "scene/presets/presets.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

using Json = nlohmann::json;

// Scene files may include scene files; this bounds the nesting (and catches cycles).
constexpr int kMaxNesting = 8;
thread_local int g_nesting = 0;

// Reading with context: every error names the file and the JSON path of the bad value.
class Reader {
public:
    explicit Reader(std::string file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw Error(file_ + ": " + where + ": " + what);
    }

    const Json& member(const Json& obj, const char* key, const std::string& where) const {
        if (!obj.is_object() || !obj.contains(key)) fail(where, std::string("missing \"") + key + "\"");
        return obj.at(key);
    }

    float number(const Json& v, const std::string& where, float lo = -1e30f, float hi = 1e30f) const {
        if (!v.is_number()) fail(where, "expected a number");
        double d = v.get<double>();
        if (!std::isfinite(d) || d < lo || d > hi)
            fail(where, "must be a finite number between " + fmt(lo) + " and " + fmt(hi));
        return float(d);
    }

    Vec3 vec3(const Json& v, const std::string& where, float lo = -1e30f, float hi = 1e30f) const {
        if (!v.is_array() || v.size() != 3) fail(where, "expected an array of three numbers");
        return {number(v[0], where + "[0]", lo, hi), number(v[1], where + "[1]", lo, hi), number(v[2], where + "[2]", lo, hi)};
    }

    std::string string(const Json& v, const std::string& where) const {
        if (!v.is_string()) fail(where, "expected a string");
        return v.get<std::string>();
    }

    std::uint32_t count(const Json& v, const std::string& where, std::uint32_t hi) const {
        if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > hi)
            fail(where, "must be a whole number between 1 and " + std::to_string(hi));
        return std::uint32_t(v.get<long long>());
    }

private:
    static std::string fmt(float x) {
        std::ostringstream s;
        s << x;
        return s.str();
    }
    std::string file_;
};

Affine readTransform(const Reader& r, const Json& asset, const std::string& where) {
    Affine t;
    if (asset.contains("scale")) {
        const Json& s = asset["scale"];
        Vec3 v = s.is_number() ? Vec3{r.number(s, where + ".scale")} : r.vec3(s, where + ".scale");
        if (v.x == 0 || v.y == 0 || v.z == 0) r.fail(where + ".scale", "must not be zero");
        t = Affine::scaling(v);
    }
    if (asset.contains("rotate")) t = Affine::eulerDegrees(r.vec3(asset["rotate"], where + ".rotate")) * t;
    if (asset.contains("translate")) t = Affine::translation(r.vec3(asset["translate"], where + ".translate")) * t;
    return t;
}

void readMaterial(const Reader& r, const Json& j, const std::string& where, Material& m) {
    if (j.contains("albedo")) m.albedo = r.vec3(j["albedo"], where + ".albedo", 0, 1);
    if (j.contains("emission")) m.emission = r.vec3(j["emission"], where + ".emission", 0, 1e9f);
    if (j.contains("metallic")) m.metallic = r.number(j["metallic"], where + ".metallic", 0, 1);
    if (j.contains("roughness")) m.roughness = r.number(j["roughness"], where + ".roughness", 0, 1);
    if (j.contains("ior")) m.ior = r.number(j["ior"], where + ".ior", 1, 4);
    if (j.contains("transmission")) m.transmission = r.number(j["transmission"], where + ".transmission", 0, 1);
    if (j.contains("opacity")) m.opacity = r.number(j["opacity"], where + ".opacity", 0, 1);
    if (j.contains("specular")) m.specular = r.number(j["specular"], where + ".specular", 0, 1);
    if (j.contains("absorptionColor"))
        m.absorptionColor = r.vec3(j["absorptionColor"], where + ".absorptionColor", 0, 1);
    if (j.contains("absorptionDistance"))
        m.absorptionDistance = r.number(j["absorptionDistance"], where + ".absorptionDistance", 0, 1e9f);
}

template <typename T, typename F>
std::vector<T> readFlat(const Reader& r, const Json& j, const std::string& where, std::size_t arity, F make) {
    if (!j.is_array() || j.size() % arity != 0)
        r.fail(where, "expected a flat array whose length is a multiple of " + std::to_string(arity));
    std::vector<T> out;
    out.reserve(j.size() / arity);
    for (std::size_t i = 0; i < j.size(); i += arity) out.push_back(make(i));
    return out;
}

// The first material called `material`; `where` names the reference, for the error.
std::uint32_t findMaterial(const Reader& r, const std::string& material, const std::string& where, const Scene& scene) {
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name == material) return std::uint32_t(i);
    r.fail(where, "no material named '" + material + "'");
}

std::uint32_t readMaterialRef(const Reader& r, const Json& j, const std::string& where, const Scene& scene) {
    return findMaterial(r, r.string(r.member(j, "material", where), where + ".material"), where + ".material", scene);
}

Mesh readInlineMesh(const Reader& r, const Json& j, const std::string& where, const Scene& scene) {
    Mesh m;
    if (j.contains("name")) m.name = r.string(j["name"], where + ".name");
    m.material = readMaterialRef(r, j, where, scene);
    const Json& p = r.member(j, "positions", where);
    m.positions = readFlat<Vec3>(r, p, where + ".positions", 3, [&](std::size_t i) {
        return Vec3{r.number(p[i], where + ".positions"), r.number(p[i + 1], where + ".positions"),
                    r.number(p[i + 2], where + ".positions")};
    });
    const Json& idx = r.member(j, "indices", where);
    m.indices = readFlat<std::uint32_t>(r, idx, where + ".indices", 1, [&](std::size_t i) {
        if (!idx[i].is_number_unsigned() || idx[i].get<std::uint64_t>() >= m.positions.size())
            r.fail(where + ".indices[" + std::to_string(i) + "]", "must index one of the " +
                                                                    std::to_string(m.positions.size()) + " positions");
        return std::uint32_t(idx[i].get<std::uint64_t>());
    });
    if (m.indices.size() % 3) r.fail(where + ".indices", "length must be a multiple of 3");
    if (j.contains("normals")) {
        const Json& n = j["normals"];
        m.normals = readFlat<Vec3>(r, n, where + ".normals", 3, [&](std::size_t i) {
            return Vec3{r.number(n[i], where + ".normals"), r.number(n[i + 1], where + ".normals"),
                        r.number(n[i + 2], where + ".normals")};
        });
    }
    if (j.contains("uvs")) {
        const Json& uv = j["uvs"];
        m.uvs = readFlat<Vec2>(r, uv, where + ".uvs", 2, [&](std::size_t i) {
            return Vec2{r.number(uv[i], where + ".uvs"), r.number(uv[i + 1], where + ".uvs")};
        });
    }
    return m;
}

Sphere readSphere(const Reader& r, const Json& j, const std::string& where, const Scene& scene) {
    Sphere sphere;
    sphere.center = r.vec3(r.member(j, "center", where), where + ".center");
    sphere.radius = r.number(r.member(j, "radius", where), where + ".radius", 1e-6f, 1e9f);
    sphere.material = readMaterialRef(r, j, where, scene);
    return sphere;
}

// A bounded plane: four corners in order around the edge, as two triangles; the front (emitting)
// face is the one from which they run counter-clockwise.
Mesh readQuad(const Reader& r, const Json& j, const std::string& where, const Scene& scene) {
    Mesh m;
    m.name = j.contains("name") ? r.string(j["name"], where + ".name") : "quad";
    m.material = readMaterialRef(r, j, where, scene);
    const Json& corners = r.member(j, "corners", where);
    if (!corners.is_array() || corners.size() != 4) r.fail(where + ".corners", "expected an array of four [x,y,z] points");
    for (std::size_t k = 0; k < 4; ++k) m.positions.push_back(r.vec3(corners[k], where + ".corners[" + std::to_string(k) + "]"));
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

// An asset's "material": every mesh and sphere the asset brought takes it. Resolved once the
// file's "materials" are read, since they may define it.
struct AssetMaterial {
    std::string material;
    std::string where;
    std::size_t meshBegin, meshEnd, sphereBegin, sphereEnd;
    std::size_t prototypeBegin = 0, prototypeEnd = 0;
};

Scene loadAsset(const Reader& r, const Json& a, const std::string& where, const std::filesystem::path& baseDir) {
    if (a.contains("preset")) return makePreset(r.string(a["preset"], where + ".preset"));
    std::filesystem::path file = r.string(r.member(a, "file", where), where + ".file");
    if (file.is_relative()) file = baseDir / file;
    LoadOptions options;
    if (a.contains("map")) options.map = r.string(a["map"], where + ".map");
    return loadSceneFile(file, options);
}

// "motion": {"path": [[x,y,z], ...], "speed": m/s, "repeat": "loop" | "back_and_forth" | "once",
// "spin": {"axis": [x,y,z], "degrees_per_second": d}} (docs/SCENES.md "Motions").
ScriptedMotion readMotion(const Reader& r, const Json& j, const std::string& where) {
    if (!j.is_object()) r.fail(where, "expected an object with \"path\" and \"speed\", or \"spin\"");
    for (const auto& [key, value] : j.items())
        if (key != "path" && key != "speed" && key != "repeat" && key != "spin")
            r.fail(where + "." + key, "unknown key (a motion has path, speed, repeat and spin)");
    ScriptedMotion m;
    if (j.contains("path")) {
        const Json& path = j["path"];
        if (!path.is_array() || path.size() > 100'000) r.fail(where + ".path", "expected an array of up to 100,000 [x,y,z] offsets");
        for (std::size_t i = 0; i < path.size(); ++i)
            m.path.push_back(r.vec3(path[i], where + ".path[" + std::to_string(i) + "]", -1e9f, 1e9f));
        if (m.path.size() >= 2) m.speed = r.number(r.member(j, "speed", where), where + ".speed", 1e-6f, 1e9f);
    }
    if (j.contains("repeat")) {
        const std::string repeat = r.string(j["repeat"], where + ".repeat");
        if (repeat == "loop") m.repeat = MotionRepeat::Loop;
        else if (repeat == "back_and_forth") m.repeat = MotionRepeat::BackAndForth;
        else if (repeat == "once") m.repeat = MotionRepeat::Once;
        else r.fail(where + ".repeat", "must be \"loop\", \"back_and_forth\" or \"once\" (got \"" + repeat + "\")");
    }
    if (j.contains("spin")) {
        const Json& spin = j["spin"];
        const std::string at = where + ".spin";
        m.spinDegreesPerSecond = r.number(r.member(spin, "degrees_per_second", at), at + ".degrees_per_second", -1e6f, 1e6f);
        if (spin.contains("axis")) m.spinAxis = r.vec3(spin["axis"], at + ".axis", -1e9f, 1e9f);
        if (!(length(m.spinAxis) > 1e-6f)) r.fail(at + ".axis", "must not be zero");
        m.spinAxis = normalize(m.spinAxis);
    }
    return m;
}

// An asset with "instances": its meshes become one prototype (stored once, one bottom-level BVH)
// placed by each entry's transform after the asset's own; instances the asset already has (a
// scene file's, a glTF's shared meshes) are placed with it.
void placeInstances(const Reader& r, const Json& a, const Json& list, const std::string& listWhere, Scene part,
                    const Affine& transform, Scene& scene, const std::optional<ScriptedMotion>& assetMotion = {}) {
    if (!list.is_array() || list.empty() || list.size() > 10'000'000)
        r.fail(listWhere, "expected an array of 1 to 10,000,000 placements ({\"scale\", \"rotate\", \"translate\"})");
    if (!part.spheres.empty() || !part.sprites.empty() || !part.lights.empty())
        r.fail(listWhere, "instances and motions place meshes only, and this asset also has spheres, sprites or "
                          "lights; place it with one asset per copy instead, or move only its meshes");
    const auto materialBase = static_cast<std::uint32_t>(scene.materials.size());
    const auto prototypeBase = static_cast<std::uint32_t>(scene.prototypes.size());
    std::vector<Prototype> prototypes = std::move(part.prototypes);
    std::vector<Instance> inner = std::move(part.instances);
    std::vector<InstanceAnimation> innerAnimations = std::move(part.instanceAnimations);
    part.instanceAnimations.clear();
    std::vector<bool> innerAnimated(inner.size(), false);
    for (const InstanceAnimation& moving : innerAnimations)
        if (moving.instance < inner.size()) innerAnimated[moving.instance] = true;
    const auto own = static_cast<std::uint32_t>(prototypes.size());
    if (!part.meshes.empty())
        prototypes.push_back({a.contains("file") ? a["file"].get<std::string>() : a["preset"].get<std::string>(),
                              std::move(part.meshes)});
    part.prototypes.clear();
    part.instances.clear();
    part.meshes.clear();
    appendScene(scene, std::move(part), Affine{});  // materials and textures only
    for (Prototype& p : prototypes) {
        for (Mesh& m : p.meshes) m.material += materialBase;
        scene.prototypes.push_back(std::move(p));
    }
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string at = listWhere + "[" + std::to_string(i) + "]";
        if (!list[i].is_object()) r.fail(at, "expected an object");
        const Affine placed = readTransform(r, list[i], at) * transform;
        // The placement, moved by the entry's "motion" when it has one: the top of every chain.
        NodeMotion placement;
        placement.fixed = placed;
        placement.scripted = assetMotion;
        if (list[i].contains("motion")) placement.scripted = readMotion(r, list[i]["motion"], at + ".motion");
        const bool moves = placement.scripted.has_value();
        // Every instance the entry places keeps its own copy of the path: bound what a short
        // file can make us hold.
        if (moves && placement.scripted->path.size() * (inner.size() + 1) > 10'000'000)
            r.fail(at + ".motion.path", "too long for an asset that places " + std::to_string(inner.size() + 1) +
                                           " instances (at most 10,000,000 path points in all)");
        if (own < prototypes.size()) {
            if (moves) scene.instanceAnimations.push_back({std::uint32_t(scene.instances.size()), {placement}});
            scene.instances.push_back({prototypeBase + own, placed});
        }
        const auto innerBase = static_cast<std::uint32_t>(scene.instances.size());
        for (std::size_t k = 0; k < inner.size(); ++k) {
            if (moves && !innerAnimated[k]) {  // an animated one gets the motion on top of its chain below
                NodeMotion local;
                local.fixed = inner[k].transform;
                scene.instanceAnimations.push_back({innerBase + std::uint32_t(k), {placement, local}});
            }
            scene.instances.push_back({prototypeBase + inner[k].prototype, placed * inner[k].transform});
        }
        for (InstanceAnimation moving : innerAnimations) {  // each copy keeps moving, under its placement
            moving.instance += innerBase;
            moving.chain.insert(moving.chain.begin(), placement);
            scene.instanceAnimations.push_back(std::move(moving));
        }
    }
}

// "assets": each is loaded, transformed and appended; the first one's camera (transformed with
// it), background and environment become the scene's.
std::vector<AssetMaterial> readAssets(const Reader& r, const Json& doc, const std::filesystem::path& baseDir,
                                      Scene& scene) {
    std::vector<AssetMaterial> assetMaterials;
    if (!doc.contains("assets")) return assetMaterials;
    const Json& assets = doc["assets"];
    if (!assets.is_array()) r.fail("assets", "expected an array");
    for (std::size_t i = 0; i < assets.size(); ++i) {
        const std::string where = "assets[" + std::to_string(i) + "]";
        const Json& a = assets[i];
        if (!a.is_object()) r.fail(where, "expected an object");
        Scene part = loadAsset(r, a, where, baseDir);
        const Affine transform = readTransform(r, a, where);
        if (i == 0) {
            scene.camera = transformCamera(part.camera, transform);
            scene.background = part.background;
            scene.environment = part.environment;
        }
        AssetMaterial am{"", where, scene.meshes.size(), 0, scene.spheres.size(), 0, scene.prototypes.size(), 0};
        if (a.contains("instances")) {
            if (a.contains("preset")) r.fail(where + ".instances", "instances place a \"file\" asset, not a preset");
            if (a.contains("motion"))
                r.fail(where + ".motion", "an asset with \"instances\" moves per instance: give each entry its \"motion\"");
            placeInstances(r, a, a["instances"], where + ".instances", std::move(part), transform, scene);
        } else if (a.contains("motion")) {
            // A moving asset is one instance (its meshes stored once, moved by the top level).
            placeInstances(r, a, Json::array({Json::object()}), where, std::move(part), transform, scene,
                           readMotion(r, a["motion"], where + ".motion"));
        } else {
            appendScene(scene, std::move(part), transform);
        }
        if (a.contains("material")) {
            am.material = r.string(a["material"], where + ".material");
            am.meshEnd = scene.meshes.size();
            am.sphereEnd = scene.spheres.size();
            am.prototypeEnd = scene.prototypes.size();
            assetMaterials.push_back(am);
        }
    }
    return assetMaterials;
}

// "materials": a name that exists overrides the given fields of every material of that name; a
// new name defines a material.
void readMaterials(const Reader& r, const Json& mats, Scene& scene) {
    if (!mats.is_array()) r.fail("materials", "expected an array");
    for (std::size_t i = 0; i < mats.size(); ++i) {
        const std::string where = "materials[" + std::to_string(i) + "]";
        std::string matName = r.string(r.member(mats[i], "name", where), where + ".name");
        bool overridden = false;
        for (Material& m : scene.materials)
            if (m.name == matName) readMaterial(r, mats[i], where, m), overridden = true;
        if (!overridden) {
            Material m;
            m.name = matName;
            readMaterial(r, mats[i], where, m);
            scene.materials.push_back(m);
        }
    }
}

void assignAssetMaterials(const Reader& r, const std::vector<AssetMaterial>& assetMaterials, Scene& scene) {
    for (const AssetMaterial& am : assetMaterials) {
        const std::uint32_t id = findMaterial(r, am.material, am.where + ".material", scene);
        for (std::size_t m = am.meshBegin; m < am.meshEnd; ++m) scene.meshes[m].material = id;
        for (std::size_t s = am.sphereBegin; s < am.sphereEnd; ++s) scene.spheres[s].material = id;
        for (std::size_t p = am.prototypeBegin; p < am.prototypeEnd; ++p)
            for (Mesh& m : scene.prototypes[p].meshes) m.material = id;
    }
}

// A material the file writes that no mesh, quad, sphere or asset uses is most likely meant for
// an asset and forgotten: say so rather than render silently without it.
void warnUnusedMaterials(const std::string& file, const Json& mats, const Scene& scene) {
    std::vector<bool> used(scene.materials.size(), false);
    for (const Mesh& m : scene.meshes) used.at(m.material) = true;
    for (const Prototype& p : scene.prototypes)
        for (const Mesh& m : p.meshes) used.at(m.material) = true;
    for (const Sphere& s : scene.spheres) used.at(s.material) = true;
    for (const Sprite& s : scene.sprites) used.at(s.material) = true;
    for (std::size_t i = 0; i < mats.size(); ++i) {
        const std::string matName = mats[i]["name"].get<std::string>();
        bool anyUsed = false;
        for (std::size_t k = 0; k < scene.materials.size(); ++k) anyUsed |= used[k] && scene.materials[k].name == matName;
        if (!anyUsed)
            logWarning(file + ": materials[" + std::to_string(i) + "] ('" + matName +
                       "') is not used by any mesh, quad, sphere or asset; give it to an asset with \"material\": \"" +
                       matName + "\"");
    }
}

Light readLight(const Reader& r, const Json& j, const std::string& where) {
    Light l;
    std::string type = j.contains("type") ? r.string(j["type"], where + ".type") : "point";
    if (type == "point") l.type = LightType::Point;
    else if (type == "spot") l.type = LightType::Spot;
    else if (type == "directional") l.type = LightType::Directional;
    else r.fail(where + ".type", "must be point, spot or directional");
    if (j.contains("name")) l.name = r.string(j["name"], where + ".name");
    if (j.contains("position")) l.position = r.vec3(j["position"], where + ".position");
    if (j.contains("direction")) l.direction = normalize(r.vec3(j["direction"], where + ".direction"));
    if (j.contains("color")) l.color = r.vec3(j["color"], where + ".color", 0, 1e9f);
    if (j.contains("intensity")) l.intensity = r.number(j["intensity"], where + ".intensity", 0, 1e12f);
    if (j.contains("range")) l.range = r.number(j["range"], where + ".range", 0);
    if (j.contains("radius")) l.radius = r.number(j["radius"], where + ".radius", 0);
    if (j.contains("angular_radius")) {
        if (l.type != LightType::Directional) r.fail(where + ".angular_radius", "only directional lights have one");
        l.angularRadius = degreesToRadians(r.number(j["angular_radius"], where + ".angular_radius", 0, 45));
    }
    return l;
}

// "environment": {"file": "x.hdr" | "sky": {...}, "intensity": x, "rotation": degrees}
EnvironmentSpec readEnvironment(const Reader& r, const Json& j, const std::filesystem::path& baseDir) {
    const std::string where = "environment";
    if (!j.is_object()) r.fail(where, "expected an object");
    EnvironmentSpec spec;
    if (j.contains("file") && j.contains("sky")) r.fail(where, "give either \"file\" or \"sky\", not both");
    if (j.contains("file")) {
        std::filesystem::path file = r.string(j["file"], where + ".file");
        if (file.is_relative()) file = baseDir / file;
        spec.file = file.string();
    }
    if (j.contains("sky")) {
        const Json& k = j["sky"];
        if (!k.is_object()) r.fail(where + ".sky", "expected an object");
        SkyParams p;
        if (k.contains("sun_elevation")) p.sunElevationDegrees = r.number(k["sun_elevation"], where + ".sky.sun_elevation", 0, 90);
        if (k.contains("sun_azimuth")) p.sunAzimuthDegrees = r.number(k["sun_azimuth"], where + ".sky.sun_azimuth", -360, 360);
        if (k.contains("turbidity")) p.turbidity = r.number(k["turbidity"], where + ".sky.turbidity", 1.7f, 10);
        if (k.contains("sun_radius")) p.sunRadiusDegrees = r.number(k["sun_radius"], where + ".sky.sun_radius", 0, 45);
        if (k.contains("ground_albedo")) p.groundAlbedo = r.number(k["ground_albedo"], where + ".sky.ground_albedo", 0, 1);
        spec.sky = p;
    }
    if (j.contains("intensity")) spec.intensity = r.number(j["intensity"], where + ".intensity", 0, 1e9f);
    if (j.contains("rotation")) spec.rotationDegrees = r.number(j["rotation"], where + ".rotation", -3600, 3600);
    return spec;
}

}  // namespace

// "camera_path": {"interpolation": "catmull-rom" | "linear", "keys": [{"time", "position",
// "look_at", "fov"?}, ...]}; keys without a fov take the camera's.
CameraPath readCameraPath(const Reader& r, const Json& j, const Camera& camera) {
    if (!j.is_object()) r.fail("camera_path", "expected an object with \"keys\"");
    CameraPath path;
    if (j.contains("interpolation")) {
        const std::string mode = r.string(j["interpolation"], "camera_path.interpolation");
        if (mode == "linear") path.interpolation = PathInterpolation::Linear;
        else if (mode != "catmull-rom") r.fail("camera_path.interpolation", "must be \"catmull-rom\" or \"linear\"");
    }
    const Json& keys = r.member(j, "keys", "camera_path");
    if (!keys.is_array() || keys.empty() || keys.size() > 100000)
        r.fail("camera_path.keys", "expected an array of 1 to 100000 keys");
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const std::string where = "camera_path.keys[" + std::to_string(i) + "]";
        CameraKey k;
        k.time = r.number(r.member(keys[i], "time", where), where + ".time", 0, 1e7f);
        k.position = r.vec3(r.member(keys[i], "position", where), where + ".position");
        k.lookAt = r.vec3(r.member(keys[i], "look_at", where), where + ".look_at");
        k.fovYDegrees = keys[i].contains("fov") ? r.number(keys[i]["fov"], where + ".fov", 0.01f, 179.99f)
                                                : camera.fovYDegrees;
        path.keys.push_back(k);
    }
    try {
        validateCameraPath(path);
    } catch (const Error& e) {
        r.fail("camera_path", e.what());
    }
    return path;
}

namespace {

Json parseDocument(const Reader& r, std::string_view text, const std::string& name) {
    Json doc;
    try {
        doc = Json::parse(text.begin(), text.end());
    } catch (const Json::exception& e) {  // parse errors, and numbers too large for a double
        throw Error(name + ": not valid JSON: " + e.what());
    }
    if (!doc.is_object()) r.fail("top level", "expected an object");
    return doc;
}

// doc[key], when present, is an array: read(element, "key[i]") for each element.
template <class Read>
void forEachInArray(const Reader& r, const Json& doc, const char* key, Read&& read) {
    if (!doc.contains(key)) return;
    const Json& array = doc[key];
    if (!array.is_array()) r.fail(key, "expected an array");
    for (std::size_t i = 0; i < array.size(); ++i) read(array[i], std::string(key) + "[" + std::to_string(i) + "]");
}

// The shapes and lights written in the file itself: "meshes", "quads", "spheres", "lights".
void readInlineGeometry(const Reader& r, const Json& doc, Scene& scene) {
    forEachInArray(r, doc, "meshes", [&](const Json& j, const std::string& where) {
        scene.meshes.push_back(readInlineMesh(r, j, where, scene));
    });
    forEachInArray(r, doc, "quads", [&](const Json& j, const std::string& where) {
        scene.meshes.push_back(readQuad(r, j, where, scene));
    });
    forEachInArray(r, doc, "spheres", [&](const Json& j, const std::string& where) {
        scene.spheres.push_back(readSphere(r, j, where, scene));
    });
    forEachInArray(r, doc, "lights", [&](const Json& j, const std::string& where) {
        scene.lights.push_back(readLight(r, j, where));
    });
}

// "camera": {"position", "look_at", "up", "fov", "aperture", "focus_distance"}, each optional.
void readCamera(const Reader& r, const Json& c, Camera& camera) {
    if (!c.is_object()) r.fail("camera", "expected an object");
    if (c.contains("position")) camera.position = r.vec3(c["position"], "camera.position");
    if (c.contains("look_at")) camera.lookAt = r.vec3(c["look_at"], "camera.look_at");
    if (c.contains("up")) camera.up = r.vec3(c["up"], "camera.up");
    if (c.contains("fov")) camera.fovYDegrees = r.number(c["fov"], "camera.fov", 0.01f, 179.99f);
    if (c.contains("aperture")) camera.apertureRadius = r.number(c["aperture"], "camera.aperture", 0, 1e6f);
    if (c.contains("focus_distance"))
        camera.focusDistance = r.number(c["focus_distance"], "camera.focus_distance", 1e-6f, 1e9f);
}

// "render": {"spp", "bounces", "width", "height", "exposure"}, each optional.
SceneFileSettings readRenderSettings(const Reader& r, const Json& s) {
    SceneFileSettings read;
    if (!s.is_object()) r.fail("render", "expected an object");
    if (s.contains("spp")) read.samplesPerPixel = r.count(s["spp"], "render.spp", 1u << 20);
    if (s.contains("bounces")) read.maxBounces = r.count(s["bounces"], "render.bounces", 1024);
    if (s.contains("width")) read.width = r.count(s["width"], "render.width", 16384);
    if (s.contains("height")) read.height = r.count(s["height"], "render.height", 16384);
    if (s.contains("exposure")) read.exposure = r.number(s["exposure"], "render.exposure", -64, 64);
    return read;
}

// Inline meshes, and assets scaled up, can hold faces the renderer cannot use: they are dropped
// with a warning, and a scene left with nothing to render is an error.
void dropUnusableFaces(Scene& scene, const std::string& name) {
    SkippedFaces skipped;
    for (Mesh& m : scene.meshes) dropBadTriangles(m, skipped);
    for (Prototype& p : scene.prototypes)
        for (Mesh& m : p.meshes) dropBadTriangles(m, skipped);
    const bool anyFace = !scene.instances.empty() || std::any_of(scene.meshes.begin(), scene.meshes.end(),
                                                                 [](const Mesh& m) { return !m.indices.empty(); });
    if (!anyFace && scene.spheres.empty() && skipped.total() > 0)
        throw Error(name + ": no face can be rendered: the scene has " + skipped.describe());
    skipped.warn(name);
}

}  // namespace

Scene loadSceneJsonFromText(std::string_view text, const std::filesystem::path& baseDir, const std::string& name,
                            SceneFileSettings* settings) {
    Reader r(name);
    if (g_nesting >= kMaxNesting) r.fail("assets", "scene files nest more than 8 deep (does one include itself?)");
    struct Nest {
        Nest() { ++g_nesting; }
        ~Nest() { --g_nesting; }
    } nest;
    const Json doc = parseDocument(r, text, name);

    Scene scene;
    scene.name = std::filesystem::path(name).stem().string();
    const std::vector<AssetMaterial> assetMaterials = readAssets(r, doc, baseDir, scene);
    if (doc.contains("materials")) readMaterials(r, doc["materials"], scene);
    assignAssetMaterials(r, assetMaterials, scene);
    readInlineGeometry(r, doc, scene);
    if (doc.contains("background")) scene.background = r.vec3(doc["background"], "background", 0, 1e9f);
    if (doc.contains("environment")) {
        try {
            applyEnvironment(scene, readEnvironment(r, doc["environment"], baseDir));
        } catch (const Error& e) {
            r.fail("environment", e.what());
        }
    }
    if (doc.contains("camera")) readCamera(r, doc["camera"], scene.camera);
    if (doc.contains("camera_path")) scene.cameraPath = readCameraPath(r, doc["camera_path"], scene.camera);
    if (doc.contains("render")) {
        // Checked even when the caller does not want them: a bad file is bad either way.
        const SceneFileSettings read = readRenderSettings(r, doc["render"]);
        if (settings) *settings = read;
    }
    if (scene.meshes.empty() && scene.spheres.empty() && scene.instances.empty())
        r.fail("top level", "the scene has no geometry (add \"assets\", \"meshes\", \"quads\" or \"spheres\")");
    dropUnusableFaces(scene, name);
    scene.validate();
    if (doc.contains("materials")) warnUnusedMaterials(name, doc["materials"], scene);
    try {
        validateCamera(scene.camera);
    } catch (const Error& e) {
        r.fail("camera", e.what());
    }
    return scene;
}

Scene loadSceneJson(const std::filesystem::path& path, SceneFileSettings* settings) {
    std::string text = readFileBytes(path, std::size_t(1) << 30);
    return loadSceneJsonFromText(text, path.parent_path(), path.string(), settings);
}

std::string sceneToJson(const Scene& instanced) {
    // Scene files write instances as the world meshes they place.
    Scene scene = instanced;
    bakeAllInstances(scene);
    Json doc;
    auto v3 = [](Vec3 v) { return Json::array({v.x, v.y, v.z}); };
    doc["camera"] = {{"position", v3(scene.camera.position)}, {"look_at", v3(scene.camera.lookAt)},
                     {"up", v3(scene.camera.up)}, {"fov", scene.camera.fovYDegrees}};
    if (scene.camera.apertureRadius > 0) doc["camera"]["aperture"] = scene.camera.apertureRadius;
    if (scene.camera.focusDistance > 0) doc["camera"]["focus_distance"] = scene.camera.focusDistance;
    for (const CameraKey& k : scene.cameraPath.keys)
        doc["camera_path"]["keys"].push_back(
            {{"time", k.time}, {"position", v3(k.position)}, {"look_at", v3(k.lookAt)}, {"fov", k.fovYDegrees}});
    if (!scene.cameraPath.keys.empty())
        doc["camera_path"]["interpolation"] =
            scene.cameraPath.interpolation == PathInterpolation::Linear ? "linear" : "catmull-rom";
    doc["background"] = v3(scene.background);
    if (!scene.textures.empty())
        logWarning("scene '" + scene.name + "' has textures, which scene files do not carry yet; they are left out");
    for (const Material& m : scene.materials)
        doc["materials"].push_back({{"name", m.name}, {"albedo", v3(m.albedo)}, {"emission", v3(m.emission)},
                                    {"metallic", m.metallic}, {"roughness", m.roughness}, {"ior", m.ior},
                                    {"transmission", m.transmission}, {"opacity", m.opacity},
                                    {"specular", m.specular}, {"absorptionColor", v3(m.absorptionColor)},
                                    {"absorptionDistance", m.absorptionDistance}});
    for (const Mesh& mesh : scene.meshes) {
        Json j = {{"name", mesh.name}, {"material", scene.materials.at(mesh.material).name}};
        Json& p = j["positions"] = Json::array();
        for (Vec3 v : mesh.positions) p.insert(p.end(), {v.x, v.y, v.z});
        j["indices"] = mesh.indices;
        if (!mesh.normals.empty()) {
            Json& n = j["normals"] = Json::array();
            for (Vec3 v : mesh.normals) n.insert(n.end(), {v.x, v.y, v.z});
        }
        if (!mesh.uvs.empty()) {
            Json& uv = j["uvs"] = Json::array();
            for (Vec2 v : mesh.uvs) uv.insert(uv.end(), {v.x, v.y});
        }
        doc["meshes"].push_back(j);
    }
    for (const Sphere& sphere : scene.spheres)
        doc["spheres"].push_back({{"center", v3(sphere.center)}, {"radius", sphere.radius},
                                  {"material", scene.materials.at(sphere.material).name}});
    for (const Light& l : scene.lights) {
        const char* type = l.type == LightType::Point ? "point" : (l.type == LightType::Spot ? "spot" : "directional");
        doc["lights"].push_back({{"name", l.name}, {"type", type}, {"position", v3(l.position)},
                                 {"direction", v3(l.direction)}, {"color", v3(l.color)}, {"intensity", l.intensity},
                                 {"range", l.range}, {"radius", l.radius}});
        if (l.type == LightType::Directional && l.angularRadius > 0)
            doc["lights"].back()["angular_radius"] = radiansToDegrees(l.angularRadius);
    }
    const Environment& env = scene.environment;
    if (env.map || env.intensity != 1.0f || env.rotationDegrees != 0.0f) {
        doc["environment"] = {{"intensity", env.intensity}, {"rotation", env.rotationDegrees}};
        if (env.map)
            logWarning("scene '" + scene.name + "' has an environment map, which scene files refer to by file name " +
                       "only; add \"file\" or \"sky\" to \"environment\" by hand");
    }
    return doc.dump(1) + "\n";
}

}  // namespace penumbra
