// Texture decoding: PNG through stb_image, size limits checked from the header, the checker.
#include <gtest/gtest.h>

#include <cstring>

#include "io_test_util.h"
#include "scene/io/texture_io.h"

namespace penumbra {
namespace {

TEST(TextureIo, DecodesPng) {
    std::string why;
    auto t = loadTextureFile(test::dataDir() / "obj/checker2x2.png", false, &why);
    ASSERT_TRUE(t) << why;
    EXPECT_EQ(t->width, 2);
    EXPECT_EQ(t->height, 2);
    EXPECT_FALSE(t->srgb);
    EXPECT_EQ(t->name, "checker2x2.png");
    const std::uint8_t expected[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    ASSERT_EQ(t->rgba.size(), 16u);
    EXPECT_EQ(std::memcmp(t->rgba.data(), expected, 16), 0);
}

TEST(TextureIo, RefusesGarbageAndMissingFiles) {
    std::string why;
    EXPECT_FALSE(decodeTexture("", "x", true, &why));
    EXPECT_FALSE(decodeTexture("not an image at all", "x", true, &why));
    EXPECT_FALSE(why.empty());
    EXPECT_FALSE(loadTextureFile("/nonexistent/x.png", true, &why));
    EXPECT_NE(why.find("not found"), std::string::npos);
    std::string png = test::readBytes(test::dataDir() / "obj/checker2x2.png");
    EXPECT_FALSE(decodeTexture(png.substr(0, 40), "cut", true, &why));  // truncated
}

TEST(TextureIo, RefusesOversizedImageBeforeDecoding) {
    // A PNG header claiming 100000 x 100000 pixels, with no pixel data.
    std::string png = test::readBytes(test::dataDir() / "obj/checker2x2.png");
    const unsigned char side[4] = {0x00, 0x01, 0x86, 0xA0};
    std::memcpy(&png[16], side, 4);
    std::memcpy(&png[20], side, 4);
    std::string why;
    EXPECT_FALSE(decodeTexture(png, "huge", true, &why));
    EXPECT_NE(why, "");
}

TEST(TextureIo, RefusesTinyFileClaimingHugeImage) {
    // 16000 x 16000 is within kMaxTextureSide, but 75 bytes cannot hold it: no 1 GiB allocation.
    std::string png = test::readBytes(test::dataDir() / "obj/checker2x2.png");
    const unsigned char side[4] = {0x00, 0x00, 0x3E, 0x80};
    std::memcpy(&png[16], side, 4);
    std::memcpy(&png[20], side, 4);
    std::string why;
    EXPECT_FALSE(decodeTexture(png, "claims", true, &why));
    EXPECT_NE(why.find("claims"), std::string::npos) << why;
}

TEST(TextureIo, MissingTextureIsAMagentaChecker) {
    Texture t = missingTexture("lost.png");
    EXPECT_EQ(t.name, "lost.png");
    EXPECT_EQ(t.width, 8);
    EXPECT_EQ(t.height, 8);
    ASSERT_EQ(t.rgba.size(), 8u * 8u * 4u);
    EXPECT_EQ(t.rgba[0], 255);
    EXPECT_EQ(t.rgba[1], 0);
    EXPECT_EQ(t.rgba[2], 255);
    int magenta = 0;
    for (std::size_t i = 0; i < t.rgba.size(); i += 4) magenta += t.rgba[i] == 255;
    EXPECT_EQ(magenta, 32);
}

}  // namespace
}  // namespace penumbra
