// The penumbra executable run as a user runs it, in a scratch folder: exit code, standard error
// and standard output, on lavapipe (or PENUMBRA_TEST_DEVICE) with validation on. The one run
// helper of the CLI, environment and viewer tests.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "binary_path.h"

namespace penumbra::test {

struct RunResult {
    int exitCode;     // -1 when the process did not exit normally
    std::string err;  // standard error
    std::string out;  // standard output
};

inline std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Runs penumbra in `dir` with `args`. `env` is a prefix of VAR=value assignments; `wrapper` a
// command that starts penumbra (e.g. "xvfb-run -a").
inline RunResult runPenumbra(const std::filesystem::path& dir, const std::string& args, const std::string& env = "",
                             const std::string& wrapper = "") {
    const char* device = std::getenv("PENUMBRA_TEST_DEVICE");
    const std::string cmd = "cd '" + dir.string() + "' && env PENUMBRA_DEVICE=" + (device ? device : "llvmpipe") +
                            " PENUMBRA_VALIDATION=1 " + env + " " + wrapper + " '" + penumbraBinary() + "' " + args +
                            " >stdout.txt 2>stderr.txt";
    const int status = std::system(cmd.c_str());
    RunResult result{WIFEXITED(status) ? WEXITSTATUS(status) : -1, readText(dir / "stderr.txt"),
                     readText(dir / "stdout.txt")};
    std::filesystem::remove(dir / "stderr.txt");
    std::filesystem::remove(dir / "stdout.txt");
    return result;
}

}  // namespace penumbra::test
