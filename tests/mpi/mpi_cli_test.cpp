// penumbra under real mpirun processes, on lavapipe (docs/DISTRIBUTED.md): one image on three
// ranks equals the one-process image, a sequence's frames are each rendered once, a killed rank
// ends the job and --resume renders exactly the missing frames, bad use is one line, not a hang.
// Sizes are tiny: three ranks share the machine's cores.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <thread>

#include "cli_fixture.h"
#include "image/exr_layers.h"

namespace penumbra::test {
namespace {

// Every mpirun gets this long; a hang fails the test instead of the suite.
constexpr int kTimeoutSeconds = 240;
constexpr const char* kSmall = "render cornell --width 24 --height 16 --bounces 4 ";

class MpiTest : public CliTest {
protected:
    // "mpirun ... penumbra" with the flags this machine needs: root in containers, more ranks
    // than cores, no single-copy shared memory (containers often forbid ptrace), and quiet
    // (-q: no Open MPI banners, so penumbra's own line is all a failure prints).
    std::string mpirun(int ranks, bool quiet = true) const {
        std::string cmd = std::string("env PENUMBRA_DEVICE=") + device() +
                          " PENUMBRA_VALIDATION=1 OMPI_MCA_btl_vader_single_copy_mechanism=none timeout " +
                          std::to_string(kTimeoutSeconds) + " " + PENUMBRA_MPIRUN + " --oversubscribe";
        if (::geteuid() == 0) cmd += " --allow-run-as-root";
        if (quiet) cmd += " -q";
        return cmd + " -np " + std::to_string(ranks) + " '" + penumbraBinary() + "' ";
    }
    static const char* device() {
        const char* d = std::getenv("PENUMBRA_TEST_DEVICE");
        return d ? d : "llvmpipe";
    }
    // `command` is everything after "cd dir &&"; output lands in stdout.txt and stderr.txt.
    RunResult shell(const std::string& command) {
        const std::string cmd = "cd '" + dir.string() + "' && " + command + " >stdout.txt 2>stderr.txt";
        const int status = std::system(cmd.c_str());
        RunResult r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "stderr.txt"), slurp(dir / "stdout.txt")};
        fs::remove(dir / "stderr.txt");
        fs::remove(dir / "stdout.txt");
        EXPECT_NE(r.exitCode, 124) << "timed out: " << command << "\n" << r.err;
        return r;
    }
    RunResult runMpi(int ranks, const std::string& args, bool quiet = true) {
        return shell(mpirun(ranks, quiet) + args);
    }

    // Files whose names say a write was cut short.
    std::vector<fs::path> leftovers() {
        std::vector<fs::path> out;
        for (const fs::path& p : filesIn(dir))
            if (p.filename().string().find(".tmp.") != std::string::npos || p.extension() == ".state") out.push_back(p);
        return out;
    }

    // Frame numbers of the "penumbra: frame N ..." lines, each with how often it was reported.
    static std::map<int, int> framesReported(const std::string& err) {
        std::map<int, int> frames;
        const std::regex line(R"(penumbra: frame (\d+) \()");
        for (auto it = std::sregex_iterator(err.begin(), err.end(), line); it != std::sregex_iterator(); ++it)
            ++frames[std::stoi((*it)[1])];
        return frames;
    }
};

ExrChannels readBeauty(const fs::path& p) { return readExrChannels(p); }

// The largest per-channel difference between two renders, relative to the larger value (plus a
// floor for black pixels).
double worstRelativeDifference(const fs::path& a, const fs::path& b) {
    const ExrChannels x = readBeauty(a), y = readBeauty(b);
    EXPECT_EQ(x.width, y.width);
    EXPECT_EQ(x.height, y.height);
    double worst = 0;
    for (const char* c : {"R", "G", "B"}) {
        const std::vector<float>& u = x.channels.at(c);
        const std::vector<float>& v = y.channels.at(c);
        EXPECT_EQ(u.size(), v.size());
        for (std::size_t i = 0; i < std::min(u.size(), v.size()); ++i)
            worst = std::max(worst, std::abs(double(u[i]) - v[i]) / (std::max(std::abs(u[i]), std::abs(v[i])) + 1e-6));
    }
    return worst;
}

// The pass sums are float on the GPU: 16 or fewer non-negative samples per sum lose at most
// about 16 * 2^-24 ~ 1e-6 of the total, so 1e-5 is float summation order and nothing else.
// The control (another seed) differs by far more, so the comparison can fail.
TEST_F(MpiTest, ImageOnThreeRanksEqualsOneProcess) {
    const std::string args = std::string(kSmall) + "--spp 16 --seed 7 -q ";
    const RunResult one = run(args + "-o one.exr");
    ASSERT_EQ(one.exitCode, 0) << one.err;
    const RunResult control = run(std::string(kSmall) + "--spp 16 --seed 8 -q -o control.exr");
    ASSERT_EQ(control.exitCode, 0) << control.err;
    const RunResult three = runMpi(3, args + "-o three.exr");
    ASSERT_EQ(three.exitCode, 0) << three.err;
    EXPECT_LT(worstRelativeDifference(dir / "three.exr", dir / "one.exr"), 1e-5);
    EXPECT_GT(worstRelativeDifference(dir / "control.exr", dir / "one.exr"), 1e-2);
    EXPECT_TRUE(leftovers().empty());
}

// Adaptive sampling: every round's sums are summed on every rank, so all ranks plan the next
// round alike and the image is the one-process image (rounds of 16 passes; from 32 samples on,
// converged tiles skip rounds: the samples layer shows they did, on both).
TEST_F(MpiTest, AdaptiveImageOnThreeRanksEqualsOneProcess) {
    const std::string args = std::string(kSmall) + "--spp 48 --noise-threshold 0.5 --seed 5 --aov samples -q ";
    const RunResult one = run(args + "-o one.exr");
    ASSERT_EQ(one.exitCode, 0) << one.err;
    const RunResult three = runMpi(3, args + "-o three.exr");
    ASSERT_EQ(three.exitCode, 0) << three.err;
    EXPECT_LT(worstRelativeDifference(dir / "three.exr", dir / "one.exr"), 1e-5);
    const std::vector<float> samplesOne = readExrChannels(dir / "one.exr").channels.at("samples.N");
    EXPECT_EQ(readExrChannels(dir / "three.exr").channels.at("samples.N"), samplesOne);
    EXPECT_LT(*std::min_element(samplesOne.begin(), samplesOne.end()), 48.0f) << "no tile skipped a round";
}

TEST_F(MpiTest, SequenceOnThreeRanksRendersEachFrameOnce) {
    const RunResult r = runMpi(3, std::string(kSmall) + "--spp 2 --frames 0..5 -o f_%d.png");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::map<int, int> frames = framesReported(r.err);
    EXPECT_EQ(frames.size(), 6u) << r.err;
    std::set<std::string> ranks;
    const std::regex rank(R"(on rank (\d+) )");
    for (auto it = std::sregex_iterator(r.err.begin(), r.err.end(), rank); it != std::sregex_iterator(); ++it)
        ranks.insert((*it)[1]);
    EXPECT_GE(ranks.size(), 2u) << "frames go to whichever rank is free: " << r.err;
    for (int f = 0; f < 6; ++f) {
        EXPECT_EQ(frames.count(f) ? frames.at(f) : 0, 1) << "frame " << f << "\n" << r.err;
        EXPECT_TRUE(fs::is_regular_file(dir / ("f_" + std::to_string(f) + ".png"))) << f;
    }
    EXPECT_TRUE(leftovers().empty());
}

// The rank of an mpirun child: its environment says OMPI_COMM_WORLD_RANK, its command line
// names this test's folder.
pid_t findRank(const fs::path& marker, int rank) {
    for (const auto& e : fs::directory_iterator("/proc")) {
        const std::string name = e.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        std::ifstream cmdline(e.path() / "cmdline"), environ(e.path() / "environ");
        std::string args((std::istreambuf_iterator<char>(cmdline)), {}), env((std::istreambuf_iterator<char>(environ)), {});
        if (args.find(marker.string()) == std::string::npos) continue;
        if (env.find(std::string("OMPI_COMM_WORLD_RANK=") + std::to_string(rank) + '\0') == std::string::npos) continue;
        return pid_t(std::stoi(name));
    }
    return -1;
}

TEST_F(MpiTest, KilledRankEndsTheJobAndResumeRendersOnlyTheMissingFrames) {
    // The output pattern carries the folder, so this test's ranks can be told from others'.
    const std::string pattern = (dir / "k_%d.exr").string();
    const std::string args = std::string(kSmall) + "--spp 4 --frames 0..5 -o '" + pattern + "'";
    const pid_t job = ::fork();
    ASSERT_GE(job, 0);
    if (job == 0) {
        const std::string cmd = "cd '" + dir.string() + "' && " + mpirun(3, false) + args + " >kill_out.txt 2>kill_err.txt";
        ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // Kill rank 2 as soon as the first frame is written: the other frames are then still being
    // rendered or not yet handed out.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kTimeoutSeconds);
    auto framesDone = [&] {
        int n = 0;
        for (int f = 0; f < 6; ++f) n += fs::exists(dir / ("k_" + std::to_string(f) + ".exr"));
        return n;
    };
    while (framesDone() == 0 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const pid_t victim = findRank(dir, 2);
    ASSERT_GT(victim, 0) << "rank 2 not found";
    ASSERT_EQ(::kill(victim, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(job, &status, 0), job);
    const std::string err = slurp(dir / "kill_err.txt");
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0 && WEXITSTATUS(status) != 124) << err;
    // mpirun's own notice names the rank, the host and the signal.
    EXPECT_NE(err.find("rank 2"), std::string::npos) << err;
    EXPECT_NE(err.find("signal 9"), std::string::npos) << err;
    EXPECT_TRUE(leftovers().empty()) << "a killed job leaves no partial files";

    std::map<fs::path, std::pair<ino_t, long>> before;
    for (int f = 0; f < 6; ++f) {
        const fs::path p = dir / ("k_" + std::to_string(f) + ".exr");
        struct stat st{};
        if (::stat(p.c_str(), &st) == 0) before[p] = {st.st_ino, long(st.st_mtim.tv_nsec) + long(st.st_mtim.tv_sec) * 1000000000L};
    }
    ASSERT_GE(before.size(), 1u);
    ASSERT_LT(before.size(), 6u) << "the kill came too late to test --resume: " << err;

    const RunResult again = runMpi(3, args + " --resume '" + pattern + "'");
    ASSERT_EQ(again.exitCode, 0) << again.err;
    const std::map<int, int> rendered = framesReported(again.err);
    for (int f = 0; f < 6; ++f) {
        const fs::path p = dir / ("k_" + std::to_string(f) + ".exr");
        struct stat st{};
        ASSERT_EQ(::stat(p.c_str(), &st), 0) << p;
        if (before.count(p)) {
            EXPECT_EQ(rendered.count(f), 0u) << "finished frame " << f << " rendered again\n" << again.err;
            EXPECT_EQ(before[p].first, st.st_ino) << "finished frame " << f << " rewritten";
        } else {
            EXPECT_EQ(rendered.count(f) ? rendered.at(f) : 0, 1) << "missing frame " << f << "\n" << again.err;
        }
    }
    EXPECT_NE(again.err.find(std::to_string(before.size()) + " finished frames were skipped"), std::string::npos)
        << again.err;
}

// Ranks started with different commands (mpirun's colon form).
TEST_F(MpiTest, MismatchedOptionsAreOneLine) {
    const std::string small = std::string(kSmall) + "-o m.png ";
    const RunResult r = shell(mpirun(2) + small + "--spp 2 : -np 1 '" + penumbraBinary() + "' " + small + "--spp 4");
    expectOneLineError(r, 2, "rank 2 on ");
    EXPECT_NE(r.err.find("differ from rank 0"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "m.png"));
}

TEST_F(MpiTest, SceneMissingOnOneRankIsOneLine) {
    const std::string tail = " --width 8 --height 8 --spp 1 -o m.png";
    const RunResult r = shell(mpirun(2) + "render cornell" + tail + " : -np 1 '" + penumbraBinary() + "' render nosuch.obj" + tail);
    expectOneLineError(r, 1, "rank 2 on ");
    EXPECT_NE(r.err.find("nosuch.obj"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "m.png"));
}

TEST_F(MpiTest, BadDeviceOnEveryRankIsOneLine) {
    expectOneLineError(runMpi(3, std::string(kSmall) + "--spp 1 --device 97 -o m.png"), 2, "no Vulkan device matches '97'");
}

TEST_F(MpiTest, BadFlagIsOneLine) { expectOneLineError(runMpi(3, "render --frames 5..2"), 2, "--frames"); }

// A rank that fails mid-sequence (its frame's file cannot be written) ends the job with one line
// naming it, and leaves no partial file.
TEST_F(MpiTest, FailureWhileRenderingEndsTheJobWithOneLine) {
    fs::create_directories(dir / "w_3.png");  // frame 3's file is a folder
    const RunResult r = runMpi(3, std::string(kSmall) + "--spp 1 --frames 0..5 -o w_%d.png");
    EXPECT_NE(r.exitCode, 0);
    std::size_t errors = 0;
    for (std::size_t at = r.err.find("penumbra: error: "); at != std::string::npos; at = r.err.find("penumbra: error: ", at + 1))
        ++errors;
    EXPECT_EQ(errors, 1u) << r.err;
    EXPECT_TRUE(std::regex_search(r.err, std::regex(R"(penumbra: error: rank \d on [^:]+: cannot write '[^']*w_3\.png')")))
        << r.err;
    EXPECT_TRUE(leftovers().empty());
}

TEST_F(MpiTest, InfoListsEveryRank) {
    const RunResult r = runMpi(3, "info");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (int rank = 0; rank < 3; ++rank)
        EXPECT_TRUE(std::regex_search(r.out, std::regex("rank " + std::to_string(rank) + R"( of 3 on \S+ \(local rank \d\): device \d+, )")))
            << r.out;
}

}  // namespace
}  // namespace penumbra::test
