#include <gtest/gtest.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>
#include <limits>

#include "core/error.h"
#include "image/write.h"
#include "test_dir.h"

namespace penumbra {
namespace {

using test::TempDir;

ImageRgb gradient(int w, int h) {
    ImageRgb img(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            // Values that float16 could not hold exactly, so a half-float EXR would fail.
            img.at(x, y) = {0.1f * static_cast<float>(x) + 1e-4f, 3.14159f * static_cast<float>(y),
                            -0.333333f + 1e5f * static_cast<float>(x * y)};
        }
    }
    return img;
}

TEST(FormatFromPath, ByExtensionCaseInsensitive) {
    EXPECT_EQ(formatFromPath("out.png"), ImageFormat::Png);
    EXPECT_EQ(formatFromPath("dir/OUT.PNG"), ImageFormat::Png);
    EXPECT_EQ(formatFromPath("a.b/render.Exr"), ImageFormat::Exr);
    EXPECT_EQ(formatFromPath("x.jpg"), ImageFormat::Jpeg);
    EXPECT_EQ(formatFromPath("x.JPEG"), ImageFormat::Jpeg);
    EXPECT_EQ(formatFromPath("x.tga"), ImageFormat::Tga);
    EXPECT_EQ(formatFromPath("x.bmp"), ImageFormat::Bmp);
    EXPECT_EQ(formatFromPath("x.hdr"), ImageFormat::Hdr);
    EXPECT_TRUE(isLinearFormat(ImageFormat::Hdr));
    EXPECT_FALSE(isLinearFormat(ImageFormat::Jpeg));
    EXPECT_THROW(formatFromPath("x.gif"), UsageError);
    EXPECT_THROW(formatFromPath("png"), UsageError);
    EXPECT_THROW(formatFromPath("dir.png/noext"), UsageError);
    try {
        formatFromPath("x.gif");
    } catch (const UsageError& e) {
        EXPECT_STREQ(e.what(),
                     "cannot tell the image format of 'x.gif': use a .png or .exr file name (or .jpg, .tga, .bmp, .hdr)");
    }
}

// The 8-bit formats hold the same tone-mapped pixels as the PNG (JPEG within its compression).
TEST(EightBitFormats, HoldThePngsPixels) {
    TempDir dir;
    ImageRgb img(9, 6);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 9; ++x) img.at(x, y) = {0.05f * float(x), 0.2f * float(y), 0.5f};  // smooth: JPEG-friendly
    for (const char* name : {"a.png", "a.tga", "a.bmp", "a.jpg"}) writeImage(dir / name, img, {});
    auto load = [&](const char* name) {
        int w = 0, h = 0, n = 0;
        unsigned char* data = stbi_load((dir / name).c_str(), &w, &h, &n, 3);
        EXPECT_NE(data, nullptr) << name;
        EXPECT_EQ(w, 9);
        EXPECT_EQ(h, 6);
        std::vector<int> out(data, data + (data ? 9 * 6 * 3 : 0));
        stbi_image_free(data);
        return out;
    };
    const std::vector<int> png = load("a.png");
    EXPECT_EQ(load("a.tga"), png);
    EXPECT_EQ(load("a.bmp"), png);
    const std::vector<int> jpg = load("a.jpg");
    ASSERT_EQ(jpg.size(), png.size());
    for (std::size_t i = 0; i < png.size(); ++i) EXPECT_NEAR(jpg[i], png[i], 12) << i;
}

TEST(Hdr, HoldsLinearRadianceToRgbePrecision) {
    TempDir dir;
    ImageRgb img = gradient(7, 5);
    for (Vec3& p : img.pixels) p = Vec3{std::abs(p.x), std::abs(p.y) + 1e-3f, std::abs(p.z) + 1.0f};
    writeImage(dir / "a.hdr", img, {.exposure = 3});  // exposure must not touch linear data
    int w = 0, h = 0, n = 0;
    float* data = stbi_loadf((dir / "a.hdr").c_str(), &w, &h, &n, 3);
    ASSERT_NE(data, nullptr);
    ASSERT_EQ(w, 7);
    ASSERT_EQ(h, 5);
    for (int i = 0; i < 7 * 5; ++i) {
        // RGBE: 8-bit mantissas under the largest channel's exponent.
        const float largest = std::max({img.pixels[i].x, img.pixels[i].y, img.pixels[i].z});
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(data[3 * i + c], img.pixels[i][c], largest / 128.0f) << i << "," << c;
    }
    stbi_image_free(data);
}

TEST(Exr, RoundTripIsExactForFloat32) {
    TempDir dir;
    ImageRgb img = gradient(7, 5);  // odd sizes catch row/column mix-ups
    img.at(0, 0) = {std::numeric_limits<float>::min(), 65504.0f * 4, 1e-30f};
    writeImage(dir / "a.exr", img, {.exposure = 3});  // exposure must not touch EXR data
    ImageRgb back = readExr(dir / "a.exr");
    ASSERT_EQ(back.width, 7);
    ASSERT_EQ(back.height, 5);
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 7; ++x) {
            EXPECT_EQ(back.at(x, y), img.at(x, y)) << x << "," << y;
        }
    }
}

TEST(Exr, ReadMissingOrBadFileThrowsError) {
    TempDir dir;
    EXPECT_THROW(readExr(dir / "missing.exr"), Error);
    test::writeAll(dir / "bad.exr", "not an exr file");
    try {
        readExr(dir / "bad.exr");
        FAIL() << "no exception";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.exr"), std::string::npos) << e.what();
    }
}

TEST(Png, WrittenBytesReadBack) {
    TempDir dir;
    ImageRgb img(3, 2);
    img.at(0, 0) = {0, 0, 0};
    img.at(1, 0) = {1, 1, 1};
    img.at(2, 0) = {std::numeric_limits<float>::infinity(), 0, 0};
    img.at(0, 1) = {0.25f, 0.5f, 3.0f};
    img.at(1, 1) = {std::numeric_limits<float>::quiet_NaN(), 0.1f, 0.01f};
    img.at(2, 1) = {100, 0, 1};
    ToneMapSettings settings{.exposure = 0.5f};
    writeImage(dir / "a.png", img, settings);

    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load((dir / "a.png").c_str(), &w, &h, &n, 3);
    ASSERT_NE(data, nullptr);
    ASSERT_EQ(w, 3);
    ASSERT_EQ(h, 2);
    auto expected = toneMapToSrgb8(img, settings);
    EXPECT_EQ(std::memcmp(data, expected.data(), expected.size()), 0);
    EXPECT_EQ(data[0 * 3], 0);    // black stays black
    EXPECT_EQ(data[2 * 3], 255);  // +inf red is white-hot red
    EXPECT_EQ(data[4 * 3], 0);    // NaN red is 0
    stbi_image_free(data);
}

TEST(WriteImage, MissingDirectoryThrowsAndLeavesNothing) {
    TempDir dir;
    for (const char* name : {"a.png", "a.exr"}) {
        try {
            writeImage(dir / "no_such_dir" / name, gradient(2, 2), {});
            FAIL() << "no exception";
        } catch (const Error& e) {
            std::string msg = e.what();
            EXPECT_NE(msg.find("no_such_dir"), std::string::npos) << msg;
            EXPECT_NE(msg.find("No such file or directory"), std::string::npos) << msg;
            EXPECT_NE(msg.find("writable"), std::string::npos) << msg;
        }
    }
    EXPECT_TRUE(dir.entries().empty());
}

TEST(WriteImage, ReplacesExistingFileAndLeavesNoTemp) {
    TempDir dir;
    test::writeAll(dir / "a.exr", "old contents");
    writeImage(dir / "a.exr", gradient(2, 2), {});
    EXPECT_EQ(readExr(dir / "a.exr").at(1, 1), gradient(2, 2).at(1, 1));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.exr"});
}

TEST(WriteImage, UnknownExtensionIsUsageErrorBeforeAnyFile) {
    TempDir dir;
    EXPECT_THROW(writeImage(dir / "a.gif", gradient(2, 2), {}), UsageError);
    EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace penumbra
