// JPEG encoding of RGBA8 pixel rows through libjpeg-turbo's TurboJPEG API (Debian
// libturbojpeg0-dev). One encoder per thread: a TurboJPEG handle is not thread-safe.
#pragma once

#include <cstdint>
#include <string>

namespace penumbra::serve {

class JpegEncoder {
public:
    JpegEncoder();
    ~JpegEncoder();
    JpegEncoder(const JpegEncoder&) = delete;
    JpegEncoder& operator=(const JpegEncoder&) = delete;

    // Encodes `rows` rows of `width` pixels (4 bytes each, R G B and an unused byte, rows packed)
    // at quality 1..100 with 4:2:0 chroma, replacing the contents of `out`.
    void encode(const std::uint8_t* rgbx, int width, int rows, int quality, std::string& out);

private:
    void* handle_ = nullptr;  // tjhandle
};

// Decodes a JPEG into packed RGB (3 bytes a pixel); false when it is not one. For the probe
// client and the tests.
bool decodeJpeg(const std::string& jpeg, int& width, int& height, std::string& rgb);

}  // namespace penumbra::serve
