// penumbra export-scene NAME: a built-in scene as a JSON scene file, to start your own from.
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "app/common_options.h"
#include "core/atomic_file.h"
#include "scene/io/scene_json.h"

namespace penumbra::app {
namespace {

struct ExportArgs {
    std::string scene;
    std::string map;
    std::string output;  // empty: standard output
};

void runExport(const ExportArgs& args) {
    Scene scene = loadScene(args.scene, args.map, {});
    std::string json = sceneToJson(scene);
    if (args.output.empty()) {
        std::fwrite(json.data(), 1, json.size(), stdout);
        return;
    }
    checkWritable(args.output);
    writeBytesAtomically(args.output, std::span(reinterpret_cast<const unsigned char*>(json.data()), json.size()));
}

}  // namespace

void registerExport(CLI::App& app, Action& action) {
    auto args = std::make_shared<ExportArgs>();
    CLI::App* cmd = app.add_subcommand("export-scene", "write a scene as a JSON scene file (see docs/SCENES.md)");
    cmd->add_option("scene", args->scene, "built-in scene or scene file")->required();
    cmd->add_option("--map", args->map, "level of a .wad file");
    cmd->add_option("-o,--output", args->output, "output .json file (default: standard output)");
    cmd->callback([args, &action] { action = [args] { runExport(*args); }; });
}

}  // namespace penumbra::app
