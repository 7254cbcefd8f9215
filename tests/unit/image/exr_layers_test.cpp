// Multi-layer EXR: channels written are read back exactly under the names compositors expect.
#include "image/exr_layers.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "image/write.h"
#include "test_dir.h"

namespace penumbra {
namespace {

TEST(ExrLayers, ChannelsRoundTripExactly) {
    test::TempDir dir;
    const int w = 5, h = 3;
    ImageRgb beauty(w, h), albedo(w, h);
    for (int i = 0; i < w * h; ++i) {
        beauty.pixels[i] = Vec3{float(i), 1e-8f * float(i), 65504.0f * 4};
        albedo.pixels[i] = Vec3{0.25f, 0.5f, float(i) / 15};
    }
    std::vector<ExrChannel> channels;
    appendRgbChannels(channels, beauty);
    appendRgbChannels(channels, albedo, "albedo");
    appendRgbChannels(channels, albedo, "N", "XYZ");
    channels.push_back({"Z", std::vector<float>(w * h, 1e10f)});
    writeExrChannels(dir / "a.exr", w, h, channels);

    const ExrChannels read = readExrChannels(dir / "a.exr");
    EXPECT_EQ(read.width, w);
    EXPECT_EQ(read.height, h);
    std::vector<std::string> names;
    for (const auto& [name, values] : read.channels) names.push_back(name);
    EXPECT_EQ(names, (std::vector<std::string>{"B", "G", "N.X", "N.Y", "N.Z", "R", "Z", "albedo.B", "albedo.G",
                                               "albedo.R"}));
    for (const ExrChannel& c : channels) EXPECT_EQ(read.channels.at(c.name), c.values) << c.name;  // float32, lossless
    EXPECT_EQ(read.channels.at("G")[7], 7e-8f);
}

// The files `render --aov` writes: readExr (used by --compare references, bench and the tests)
// reads their beauty, which tinyexr's single-layer reader refused.
TEST(ExrLayers, ReadExrTakesTheBeautyOfAMultiLayerFile) {
    test::TempDir dir;
    const int w = 4, h = 3;
    ImageRgb beauty(w, h), albedo(w, h, Vec3{0.25f, 0.5f, 0.75f});
    for (int i = 0; i < w * h; ++i) beauty.pixels[i] = Vec3{float(i), 2.0f * float(i) + 1e-7f, 1e4f};
    std::vector<ExrChannel> channels;
    appendRgbChannels(channels, albedo, "albedo");
    appendRgbChannels(channels, beauty);
    appendRgbChannels(channels, albedo, "N", "XYZ");
    channels.push_back({"Z", std::vector<float>(w * h, 3.0f)});
    writeExrChannels(dir / "aov.exr", w, h, channels);
    const ImageRgb back = readExr(dir / "aov.exr");
    ASSERT_EQ(back.width, w);
    ASSERT_EQ(back.height, h);
    EXPECT_EQ(back.pixels, beauty.pixels);

    // A layered file with no unprefixed beauty (Blender's "ViewLayer.Combined.R" ...): the layer.
    channels.clear();
    appendRgbChannels(channels, albedo, "ViewLayer.Denoising Albedo");
    appendRgbChannels(channels, beauty, "ViewLayer.Combined");
    writeExrChannels(dir / "blender.exr", w, h, channels);
    EXPECT_EQ(readExr(dir / "blender.exr").pixels, beauty.pixels);

    channels = {{"Z", std::vector<float>(w * h, 1.0f)}};
    writeExrChannels(dir / "depth.exr", w, h, channels);
    try {
        readExr(dir / "depth.exr");
        FAIL() << "a depth-only file has no image";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no R, G, B or Y"), std::string::npos) << e.what();
    }
}

TEST(ExrLayers, BeautyChannelsPreferRgbThenYThenTheFirstLayer) {
    using Names = std::vector<std::string>;
    using Rgb = std::array<std::string, 3>;
    EXPECT_EQ(beautyChannels(Names{"A", "B", "G", "R", "albedo.R", "albedo.G", "albedo.B"}), (Rgb{"R", "G", "B"}));
    EXPECT_EQ(beautyChannels(Names{"Y", "A"}), (Rgb{"Y", "Y", "Y"}));
    EXPECT_EQ(beautyChannels(Names{"b.R", "b.G", "b.B", "a.R", "a.G", "a.B"}), (Rgb{"a.R", "a.G", "a.B"}));
    EXPECT_EQ(beautyChannels(Names{"R", "G", "Z", "n.R", "n.G"}), std::nullopt);
}

TEST(ExrLayers, UnreadableFilesAreOneErrorNamingThem) {
    test::TempDir dir;
    std::ofstream(dir / "bad.exr") << "not an exr";
    try {
        readExrChannels(dir / "bad.exr");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.exr"), std::string::npos) << e.what();
    }
    EXPECT_THROW(readExrChannels(dir / "missing.exr"), Error);
}

}  // namespace
}  // namespace penumbra
