// penumbra serve [SCENE]: the viewer in a browser (src/serve/, docs/SERVE.md).
#include <memory>
#include <thread>

#include "app/commands.h"
#include "app/common_options.h"
#include "core/error.h"
#include "serve/server.h"

namespace penumbra::app {
namespace {

struct ServeArgs {
    std::string scene = "cornell";
    std::string map;
    CameraOverrides camera;
    EnvironmentSpec env;
    WadOptions wad;
    serve::ServeOptions options;
    std::string debug = "none";
    bool denoise = false;
    int port = 8080;
};

// Tokens go into URLs as they are: letters, digits and - _ . ~ need no escaping.
void checkToken(const std::string& token) {
    if (token.size() > 256) throw UsageError("--token is longer than 256 characters");
    for (char c : token)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.' && c != '~')
            throw UsageError("--token may hold only letters, digits and - _ . ~ (it goes into the URL as it is)");
}

void checkArgs(ServeArgs& a) {
    serve::ServeOptions& o = a.options;
    if (a.port < 0 || a.port > 65535) throw UsageError("--port must be between 0 and 65535 (0: any free port)");
    o.port = static_cast<unsigned short>(a.port);
    if (o.width < 16 || o.height < 16 || o.width > 8192 || o.height > 8192)
        throw UsageError("--width and --height must be between 16 and 8192");
    if (o.view.samplesPerFrame < 1 || o.view.samplesPerFrame > 64)
        throw UsageError("--spp must be between 1 and 64 samples per frame");
    if (o.view.maxBounces < 1 || o.view.maxBounces > 32) throw UsageError("--bounces must be between 1 and 32");
    if (o.encode.restQuality < 1 || o.encode.restQuality > 100 || o.encode.motionQuality < 1 ||
        o.encode.motionQuality > 100)
        throw UsageError("--quality and --motion-quality must be between 1 and 100");
    if (o.encode.threads < 1 || o.encode.threads > 64) throw UsageError("--encode-threads must be between 1 and 64");
    if (!(o.pace.maxFps >= 0 && o.pace.maxFps <= 1000) || !(o.pace.restFps >= 0 && o.pace.restFps <= 1000))
        throw UsageError("--max-fps and --rest-fps must be between 0 (no limit) and 1000");
    checkToken(o.token);
    const std::optional<DebugView> debug = debugViewFromName(a.debug);
    if (!debug) throw UsageError("--debug: no debug view '" + a.debug + "'");
    o.view.debug = *debug;
    o.view.denoise = a.denoise;
    checkViewSettingRanges(o.view);
}

void runServe(ServeArgs args) {
    checkArgs(args);
    Scene scene;
    try {
        scene = loadScene(args.scene, args.map, args.camera, nullptr, args.env, args.wad);
    } catch (const UsageError&) {
        throw;
    } catch (const Error& e) {
        throw UsageError(e.what());  // nothing listens yet: a scene that cannot load is exit code 2
    }
    args.options.view.apertureRadius = scene.camera.apertureRadius;
    args.options.view.focusDistance = scene.camera.focusDistance;
    serve::runServer(std::move(scene), args.options);
}

}  // namespace

void registerServe(CLI::App& app, Action& action) {
    auto a = std::make_shared<ServeArgs>();
    serve::ServeOptions& o = a->options;
    CLI::App* cmd = app.add_subcommand("serve", "serve the live viewer to web browsers (no display needed; docs/SERVE.md)");
    cmd->add_option("scene", a->scene, sceneArgumentHelp());
    cmd->add_option("--map", a->map, "level of a .wad file, e.g. E1M1 or MAP01 (default: the first)");
    cmd->add_option("--port", a->port, "TCP port (default 8080; 0: any free port, printed)");
    cmd->add_option("--bind", o.bind, "address to listen on (default 127.0.0.1; 0.0.0.0 reaches other machines)");
    cmd->add_option("--token", o.token, "a secret the URL must carry (?token=...); wise with --bind 0.0.0.0");
    cmd->add_option("--width", o.width, "picture width at resolution scale 1 (default 1280)");
    cmd->add_option("--height", o.height, "picture height (default 720)");
    cmd->add_option("--spp", o.view.samplesPerFrame, "samples per pixel per frame (default 1)");
    cmd->add_option("--bounces", o.view.maxBounces, "bounces per path (default 8)");
    cmd->add_flag("--denoise", a->denoise, "start with the a-trous denoiser on");
    cmd->add_option("--debug", a->debug, "start in a debug view: normals, albedo, depth, motion, samples, nodes, triangles, boxes, leaf-depth, leaf-triangles");
    cmd->add_flag("--fly", o.fly, "start in free flight on Doom levels (F toggles walking)");
    addPhantomOption(*cmd, a->options.phantom);
    addViewSettingOptions(*cmd, o.view);
    cmd->add_option("--quality", o.encode.restQuality, "JPEG quality while nothing moves (default 85)");
    cmd->add_option("--motion-quality", o.encode.motionQuality, "JPEG quality while the camera moves (default 50)");
    cmd->add_option("--encode-threads", o.encode.threads, "CPU threads encoding each frame's strips (default 4)");
    cmd->add_option("--max-fps", o.pace.maxFps, "frames sent per second while moving, at most (default 60; 0: every frame rendered)");
    cmd->add_option("--rest-fps", o.pace.restFps, "frames sent per second at rest, at most (default 15; 0: every frame rendered)");
    addDeviceOption(*cmd, o.device);
    addBvhCacheOption(*cmd);
    addCameraOptions(*cmd, a->camera);
    addEnvironmentOptions(*cmd, a->env);
    addWadOptions(*cmd, a->wad);
    cmd->callback([a, &action] { action = [a] { runServe(*a); }; });
}

}  // namespace penumbra::app
