// Exceptions inside, exit codes at the edge: only this function catches.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/environment_settings.h"
#include "core/error.h"
#include "core/log.h"
#include "distributed/launch.h"

int main(int argc, char** argv) {
    CLI::App app{"penumbra: a GPU path tracer on Vulkan compute"};
    app.require_subcommand(1);
    bool verbose = false;
    app.add_flag("-v,--verbose", verbose, "print more about what happens");
    penumbra::app::Action action;
    penumbra::app::registerRender(app, action);
    penumbra::app::registerInfo(app, action);
    penumbra::app::registerBench(app, action);
    penumbra::app::registerExport(app, action);
    penumbra::app::registerCompare(app, action);
    penumbra::app::registerServe(app, action);
#ifdef PENUMBRA_HAVE_VIEWER
    penumbra::app::registerView(app, action);
#endif
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // Under mpirun every rank parses the same command: one of them says what is wrong.
        if (penumbra::distributed::launchFromEnvironment().rank != 0) return 2;
        std::fprintf(stderr, "penumbra: error: %s; run 'penumbra --help' for usage\n", e.what());
        return 2;
    }
    penumbra::setVerbose(verbose);
    try {
        penumbra::app::applyEnvironmentSettings();
        penumbra::app::configureBvhCache();
        action();
        return 0;
    } catch (const penumbra::distributed::Reported& e) {
        return e.exitCode;  // a rank of an MPI job, whose error rank 0 printed
    } catch (const penumbra::UsageError& e) {
        std::fprintf(stderr, "penumbra: error: %s\n", e.what());
        return 2;
    } catch (const penumbra::Interrupted& e) {
        std::fprintf(stderr, "penumbra: error: %s\n", e.what());
        return e.exitCode;
    } catch (const penumbra::Error& e) {
        std::fprintf(stderr, "penumbra: error: %s\n", e.what());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "penumbra: error: out of memory; try a smaller image or scene\n");
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "penumbra: error: %s\n", e.what());
        return 1;
    }
}
