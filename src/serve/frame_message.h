// A frame as it goes over the WebSocket (docs/SERVE.md, "Server to browser"): a 32-byte header,
// then strips of JPEG. The strips are encoded once and shared by every browser; only the header
// differs between browsers (it carries each browser's own input acknowledgement).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::serve {

inline constexpr std::uint32_t kFrameMagic = 0x31464E50;  // "PNF1" in little-endian bytes
inline constexpr std::size_t kFrameHeaderBytes = 32;
inline constexpr std::size_t kStripHeaderBytes = 8;

struct FrameInfo {
    std::uint32_t frame = 0;  // frames rendered since the server started
    std::uint16_t width = 0, height = 0;
    float renderMs = 0;   // the frame's GPU time
    float encodeMs = 0;   // the slowest strip's encoding time
    std::uint32_t quality = 0;
};

struct Strip {
    std::uint16_t y = 0, rows = 0;
    std::string jpeg;
};

// The header for one browser: `ack` is the seq of its latest input applied before the frame.
std::array<std::uint8_t, kFrameHeaderBytes> frameHeader(const FrameInfo& info, std::uint32_t ack,
                                                        std::uint32_t strips);
// The strips, each behind its 8-byte record, as one block sent after the header.
std::string packStrips(const std::vector<Strip>& strips);

// A frame message read back (the probe client and the tests); nothing when it is malformed.
struct ParsedFrame {
    FrameInfo info;
    std::uint32_t ack = 0;
    std::vector<Strip> strips;
};
std::optional<ParsedFrame> parseFrame(std::string_view bytes);

}  // namespace penumbra::serve
