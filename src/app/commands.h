// The subcommands; each registers its options on the CLI and returns the action to run.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace penumbra::app {

using Action = std::function<void()>;

void registerRender(CLI::App& app, Action& action);
void registerInfo(CLI::App& app, Action& action);
void registerBench(CLI::App& app, Action& action);
void registerExport(CLI::App& app, Action& action);
void registerCompare(CLI::App& app, Action& action);
void registerServe(CLI::App& app, Action& action);
#ifdef PENUMBRA_HAVE_VIEWER
void registerView(CLI::App& app, Action& action);
#endif

}  // namespace penumbra::app
