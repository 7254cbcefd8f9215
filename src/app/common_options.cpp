#include "app/common_options.h"

#include <cmath>
#include <sstream>

#include "app/environment_settings.h"
#include "bvh/cache.h"
#include "core/error.h"
#include "scene/io/load.h"
#include "scene/presets/presets.h"

namespace penumbra::app {

std::string sceneArgumentHelp() {
    return "built-in scene (" + presetList() + ") or a " + sceneFileExtensions() + " file (default cornell)";
}

void addDeviceOption(CLI::App& cmd, std::string& device) {
    cmd.add_option("--device", device,
                   "Vulkan device: index from 'penumbra info' or part of its name (default: best; env PENUMBRA_DEVICE)");
}

void addBvhBuildOption(CLI::App& cmd, BvhBuild& where) {
    cmd.add_option_function<std::string>(
        "--bvh-build",
        [&where](const std::string& name) {
            try {
                where = parseBvhBuild(name);
            } catch (const UsageError& e) {  // parse errors are CLI11's while the line is read
                throw CLI::ValidationError(e.what());
            }
        },
        "where the BVH is built: cpu (binned SAH, default) or gpu (Morton codes, radix sort and Karras's hierarchy "
        "in compute shaders; instances' own trees stay the CPU's)");
}

namespace {
bool noBvhCache = false;
}  // namespace

void addBvhCacheOption(CLI::App& cmd) {
    cmd.add_flag("--no-bvh-cache", noBvhCache,
                 "build the BVH afresh instead of reading or writing the on-disk cache "
                 "(folder: PENUMBRA_CACHE_DIR, else XDG_CACHE_HOME/penumbra or ~/.cache/penumbra)");
}

void configureBvhCache() {
    bvh::CacheSettings settings;
    settings.directory = bvhCacheDirectoryFromEnvironment();
    settings.enabled = !noBvhCache && !settings.directory.empty();
    bvh::setCacheSettings(settings);
}

void addCameraOptions(CLI::App& cmd, CameraOverrides& o) {
    cmd.add_option("--camera", o.position, "camera position x,y,z");
    cmd.add_option("--look-at", o.lookAt, "point the camera looks at, x,y,z");
    cmd.add_option("--up", o.up, "camera up vector x,y,z");
    cmd.add_option("--fov", o.fov, "vertical field of view in degrees");
    cmd.add_option("--aperture", o.aperture, "thin-lens aperture radius in metres (0: pinhole, everything sharp)");
    cmd.add_option("--focus-distance", o.focusDistance, "distance in metres along the view direction that is in focus");
    cmd.add_option("--focus-point", o.focusPoint, "point x,y,z to focus on (sets the focus distance to its depth)")
        ->excludes("--focus-distance");
    cmd.add_option("--torch", o.torch, "intensity in candela of a light carried at the camera (0: off; on for WAD levels)");
    cmd.add_option("--torch-color", o.torchColor, "torch colour r,g,b (linear, each in [0, 1])");
    cmd.add_option("--torch-range", o.torchRange, "distance in metres at which the torch fades to nothing (0: unlimited)");
}

void addEnvironmentOptions(CLI::App& cmd, EnvironmentSpec& env) {
    cmd.add_option("--env", env.file,
                   "environment light: an equirectangular .hdr or .exr map, or 'sky' for a procedural sky and sun");
    cmd.add_option("--env-intensity", env.intensity, "multiplies the environment (map, background, sky and its sun)");
    cmd.add_option("--env-rotation", env.rotationDegrees, "turns the environment about +y, in degrees");
}

void addWadOptions(CLI::App& cmd, WadOptions& wad) {
    cmd.add_option("--wad-glow", wad.glow, "Doom levels: scales the light of glowing textures and flats (0: none glow)");
    cmd.add_option("--wad-sector-light", wad.sectorLight,
                   "Doom levels: scales the light that sector light levels give their rooms (0: none)");
    cmd.add_option_function<std::string>(
           "--wad-filter", [&wad](const std::string& name) { wad.filter = name == "bilinear" ? Filter::Linear : Filter::Nearest; },
           "Doom levels: texture lookup, nearest (default: Doom's crisp texels) or bilinear")
        ->check(CLI::IsMember({"nearest", "bilinear"}));
}

Vec3 parseVec3(const std::string& text, const std::string& flag) {
    Vec3 v;
    std::istringstream in(text);
    char c1 = 0, c2 = 0;
    std::string rest;
    if (!(in >> v.x >> c1 >> v.y >> c2 >> v.z) || c1 != ',' || c2 != ',' || (in >> rest) || !isFinite(v))
        throw UsageError(flag + " expects three numbers separated by commas, like 1,2.5,-3 (got '" + text + "')");
    return v;
}

Scene loadScene(const std::string& nameOrPath, const std::string& map, const CameraOverrides& o,
                SceneFileSettings* fileSettings, const EnvironmentSpec& env, const WadOptions& wad) {
    validateWadOptions(wad);
    const std::filesystem::path path(nameOrPath);
    Scene scene = (path.extension() == ".json" && !isPreset(nameOrPath))
                      ? loadSceneJson(path, fileSettings)
                      : loadSceneByName(nameOrPath, LoadOptions{map, wad});
    if (!o.position.empty()) scene.camera.position = parseVec3(o.position, "--camera");
    if (!o.lookAt.empty()) scene.camera.lookAt = parseVec3(o.lookAt, "--look-at");
    if (!o.up.empty()) scene.camera.up = parseVec3(o.up, "--up");
    if (o.fov) scene.camera.fovYDegrees = *o.fov;
    if (o.aperture) scene.camera.apertureRadius = *o.aperture;
    if (o.focusDistance) {
        if (!(*o.focusDistance > 0)) throw UsageError("--focus-distance must be a number of metres > 0");
        scene.camera.focusDistance = *o.focusDistance;
    }
    validateCamera(scene.camera);
    if (!o.focusPoint.empty()) {
        const Vec3 forward = normalize(scene.camera.lookAt - scene.camera.position);
        const float depth = dot(parseVec3(o.focusPoint, "--focus-point") - scene.camera.position, forward);
        if (!(depth > 0)) throw UsageError("--focus-point must lie in front of the camera");
        scene.camera.focusDistance = depth;
    }
    applyEnvironment(scene, env);
    if (o.torch) {
        if (!(*o.torch >= 0 && *o.torch <= 1e9f)) throw UsageError("--torch must be between 0 and 1e9 candela");
        scene.torch.enabled = *o.torch > 0;
        scene.torch.intensity = *o.torch;
    }
    if (!o.torchColor.empty()) {
        const Vec3 c = parseVec3(o.torchColor, "--torch-color");
        if (!(c.x >= 0 && c.x <= 1 && c.y >= 0 && c.y <= 1 && c.z >= 0 && c.z <= 1))
            throw UsageError("--torch-color needs three numbers between 0 and 1, e.g. 1,0.85,0.6");
        scene.torch.color = c;
    }
    if (o.torchRange) {
        if (!(*o.torchRange >= 0 && *o.torchRange <= 1e6f)) throw UsageError("--torch-range must be between 0 and 1e6 metres");
        scene.torch.range = *o.torchRange;
    }
    attachTorch(scene);
    return scene;
}

std::unique_ptr<gpu::Context> openDevice(const std::string& selector) {
    gpu::ContextOptions options;
    options.deviceSelector = selector;
    gpu::ContextResult result = gpu::Context::create(options);
    if (!result.context) throw Error(result.error);
    return std::move(result.context);
}

void addPhantomOption(CLI::App& cmd, bool& phantom) {
    cmd.add_flag_callback("--no-phantom", [&phantom] { phantom = false; },
                          "the dungeon's phantom switched off: not drawn, not moving (H toggles it in the viewer, "
                          "the browser and a walk's events)");
}

void addViewSettingOptions(CLI::App& cmd, ViewSettings& view) {
    cmd.add_option("--resolution-scale", view.resolutionScale,
                   "render at this multiple of the window, 0.25 to 2 (above 1 supersamples; default 1)");
    cmd.add_option("--texture-saturation", view.textureSaturation,
                   "saturation of textures, 0 (grey) to 2; 1 keeps them as they are (default)");
    cmd.add_option("--render-distance", view.renderDistance,
                   "metres across the floor beyond which nothing is drawn (default 0: no limit)");
}

}  // namespace penumbra::app
