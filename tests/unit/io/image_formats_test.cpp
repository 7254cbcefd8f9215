// Image formats beyond stb_image, for textures and environment maps: OpenEXR in every
// compression (DWAA/DWAB written here through the OpenEXR library must load with the same pixels
// as the uncompressed file, within DWA's lossy tolerance), TIFF (8-bit and 32-bit float, written
// here through libtiff), Radiance HDR and PNG panoramas, and malformed files.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <gtest/gtest.h>
#include <tiffio.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "core/error.h"
#include "io_test_util.h"
#include "scene/io/env_load.h"
#include "scene/io/texture_io.h"
#include "shared/color.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

fs::path scratch() {
    const fs::path dir = fs::temp_directory_path() / ("penumbra-image-formats-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

// A smooth sky-like panorama with a bright sun, the kind of content DWA is made for: values from
// 0.05 to about 50.
Vec3 sky(int x, int y, int w, int h) {
    const float u = (float(x) + 0.5f) / float(w), v = (float(y) + 0.5f) / float(h);
    const float base = 0.05f + 1.5f * (1.0f - v) * (0.6f + 0.4f * std::sin(6.2831853f * u));
    const float du = u - 0.3f, dv = v - 0.25f;
    const float sun = 50.0f * std::exp(-(du * du + dv * dv) * 400.0f);
    return {base + sun, 0.9f * base + sun, 1.2f * base + 0.8f * sun};
}

// Writes the panorama as half-float R, G, B (DWA compresses half colour channels lossily; float
// channels it stores losslessly) plus a half A of 0.5.
std::string writeExr(const fs::path& path, int w, int h, Imf::Compression compression) {
    std::vector<Imath::half> r(std::size_t(w) * std::size_t(h)), g(r.size()), b(r.size()), a(r.size(), Imath::half(0.5f));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Vec3 c = sky(x, y, w, h);
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            r[i] = c.x;
            g[i] = c.y;
            b[i] = c.z;
        }
    Imf::Header header(w, h);
    header.compression() = compression;
    Imf::FrameBuffer frame;
    const std::pair<const char*, std::vector<Imath::half>*> channels[] = {{"R", &r}, {"G", &g}, {"B", &b}, {"A", &a}};
    for (auto [name, values] : channels) {
        header.channels().insert(name, Imf::Channel(Imf::HALF));
        frame.insert(name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(values->data()), sizeof(Imath::half),
                                      sizeof(Imath::half) * std::size_t(w)));
    }
    {
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(h);
    }
    return test::readBytes(path);
}

TEST(ExrCompression, DwaEnvironmentMapMatchesTheUncompressedOne) {
    const int w = 128, h = 64;
    const fs::path dir = scratch();
    const EnvironmentMap reference = decodeEnvironmentMap(writeExr(dir / "none.exr", w, h, Imf::NO_COMPRESSION), "none.exr");
    ASSERT_EQ(reference.width, w);
    ASSERT_EQ(reference.height, h);
    EXPECT_NEAR(reference.radiance[0].x, sky(0, 0, w, h).x, 1e-3f * sky(0, 0, w, h).x);  // half precision
    for (auto [compression, label] : {std::pair{Imf::DWAA_COMPRESSION, "DWAA"}, std::pair{Imf::DWAB_COMPRESSION, "DWAB"},
                                      std::pair{Imf::PIZ_COMPRESSION, "PIZ"}, std::pair{Imf::B44_COMPRESSION, "B44"}}) {
        SCOPED_TRACE(label);
        const std::string bytes = writeExr(dir / (std::string(label) + ".exr"), w, h, compression);
        const EnvironmentMap map = decodeEnvironmentMap(bytes, label);
        ASSERT_EQ(map.width, w);
        ASSERT_EQ(map.height, h);
        // DWA quantises DCT coefficients of perceptually encoded values (default level 45): a few
        // per cent per pixel at most on smooth content, far less on average.
        double sumRelative = 0, maxRelative = 0;
        for (std::size_t i = 0; i < map.radiance.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                const double ref = reference.radiance[i][c];
                const double rel = std::abs(map.radiance[i][c] - ref) / ref;
                sumRelative += rel;
                maxRelative = std::max(maxRelative, rel);
            }
        const double meanRelative = sumRelative / double(map.radiance.size() * 3);
        EXPECT_LT(meanRelative, 0.01) << "mean relative error";
        EXPECT_LT(maxRelative, 0.1) << "largest relative error";
        if (compression == Imf::PIZ_COMPRESSION) {
            EXPECT_EQ(maxRelative, 0.0) << "PIZ is lossless";
        }
        if (compression == Imf::DWAB_COMPRESSION) {
            EXPECT_GT(maxRelative, 0.0) << "the file was not DWA compressed";
        }
    }
    fs::remove_all(dir);
}

TEST(ExrCompression, DwaTextureKeepsAlphaAndEncodesSrgb) {
    const fs::path dir = scratch();
    const std::string bytes = writeExr(dir / "t.exr", 16, 8, Imf::DWAB_COMPRESSION);
    std::string why;
    const auto tex = decodeTexture(bytes, "t.exr", true, &why);
    ASSERT_TRUE(tex) << why;
    EXPECT_EQ(tex->width, 16);
    EXPECT_EQ(tex->height, 8);
    // Pixel (3, 7) of the panorama, below 1: sRGB-encoded to within a step or two of DWA's error.
    const Vec3 c = sky(3, 7, 16, 8);
    ASSERT_LT(c.x, 1.0f);
    const std::size_t i = (7 * 16 + 3) * 4;
    EXPECT_NEAR(tex->rgba[i], 255.0f * shader::linearToSrgb(c.x), 3.0f);
    EXPECT_EQ(tex->rgba[i + 3], 128);  // alpha 0.5, linear
    fs::remove_all(dir);
}

// A TIFF written through libtiff: 8-bit RGBA, or 32-bit float RGB.
std::string writeTiff(const fs::path& path, int w, int h, bool floating) {
    TIFF* tif = TIFFOpen(path.c_str(), "w");
    EXPECT_NE(tif, nullptr);
    const int channels = floating ? 3 : 4;
    TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(w));
    TIFFSetField(tif, TIFFTAG_IMAGELENGTH, std::uint32_t(h));
    TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, std::uint16_t(channels));
    TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, std::uint16_t(floating ? 32 : 8));
    TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, std::uint16_t(floating ? SAMPLEFORMAT_IEEEFP : SAMPLEFORMAT_UINT));
    TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, std::uint16_t(PHOTOMETRIC_RGB));
    TIFFSetField(tif, TIFFTAG_PLANARCONFIG, std::uint16_t(PLANARCONFIG_CONTIG));
    TIFFSetField(tif, TIFFTAG_COMPRESSION, std::uint16_t(COMPRESSION_ADOBE_DEFLATE));
    TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, std::uint32_t(2));
    if (!floating) {
        const std::uint16_t extra = EXTRASAMPLE_UNASSALPHA;
        TIFFSetField(tif, TIFFTAG_EXTRASAMPLES, 1, &extra);
    }
    for (int y = 0; y < h; ++y) {
        std::vector<float> rowF;
        std::vector<std::uint8_t> row8;
        for (int x = 0; x < w; ++x) {
            const Vec3 c = sky(x, y, w, h);
            if (floating) {
                rowF.insert(rowF.end(), {c.x, c.y, c.z});
            } else {
                row8.insert(row8.end(), {std::uint8_t(x * 16), std::uint8_t(y * 32), std::uint8_t(200), std::uint8_t(100)});
            }
        }
        EXPECT_EQ(TIFFWriteScanline(tif, floating ? static_cast<void*>(rowF.data()) : row8.data(), std::uint32_t(y), 0), 1);
    }
    TIFFClose(tif);
    return test::readBytes(path);
}

TEST(Tiff, EightBitTextureWithStraightAlpha) {
    const fs::path dir = scratch();
    const std::string bytes = writeTiff(dir / "t.tif", 8, 4, false);
    std::string why;
    const auto tex = decodeTexture(bytes, "t.tif", true, &why);
    ASSERT_TRUE(tex) << why;
    ASSERT_EQ(tex->width, 8);
    ASSERT_EQ(tex->height, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            const std::uint8_t* p = &tex->rgba[std::size_t(y * 8 + x) * 4];
            // Top row first; straight alpha, which libtiff premultiplies and the reader undoes
            // (to within the rounding of 8-bit premultiplied values: 255 / 100 steps).
            EXPECT_NEAR(p[0], x * 16, 1.5);
            EXPECT_NEAR(p[1], y * 32, 1.5);
            EXPECT_NEAR(p[2], 200, 1.5);
            EXPECT_EQ(p[3], 100);
        }
    fs::remove_all(dir);
}

TEST(Tiff, FloatPanoramaIsAnEnvironmentMap) {
    const fs::path dir = scratch();
    const EnvironmentMap map = decodeEnvironmentMap(writeTiff(dir / "sky.tif", 32, 16, true), "sky.tif");
    ASSERT_EQ(map.width, 32);
    ASSERT_EQ(map.height, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x) EXPECT_EQ(map.radiance[std::size_t(y * 32 + x)], sky(x, y, 32, 16));  // float32: exact
    fs::remove_all(dir);
}

TEST(Tiff, MalformedFilesAreRefused) {
    const fs::path dir = scratch();
    std::string bytes = writeTiff(dir / "t.tif", 8, 4, false);
    std::string why;
    for (std::size_t keep : {std::size_t(4), std::size_t(8), std::size_t(20), bytes.size() / 2, bytes.size() - 3}) {
        EXPECT_FALSE(decodeTexture(bytes.substr(0, keep), "cut.tif", true, &why)) << keep;
        EXPECT_EQ(why.find('\n'), std::string::npos) << why;
    }
    EXPECT_THROW(decodeEnvironmentMap(bytes.substr(0, bytes.size() / 2), "cut.tif"), Error);
    EXPECT_THROW(decodeEnvironmentMap(std::string("II*\0", 4) + std::string(100, '\xff'), "junk.tif"), Error);
    fs::remove_all(dir);
}

TEST(LdrPanorama, PngEnvironmentMapIsDecodedToLinear) {
    const EnvironmentMap map =
        decodeEnvironmentMap(test::readBytes(test::dataDir() / "obj/checker2x2.png"), "checker2x2.png");
    ASSERT_EQ(map.width, 2);
    ASSERT_EQ(map.height, 2);
    EXPECT_EQ(map.radiance[0], Vec3(1, 0, 0));  // sRGB 255 and 0 are linear 1 and 0
    EXPECT_EQ(map.radiance[3], Vec3(1, 1, 1));
}

TEST(HdrTexture, RadianceFileBecomesAnSrgbTexture) {
    // 1x1 RGBE: mantissas 128, exponent 128 -> 0.5 in every channel.
    const std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n" + std::string("\x80\x80\x80\x80", 4);
    std::string why;
    const auto tex = decodeTexture(hdr, "one.hdr", true, &why);
    ASSERT_TRUE(tex) << why;
    EXPECT_NEAR(tex->rgba[0], 255.0f * shader::linearToSrgb(0.5f), 0.5f);
    EXPECT_EQ(tex->rgba[3], 255);
}

}  // namespace
}  // namespace penumbra
