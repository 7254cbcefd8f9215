// The penumbra executable run as a user runs it, in a scratch folder: exit code, standard error
// and standard output, on lavapipe (or PENUMBRA_TEST_DEVICE) with validation on.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "gpu_fixture.h"
#include "run_penumbra.h"

namespace penumbra::test {

namespace fs = std::filesystem;

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
    RunResult run(const std::string& args, const std::string& env = "") { return runPenumbra(dir, args, env); }

    static void expectOneLineError(const RunResult& r, int code, const std::string& mentions) {
        EXPECT_EQ(r.exitCode, code) << r.err;
        EXPECT_EQ(r.err.rfind("penumbra: error: ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(mentions), std::string::npos) << "expected '" << mentions << "' in: " << r.err;
    }

    static std::string slurp(const fs::path& path) { return readText(path); }

    std::vector<fs::path> filesIn(const fs::path& d) {
        std::vector<fs::path> out;
        for (const auto& e : fs::recursive_directory_iterator(d)) out.push_back(e.path());
        return out;
    }

    fs::path dir;
};


}  // namespace penumbra::test
