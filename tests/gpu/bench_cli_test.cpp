// `penumbra bench --viewer`: the viewer's whole frame, headless, with the JSON keys scripts read.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>

#include "cli_fixture.h"

namespace penumbra::test {
namespace {

using BenchCliTest = CliTest;

const char* kTinyViewer = "bench cornell --viewer --width 64 --height 40 --frames 2 --warmup-frames 0 --warmup-seconds 0 --json";

TEST_F(BenchCliTest, ViewerJsonHasEveryKeyScriptsRead) {
    RunResult r = run(kTinyViewer);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_GT(j.at("viewer_frame_ms").get<double>(), 0.0);
    EXPECT_EQ(j.at("spp").get<int>(), 1);
    EXPECT_EQ(j.at("width").get<int>(), 64);
    EXPECT_EQ(j.at("height").get<int>(), 40);
    EXPECT_EQ(j.at("bounces").get<int>(), 4);
    EXPECT_FALSE(j.at("shared_camera_rays").get<bool>());  // the viewer's default
    // At least the camera ray; every path in the closed box also sends shadow rays.
    EXPECT_GT(j.at("rays_per_pixel_per_sample").get<double>(), 1.0);
    const auto& passes = j.at("passes");
    double sum = 0;
    for (const char* pass : {"trace", "G-buffer", "temporal", "denoise", "tonemap"}) {
        ASSERT_TRUE(passes.contains(pass)) << pass << " missing in " << r.out;
        sum += passes.at(pass).get<double>();
    }
    // The frame's own interval holds every pass (medians of different frames: allow rounding).
    EXPECT_GE(j.at("viewer_frame_ms").get<double>() * 1.05, sum * 0.5);
}

TEST_F(BenchCliTest, ViewerCameraMotionsRunAndBadOnesAreUsageErrors) {
    for (const char* motion : {"orbit", "walk"}) {
        RunResult r = run(std::string(kTinyViewer) + " --camera-motion " + motion);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(nlohmann::json::parse(r.out).at("camera_motion").get<std::string>(), motion);
    }
    expectOneLineError(run(std::string(kTinyViewer) + " --camera-motion spin"), 2, "static, orbit or walk");
    RunResult shared = run(std::string(kTinyViewer) + " --spp 3 --share-camera-rays");
    ASSERT_EQ(shared.exitCode, 0) << shared.err;
    EXPECT_TRUE(nlohmann::json::parse(shared.out).at("shared_camera_rays").get<bool>());
    expectOneLineError(run(std::string(kTinyViewer) + " --denoise 9"), 2, "--denoise");
}

// --bvh-build gpu (docs/RENDERING.md): bench's JSON has the GPU build's time and both SAH costs,
// info says where it was built; a bad name is one line and exit 2 for every command taking it.
TEST_F(BenchCliTest, BvhBuildGpuReportsItsTimeAndSahCosts) {
    RunResult r = run("bench cornell --bvh-build gpu --json --width 32 --height 24 --bounces 1 --repeats 1");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("bvh_build").get<std::string>(), "gpu");
    EXPECT_TRUE(j.at("gpu_bvh_built_on_gpu").get<bool>());
    EXPECT_GE(j.at("gpu_bvh_build_ms").get<double>(), 0.0);
    const double gpuSah = j.at("gpu_bvh_sah_cost").get<double>(), cpuSah = j.at("cpu_bvh_sah_cost").get<double>();
    EXPECT_GT(cpuSah, 0.0);
    EXPECT_NEAR(j.at("gpu_bvh_sah_ratio").get<double>(), gpuSah / cpuSah, 1e-3);
    EXPECT_NEAR(j.at("bvh_sah_cost").get<double>(), gpuSah, 1e-3) << "the traced tree is the GPU's";
    RunResult cpu = run("bench cornell --json --width 32 --height 24 --bounces 1 --repeats 1");
    ASSERT_EQ(cpu.exitCode, 0) << cpu.err;
    const nlohmann::json c = nlohmann::json::parse(cpu.out);
    EXPECT_EQ(c.at("bvh_build").get<std::string>(), "cpu");
    EXPECT_FALSE(c.contains("gpu_bvh_build_ms"));
    RunResult info = run("info cornell --bvh-build gpu");
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("built on the GPU in "), std::string::npos) << info.out;
    for (const char* command : {"info cornell", "bench cornell", "render cornell -o a.png"})
        expectOneLineError(run(std::string(command) + " --bvh-build fpga"), 2, "use cpu or gpu");
}

// The wavefront's tuning variables are checked like flags: a bad value is one line and exit 2.
TEST_F(BenchCliTest, ABadWavefrontTailThresholdIsAUsageError) {
    const std::string render = "render cornell --width 16 --height 12 --spp 1 -o a.png";
    expectOneLineError(run(render, "PENUMBRA_TRACE_KERNEL=wavefront PENUMBRA_WAVE_TAIL_PATHS=lots"), 2,
                       "PENUMBRA_WAVE_TAIL_PATHS");
    expectOneLineError(run(render, "PENUMBRA_TRACE_KERNEL=wavefront PENUMBRA_WAVE_TAIL_PATHS=-5"), 2,
                       "PENUMBRA_WAVE_TAIL_PATHS");
    EXPECT_FALSE(fs::exists(dir / "a.png"));  // nothing written by a refused run
    EXPECT_EQ(run(render, "PENUMBRA_TRACE_KERNEL=wavefront PENUMBRA_WAVE_TAIL_PATHS=0").exitCode, 0);
    EXPECT_TRUE(fs::exists(dir / "a.png"));
}

// The ray benchmark through the wide BVH (what the lead times on the GPU), and `info` reporting
// its size and the memory per triangle.
TEST_F(BenchCliTest, RayBenchRunsTheWideBvhAndInfoReportsIt) {
    RunResult r = run("bench cornell --width 32 --height 20 --repeats 1 --accel wide --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("accel").get<std::string>(), "wide");
    EXPECT_GT(j.at("wide_nodes").get<int>(), 0);
    // Times, not rates: the rates print with one decimal, and 640 rays on a loaded lavapipe can
    // take long enough to print as 0.0 Mrays/s.
    EXPECT_GT(j.at("primary_ms").get<double>(), 0.0);
    EXPECT_GT(j.at("diffuse_ms").get<double>(), 0.0);
    EXPECT_TRUE(j.contains("primary_mrays_per_s") && j.contains("diffuse_mrays_per_s"));
    // Frame statistics: one counted frame's rays, what they hit and what they tested.
    const nlohmann::json& fs = j.at("frame_statistics");
    EXPECT_GE(fs.at("closest_rays").get<long long>(), 32 * 20) << "a camera ray per pixel, at least";
    EXPECT_GT(fs.at("closest_hits").get<long long>(), 0);
    EXPECT_LE(fs.at("closest_hits").get<long long>(), fs.at("closest_rays").get<long long>());
    EXPECT_LE(fs.at("shadow_blocked").get<long long>(), fs.at("shadow_rays").get<long long>());
    EXPECT_GT(fs.at("primitives_tested").get<long long>(), 0);
    EXPECT_FALSE(j.at("cull_backfaces").get<bool>());
    RunResult info = run("info cornell --accel wide");
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("wide bvh (--accel wide): "), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("gpu memory per triangle: binary nodes 0.0, "), std::string::npos)
        << "the wide walk alone should leave the binary nodes on the host\n" << info.out;
    // The binary walk's scene builds no wide tree.
    RunResult binary = run("info cornell");
    ASSERT_EQ(binary.exitCode, 0) << binary.err;
    EXPECT_EQ(binary.out.find("wide bvh"), std::string::npos) << binary.out;
    EXPECT_NE(binary.out.find("wide nodes 0.0, "), std::string::npos) << binary.out;
    expectOneLineError(run("info cornell --accel narrow"), 2, "--accel");
}

// The stackless walk and per-object boxes through the CLI: bench names the walk, its counts show
// the BVH's pruning against the boxes' (the Cornell box's 8 objects: one box test per object per
// ray), and info reports each walk's records.
TEST_F(BenchCliTest, BenchAndInfoTakeTheStacklessAndObjectsWalks) {
    std::map<std::string, nlohmann::json> byWalk;
    for (const char* accel : {"stackless", "objects"}) {
        RunResult r = run(std::string("bench cornell --width 32 --height 20 --repeats 1 --json --accel ") + accel);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        byWalk[accel] = nlohmann::json::parse(r.out);
        EXPECT_EQ(byWalk[accel].at("accel").get<std::string>(), accel);
        EXPECT_GT(byWalk[accel].at("frame_statistics").at("closest_hits").get<long long>(), 0) << accel;
    }
    const nlohmann::json& objects = byWalk["objects"].at("traversal").at("primary");
    EXPECT_DOUBLE_EQ(objects.at("nodes_per_ray").get<double>(), 8.0) << "every object's box, once per ray";
    EXPECT_GT(byWalk["stackless"].at("traversal").at("primary").at("nodes_per_ray").get<double>(), 1.0);
    RunResult info = run("info cornell --accel stackless");
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("stackless (--accel stackless): 33 threaded nodes"), std::string::npos) << info.out;
    info = run("info cornell --accel objects");
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("objects (--accel objects): 8 boxes"), std::string::npos) << info.out;
}

// The walk's work per ray, counted for the rays the bench times: under brute force a closest-hit
// ray tests every primitive exactly once and visits no node; the BVH visits nodes and tests far
// fewer primitives, and no ray kind leaves its warps' lanes more than fully busy.
TEST_F(BenchCliTest, RayBenchCountsTheWalksWork) {
    auto traversal = [&](const std::string& accel) {
        RunResult r = run("bench cornell --width 32 --height 20 --repeats 1 --accel " + accel + " --json");
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return r.exitCode == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
    };
    const nlohmann::json brute = traversal("brute");
    ASSERT_FALSE(brute.is_null());
    const double triangles = brute.at("triangles").get<double>();
    for (const char* kind : {"primary", "diffuse"}) {
        const auto& w = brute.at("traversal").at(kind);
        EXPECT_GT(w.at("rays").get<int>(), 0) << kind;
        EXPECT_EQ(w.at("primitives_per_ray").get<double>(), triangles) << kind;
        EXPECT_EQ(w.at("nodes_per_ray").get<double>(), 0.0) << kind;
    }
    const nlohmann::json bvh = traversal("bvh");
    ASSERT_FALSE(bvh.is_null());
    for (const char* kind : {"primary", "shadow", "diffuse"}) {
        const auto& w = bvh.at("traversal").at(kind);
        EXPECT_GT(w.at("rays").get<int>(), 0) << kind;
        EXPECT_GE(w.at("nodes_per_ray").get<double>(), 1.0) << kind;
        EXPECT_LT(w.at("primitives_per_ray").get<double>(), triangles / 2) << kind;
        EXPECT_GT(w.at("lane_use").get<double>(), 0.0) << kind;
        EXPECT_LE(w.at("lane_use").get<double>(), 1.0) << kind;
    }
    // Every camera ray of the closed box hits it: one primary ray per pixel.
    EXPECT_EQ(bvh.at("traversal").at("primary").at("rays").get<int>(), 32 * 20);
}

// Russian roulette starts where the viewer starts it: bounce 3, bounce 2 on Doom levels (the scene
// asks for it), or where --roulette-start says.
TEST_F(BenchCliTest, ViewerRouletteStartFollowsTheSceneUnlessGiven) {
    auto rouletteStart = [&](const std::string& command) {
        RunResult r = run(command);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return r.exitCode == 0 ? nlohmann::json::parse(r.out).at("roulette_start").get<int>() : -1;
    };
    EXPECT_EQ(rouletteStart(kTinyViewer), 3);
    EXPECT_EQ(rouletteStart(std::string(kTinyViewer) + " --roulette-start 2"), 2);
    const std::string wad = "/usr/share/games/doom/freedoom1.wad";
    if (!std::filesystem::exists(wad)) GTEST_SKIP() << wad << " is not installed (Debian package freedoom)";
    EXPECT_EQ(rouletteStart("bench " + wad + " --map E1M1 --viewer --width 32 --height 20 --frames 1 "
                            "--warmup-frames 0 --warmup-seconds 0 --json"), 2);
}

TEST_F(BenchCliTest, EqualTimeErrorAgainstAReference) {
    ASSERT_EQ(run("render cornell --width 64 --height 40 --spp 64 --quiet -o ref.exr").exitCode, 0);
    RunResult r = run(std::string(kTinyViewer) + " --reference ref.exr --budget-ms 1");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_GE(j.at("budget_frames").get<int>(), 1);
    const double raw = j.at("rel_mse_raw").get<double>(), denoised = j.at("rel_mse_denoised").get<double>();
    EXPECT_GT(raw, 0.0);
    EXPECT_LT(raw, 10.0);  // one noisy frame of the same image, not a different image
    // The denoiser's whole point: much less error than the raw frame it filtered.
    EXPECT_LT(denoised, raw);
    ASSERT_EQ(run("render cornell --width 32 --height 40 --spp 1 --quiet -o small.exr").exitCode, 0);
    expectOneLineError(run(std::string(kTinyViewer) + " --reference small.exr"), 2, "reference");
}

// Trials repeat the measurement from a fresh history with new random numbers: a mean over three
// is not the first trial again (the bench runs the same frames in the same order each time).
TEST_F(BenchCliTest, EqualTimeErrorTrialsSeeNewRandomNumbers) {
    ASSERT_EQ(run("render cornell --width 64 --height 40 --spp 64 --quiet -o ref.exr").exitCode, 0);
    auto rawError = [&](int trials) {
        RunResult r = run(std::string(kTinyViewer) + " --reference ref.exr --budget-ms 1 --error-trials " +
                          std::to_string(trials));
        EXPECT_EQ(r.exitCode, 0) << r.err;
        if (r.exitCode != 0) return -1.0;
        const nlohmann::json j = nlohmann::json::parse(r.out);
        EXPECT_EQ(j.at("error_trials").get<int>(), trials);
        return j.at("rel_mse_raw").get<double>();
    };
    const double one = rawError(1), again = rawError(1), three = rawError(3);
    EXPECT_EQ(one, again);  // deterministic, so a difference below is the trials' own
    EXPECT_GT(three, 0.0);
    EXPECT_NE(three, one);
    expectOneLineError(run(std::string(kTinyViewer) + " --reference ref.exr --error-trials 0"), 2, "--error-trials");
}

// --budget-frames runs exactly that many frames per trial, whatever they cost.
TEST_F(BenchCliTest, EqualFrameErrorRunsTheGivenFrames) {
    ASSERT_EQ(run("render cornell --width 64 --height 40 --spp 16 --quiet -o ref.exr").exitCode, 0);
    RunResult r = run(std::string(kTinyViewer) + " --reference ref.exr --budget-frames 3 --error-trials 2");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out).at("budget_frames").get<int>(), 3);
    expectOneLineError(run(std::string(kTinyViewer) + " --reference ref.exr --budget-frames -1"), 2, "--budget-frames");
}

}  // namespace
}  // namespace penumbra::test
