// Frames on the wire (serve/frame_message.h): the header the browser's DataView reads, strips
// that survive packing, and a reader that refuses every truncated or padded message.
#include <gtest/gtest.h>

#include "serve/frame_message.h"

namespace penumbra::serve {
namespace {

std::vector<Strip> someStrips() {
    return {{0, 16, std::string("\xff\xd8 first strip", 14)}, {16, 9, "second"}, {25, 1, ""}};
}

std::string message(const FrameInfo& info, std::uint32_t ack, const std::vector<Strip>& strips) {
    const auto header = frameHeader(info, ack, std::uint32_t(strips.size()));
    return std::string(header.begin(), header.end()) + packStrips(strips);
}

TEST(ServeFrameMessage, HeaderIsLittleEndianAtTheDocumentedOffsets) {
    const FrameInfo info{0x01020304, 1280, 800, 3.5f, 1.25f, 85};
    const auto h = frameHeader(info, 0xA0B0C0D0, 4);
    ASSERT_EQ(h.size(), 32u);
    EXPECT_EQ(std::string(h.begin(), h.begin() + 4), "PNF1");
    EXPECT_EQ(h[4], 0x04);
    EXPECT_EQ(h[7], 0x01);
    EXPECT_EQ(h[8] | (h[9] << 8), 1280);
    EXPECT_EQ(h[10] | (h[11] << 8), 800);
    EXPECT_EQ(h[12], 0xD0);
    EXPECT_EQ(h[15], 0xA0);
    EXPECT_EQ(h[28], 4);
}

TEST(ServeFrameMessage, RoundTrips) {
    const FrameInfo info{42, 96, 26, 12.5f, 0.75f, 60};
    const std::vector<Strip> strips = someStrips();
    const std::optional<ParsedFrame> f = parseFrame(message(info, 9, strips));
    ASSERT_TRUE(f);
    EXPECT_EQ(f->info.frame, 42u);
    EXPECT_EQ(f->info.width, 96);
    EXPECT_EQ(f->info.height, 26);
    EXPECT_FLOAT_EQ(f->info.renderMs, 12.5f);
    EXPECT_FLOAT_EQ(f->info.encodeMs, 0.75f);
    EXPECT_EQ(f->info.quality, 60u);
    EXPECT_EQ(f->ack, 9u);
    ASSERT_EQ(f->strips.size(), strips.size());
    for (std::size_t i = 0; i < strips.size(); ++i) {
        EXPECT_EQ(f->strips[i].y, strips[i].y);
        EXPECT_EQ(f->strips[i].rows, strips[i].rows);
        EXPECT_EQ(f->strips[i].jpeg, strips[i].jpeg);
    }
}

TEST(ServeFrameMessage, RefusesEveryTruncationAndTrailingBytes) {
    const std::string whole = message(FrameInfo{1, 8, 26, 0, 0, 85}, 0, someStrips());
    for (std::size_t n = 0; n < whole.size(); ++n) EXPECT_FALSE(parseFrame(whole.substr(0, n))) << n;
    EXPECT_FALSE(parseFrame(whole + "x"));
    std::string badMagic = whole;
    badMagic[0] = 'X';
    EXPECT_FALSE(parseFrame(badMagic));
    // A strip count far beyond the bytes there: refused, not allocated for.
    std::string huge = whole;
    huge[31] = char(0x7f);
    EXPECT_FALSE(parseFrame(huge));
}

}  // namespace
}  // namespace penumbra::serve
