// The penumbra executable run as a user runs it, in a scratch folder: exit code, standard error
// and standard output, on lavapipe (or PENUMBRA_TEST_DEVICE) with validation on.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "binary_path.h"
#include "gpu_fixture.h"

namespace penumbra::test {

namespace fs = std::filesystem;

struct RunResult {
    int exitCode;
    std::string err;
    std::string out;  // standard output
};

class CliTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        dir = fs::temp_directory_path() / ("penumbra-cli-" + std::to_string(::getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override {
        fs::remove_all(dir);
        GpuTest::TearDown();
    }

    // Runs penumbra in `dir` with `args`; env is a prefix of VAR=value assignments.
    RunResult run(const std::string& args, const std::string& env = "") {
        const char* device = std::getenv("PENUMBRA_TEST_DEVICE");
        std::string cmd = "cd '" + dir.string() + "' && env PENUMBRA_DEVICE=" + (device ? device : "llvmpipe") +
                          " PENUMBRA_VALIDATION=1 " + env + " '" + penumbraBinary() + "' " + args +
                          " >stdout.txt 2>stderr.txt";
        int status = std::system(cmd.c_str());
        RunResult result{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "stderr.txt"), slurp(dir / "stdout.txt")};
        fs::remove(dir / "stderr.txt");
        fs::remove(dir / "stdout.txt");
        return result;
    }

    static void expectOneLineError(const RunResult& r, int code, const std::string& mentions) {
        EXPECT_EQ(r.exitCode, code) << r.err;
        EXPECT_EQ(r.err.rfind("penumbra: error: ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(mentions), std::string::npos) << "expected '" << mentions << "' in: " << r.err;
    }

    static std::string slurp(const fs::path& path) {
        std::ifstream in(path);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }

    std::vector<fs::path> filesIn(const fs::path& d) {
        std::vector<fs::path> out;
        for (const auto& e : fs::recursive_directory_iterator(d)) out.push_back(e.path());
        return out;
    }

    fs::path dir;
};


}  // namespace penumbra::test
