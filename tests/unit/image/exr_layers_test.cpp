// Multi-layer EXR: channels written are read back exactly under the names compositors expect.
#include "image/exr_layers.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
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
