#include "serve/frame_message.h"

#include <cstring>

namespace penumbra::serve {
namespace {

// Little-endian on every host: the browser's DataView reads it so.
template <class T>
void put(std::uint8_t* at, T value) {
    static_assert(sizeof(T) <= 4);
    std::uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof(T));
    for (std::size_t i = 0; i < sizeof(T); ++i) at[i] = std::uint8_t(bits >> (8 * i));
}

template <class T>
T get(std::string_view bytes, std::size_t at) {
    std::uint32_t bits = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i) bits |= std::uint32_t(std::uint8_t(bytes[at + i])) << (8 * i);
    T value;
    std::memcpy(&value, &bits, sizeof(T));
    return value;
}

}  // namespace

std::array<std::uint8_t, kFrameHeaderBytes> frameHeader(const FrameInfo& info, std::uint32_t ack,
                                                        std::uint32_t strips) {
    std::array<std::uint8_t, kFrameHeaderBytes> h{};
    put(&h[0], kFrameMagic);
    put(&h[4], info.frame);
    put(&h[8], info.width);
    put(&h[10], info.height);
    put(&h[12], ack);
    put(&h[16], info.renderMs);
    put(&h[20], info.encodeMs);
    put(&h[24], info.quality);
    put(&h[28], strips);
    return h;
}

std::string packStrips(const std::vector<Strip>& strips) {
    std::size_t bytes = 0;
    for (const Strip& s : strips) bytes += kStripHeaderBytes + s.jpeg.size();
    std::string out(bytes, '\0');
    auto* at = reinterpret_cast<std::uint8_t*>(out.data());
    for (const Strip& s : strips) {
        put(at, s.y);
        put(at + 2, s.rows);
        put(at + 4, std::uint32_t(s.jpeg.size()));
        std::memcpy(at + kStripHeaderBytes, s.jpeg.data(), s.jpeg.size());
        at += kStripHeaderBytes + s.jpeg.size();
    }
    return out;
}

std::optional<ParsedFrame> parseFrame(std::string_view bytes) {
    if (bytes.size() < kFrameHeaderBytes || get<std::uint32_t>(bytes, 0) != kFrameMagic) return std::nullopt;
    ParsedFrame f;
    f.info.frame = get<std::uint32_t>(bytes, 4);
    f.info.width = get<std::uint16_t>(bytes, 8);
    f.info.height = get<std::uint16_t>(bytes, 10);
    f.ack = get<std::uint32_t>(bytes, 12);
    f.info.renderMs = get<float>(bytes, 16);
    f.info.encodeMs = get<float>(bytes, 20);
    f.info.quality = get<std::uint32_t>(bytes, 24);
    const std::uint32_t count = get<std::uint32_t>(bytes, 28);
    std::size_t at = kFrameHeaderBytes;
    for (std::uint32_t i = 0; i < count; ++i) {
        if (bytes.size() - at < kStripHeaderBytes) return std::nullopt;
        Strip s;
        s.y = get<std::uint16_t>(bytes, at);
        s.rows = get<std::uint16_t>(bytes, at + 2);
        const std::uint32_t size = get<std::uint32_t>(bytes, at + 4);
        at += kStripHeaderBytes;
        if (bytes.size() - at < size) return std::nullopt;
        s.jpeg.assign(bytes.substr(at, size));
        at += size;
        f.strips.push_back(std::move(s));
    }
    if (at != bytes.size()) return std::nullopt;
    return f;
}

}  // namespace penumbra::serve
