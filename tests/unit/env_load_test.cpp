// The environment-map loader on tiny files written by the test itself: a hand-encoded flat RGBE
// file (exact values and row order), an RLE file from stb's writer, an EXR from our own writer,
// and the ways a file can be bad.
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <unistd.h>

#include "core/error.h"
#include "image/write.h"
#include "scene/environment.h"
#include "scene/io/env_load.h"
#include "scene/io/env_spec.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

fs::path tempDir() {
    fs::path dir = fs::temp_directory_path() / ("penumbra_env_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

std::string rgbeHeader(int w, int h) {
    return "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(h) + " +X " + std::to_string(w) + "\n";
}

std::string pixel(unsigned char r, unsigned char g, unsigned char b, unsigned char e) { return {char(r), char(g), char(b), char(e)}; }

TEST(EnvLoad, FlatRgbeDecodesExactlyTopRowFirst) {
    // RGBE: value = mantissa * 2^(exponent - 136). Exponent 129: mantissa / 128; 137: x 2.
    std::string file = rgbeHeader(3, 2) + pixel(128, 64, 32, 129) + pixel(0, 0, 0, 0) + pixel(255, 255, 255, 129) +
                       pixel(128, 128, 128, 137) + pixel(1, 2, 3, 136) + pixel(64, 0, 0, 128);
    EnvironmentMap m = decodeEnvironmentMap(file, "flat.hdr");
    ASSERT_EQ(m.width, 3);
    ASSERT_EQ(m.height, 2);
    const Vec3 expected[6] = {{1.0f, 0.5f, 0.25f}, {0, 0, 0}, {255 / 128.0f, 255 / 128.0f, 255 / 128.0f},
                              {256.0f, 256.0f, 256.0f},  {1, 2, 3}, {0.25f, 0, 0}};
    for (int i = 0; i < 6; ++i)
        for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(m.radiance[i][c], expected[i][c]) << "texel " << i << " channel " << c;
}

TEST(EnvLoad, RunLengthHdrFromStbRoundTripsWithinRgbePrecision) {
    const int w = 37, h = 5;  // wide enough (>= 8) that the writer run-length encodes
    std::vector<float> rgb(std::size_t(w) * h * 3);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 50.0f);
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = (i / 3) % 7 == 0 ? 0.0f : u(rng);
    std::string bytes;
    auto append = [](void* ctx, void* data, int size) { static_cast<std::string*>(ctx)->append(static_cast<char*>(data), size); };
    ASSERT_TRUE(stbi_write_hdr_to_func(append, &bytes, w, h, 3, rgb.data()));
    EnvironmentMap m = decodeEnvironmentMap(bytes, "rle.hdr");
    ASSERT_EQ(m.width, w);
    ASSERT_EQ(m.height, h);
    for (std::size_t i = 0; i < m.radiance.size(); ++i) {
        const float maxc = std::max({rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]});
        for (int c = 0; c < 3; ++c)  // a shared exponent: error up to 1/128 of the largest channel
            EXPECT_NEAR(m.radiance[i][c], rgb[3 * i + c], maxc / 128.0f + 1e-6f) << "texel " << i;
    }
}

TEST(EnvLoad, ExrRoundTripsExactlyAndLoadsFromAFile) {
    ImageRgb img(5, 3);
    for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = Vec3{float(i), 0.5f * float(i), 1000.25f};
    const fs::path path = tempDir() / "tiny.exr";
    writeImage(path, img, {});
    EnvironmentMap m = loadEnvironmentMap(path);
    ASSERT_EQ(m.width, 5);
    ASSERT_EQ(m.height, 3);
    for (std::size_t i = 0; i < img.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(m.radiance[i][c], img.pixels[i][c]) << "texel " << i;
}

TEST(EnvLoad, NegativeValuesAreClampedAndNonFiniteRefused) {
    ImageRgb img(2, 1);
    img.pixels[0] = Vec3{-1.0f, 2.0f, 3.0f};
    img.pixels[1] = Vec3{1.0f, 1.0f, 1.0f};
    const fs::path path = tempDir() / "negative.exr";
    writeImage(path, img, {});
    EnvironmentMap m = loadEnvironmentMap(path);
    EXPECT_EQ(m.radiance[0].x, 0.0f);
    EXPECT_EQ(m.radiance[0].y, 2.0f);
    img.pixels[1].y = std::nanf("");
    writeImage(path, img, {});
    try {
        loadEnvironmentMap(path);
        FAIL() << "a NaN pixel was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("pixel 1,0"), std::string::npos) << e.what();
    }
}

void expectRefused(const std::string& bytes, const std::string& needle) {
    try {
        decodeEnvironmentMap(bytes, "bad");
        ADD_FAILURE() << "accepted a bad file; expected an error mentioning '" << needle << "'";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
}

TEST(EnvLoad, BadFilesAreRefusedWithAReason) {
    expectRefused("", "not an environment map");
    expectRefused("GIF89a", "not an environment map");
    expectRefused("\x89PNG\r\n\x1a\n", "not a readable image");  // PNG panoramas are read; this one is cut short
    // Sizes checked before anything is allocated: absurd, and more than the bytes can hold.
    expectRefused(rgbeHeader(100000, 100000) + pixel(1, 1, 1, 128), "sides must be");
    expectRefused(rgbeHeader(4000, 2000) + pixel(1, 1, 1, 128), "more than the file");
    expectRefused(rgbeHeader(3, 2) + pixel(1, 1, 1, 128), "truncated");  // flat pixel data cut short
    // Run-length data cut short (a scanline marker, then nothing).
    expectRefused(rgbeHeader(8, 2) + std::string{2, 2, 0, 8, char(128 + 8), 1}, "corrupt");
    expectRefused("#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n" + pixel(1, 1, 1, 128), "Radiance");
    std::string exr = "\x76\x2f\x31\x01";
    expectRefused(exr + std::string(40, '\0'), "OpenEXR");
}

TEST(EnvLoad, TruncatedExrIsRefused) {
    ImageRgb img(16, 8, Vec3{1, 2, 3});
    const fs::path path = tempDir() / "cut.exr";
    writeImage(path, img, {});
    std::ifstream in(path, std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    for (std::size_t keep : {bytes.size() / 2, bytes.size() - 4, std::size_t(100)}) {
        EXPECT_THROW(decodeEnvironmentMap(bytes.substr(0, keep), "cut.exr"), Error) << "kept " << keep << " bytes";
    }
}

TEST(EnvLoad, SpecAppliesFileIntensityAndRotation) {
    ImageRgb img(4, 2, Vec3{1, 1, 1});
    const fs::path path = tempDir() / "white.exr";
    writeImage(path, img, {});
    Scene scene;
    EnvironmentSpec spec;
    spec.file = path.string();
    spec.intensity = 2.5f;
    spec.rotationDegrees = 90.0f;
    applyEnvironment(scene, spec);
    ASSERT_TRUE(scene.environment.map);
    EXPECT_EQ(scene.environment.map->width, 4);
    EXPECT_EQ(scene.environment.intensity, 2.5f);
    EXPECT_EQ(scene.environment.rotationDegrees, 90.0f);
    EXPECT_FALSE(scene.environment.sun);
    spec.intensity = -1.0f;
    EXPECT_THROW(applyEnvironment(scene, spec), UsageError);
    spec = {};
    spec.file = (tempDir() / "missing.hdr").string();
    EXPECT_THROW(applyEnvironment(scene, spec), Error);
}

}  // namespace
}  // namespace penumbra
