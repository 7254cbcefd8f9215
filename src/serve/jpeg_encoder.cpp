#include "serve/jpeg_encoder.h"

#include <turbojpeg.h>

#include <algorithm>

#include "core/error.h"

namespace penumbra::serve {

JpegEncoder::JpegEncoder() : handle_(tjInitCompress()) {
    if (!handle_) throw Error("cannot start the JPEG encoder (libturbojpeg)");
}

JpegEncoder::~JpegEncoder() { tjDestroy(static_cast<tjhandle>(handle_)); }

void JpegEncoder::encode(const std::uint8_t* rgbx, int width, int rows, int quality, std::string& out) {
    // Encoding straight into a buffer of the worst-case size spares TurboJPEG's reallocations.
    out.resize(tjBufSize(width, rows, TJSAMP_420));
    auto* dst = reinterpret_cast<unsigned char*>(out.data());
    unsigned long size = out.size();
    const int result = tjCompress2(static_cast<tjhandle>(handle_), rgbx, width, width * 4, rows, TJPF_RGBX, &dst,
                                   &size, TJSAMP_420, std::clamp(quality, 1, 100), TJFLAG_NOREALLOC | TJFLAG_FASTDCT);
    if (result != 0) throw Error(std::string("JPEG encoding failed: ") + tjGetErrorStr2(static_cast<tjhandle>(handle_)));
    out.resize(size);
}

bool decodeJpeg(const std::string& jpeg, int& width, int& height, std::string& rgb) {
    tjhandle handle = tjInitDecompress();
    if (!handle) return false;
    int subsampling = 0, colorspace = 0;
    const auto* src = reinterpret_cast<const unsigned char*>(jpeg.data());
    bool ok = tjDecompressHeader3(handle, src, jpeg.size(), &width, &height, &subsampling, &colorspace) == 0 &&
              width > 0 && height > 0 && width <= 65535 && height <= 65535;
    if (ok) {
        rgb.resize(std::size_t(width) * std::size_t(height) * 3);
        ok = tjDecompress2(handle, src, jpeg.size(), reinterpret_cast<unsigned char*>(rgb.data()), width, width * 3,
                           height, TJPF_RGB, 0) == 0;
    }
    tjDestroy(handle);
    return ok;
}

}  // namespace penumbra::serve
