// Checkpoint files: what is written is read back exactly, and every kind of bad file is one
// clear error (never a crash or a read past the end).
#include <gtest/gtest.h>

#include "core/error.h"
#include "render/checkpoint.h"

namespace penumbra {
namespace {

constexpr RenderKey kKey{0x0123456789abcdefull, 0xfedcba9876543210ull};

RenderSnapshot sampleSnapshot(bool adaptive, bool pending) {
    RenderSnapshot s;
    s.passesDone = pending ? 21 : 16;
    AccumulatorData& d = s.sums;
    d.width = 3;
    d.height = 2;
    d.adaptive = adaptive;
    d.nominalSamples = 16;
    for (int i = 0; i < 6; ++i) {
        d.estimate.insert(d.estimate.end(), {0.1 * i, 0.2 * i + 1e-17, 1.0 / (i + 3)});
        d.squares.push_back(i * 1e300);
        if (adaptive) {
            d.raw.insert(d.raw.end(), {double(i), -0.0, 3.25});
            d.count.push_back(std::uint32_t(i) * 7u);
        }
        if (pending) s.pending.push_back(Vec4{float(i), 0.5f, -1.0f, 2.0f});
    }
    return s;
}

void expectEqual(const RenderSnapshot& a, const RenderSnapshot& b) {
    EXPECT_EQ(a.passesDone, b.passesDone);
    EXPECT_EQ(a.sums.width, b.sums.width);
    EXPECT_EQ(a.sums.height, b.sums.height);
    EXPECT_EQ(a.sums.adaptive, b.sums.adaptive);
    EXPECT_EQ(a.sums.nominalSamples, b.sums.nominalSamples);
    EXPECT_EQ(a.sums.estimate, b.sums.estimate);  // bit for bit: doubles are stored raw
    EXPECT_EQ(a.sums.squares, b.sums.squares);
    EXPECT_EQ(a.sums.raw, b.sums.raw);
    EXPECT_EQ(a.sums.count, b.sums.count);
    ASSERT_EQ(a.pending.size(), b.pending.size());
    for (std::size_t i = 0; i < a.pending.size(); ++i) {
        EXPECT_EQ(a.pending[i].x, b.pending[i].x);
        EXPECT_EQ(a.pending[i].w, b.pending[i].w);
    }
}

std::string errorOf(std::string_view bytes, const RenderKey& key = kKey, std::uint32_t w = 3, std::uint32_t h = 2) {
    try {
        decodeCheckpoint(bytes, key, w, h, "x.state");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(Checkpoint, RoundTripsEveryKind) {
    for (bool adaptive : {false, true})
        for (bool pending : {false, true}) {
            const RenderSnapshot s = sampleSnapshot(adaptive, pending);
            expectEqual(decodeCheckpoint(encodeCheckpoint(s, kKey), kKey, 3, 2, "x"), s);
        }
}

TEST(Checkpoint, RefusesAnotherScenesOrSettingsKey) {
    const std::string bytes = encodeCheckpoint(sampleSnapshot(true, true), kKey);
    const std::string e = errorOf(bytes, RenderKey{kKey[0], kKey[1] ^ 1});
    EXPECT_NE(e.find("another scene or other settings"), std::string::npos) << e;
    EXPECT_EQ(e.rfind("x.state: ", 0), 0u) << e;  // names the file
}

TEST(Checkpoint, RefusesAnotherImageSize) {
    const std::string e = errorOf(encodeCheckpoint(sampleSnapshot(false, false), kKey), kKey, 2, 3);
    EXPECT_NE(e.find("3x2, not 2x3"), std::string::npos) << e;
}

TEST(Checkpoint, EveryTruncationIsAnError) {
    const std::string bytes = encodeCheckpoint(sampleSnapshot(true, true), kKey);
    for (std::size_t n = 0; n < bytes.size(); ++n) EXPECT_NE(errorOf(bytes.substr(0, n)), "") << n;
    EXPECT_NE(errorOf(bytes + "x").find("trailing"), std::string::npos);
}

TEST(Checkpoint, EveryFlippedByteIsAnError) {
    const std::string bytes = encodeCheckpoint(sampleSnapshot(true, false), kKey);
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        std::string bad = bytes;
        bad[i] = char(bad[i] ^ 0x10);
        EXPECT_NE(errorOf(bad), "") << "byte " << i;
    }
}

TEST(Checkpoint, ForeignFilesAreNamedAsSuch) {
    EXPECT_NE(errorOf("P3\n1 1\n255\n0 0 0\n").find("not a Penumbra checkpoint"), std::string::npos);
    EXPECT_NE(errorOf("").find("not a Penumbra checkpoint"), std::string::npos);
}

}  // namespace
}  // namespace penumbra
