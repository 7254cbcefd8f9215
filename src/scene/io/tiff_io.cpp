#include "scene/io/tiff_io.h"

#include <tiffio.h>

#include <cstdarg>
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <memory>

#include "core/error.h"

namespace penumbra {
namespace {

// libtiff's largest single allocation while decoding (strips, tiles, tables): a hostile file
// cannot make it reserve more than this.
constexpr tmsize_t kMaxSingleAllocation = tmsize_t(256) << 20;

// The file's bytes, read by libtiff through the client procedures below.
struct Source {
    std::string_view bytes;
    toff_t position = 0;
    std::string firstError;  // libtiff's first complaint, for the message
};

tmsize_t readProc(thandle_t handle, void* buffer, tmsize_t size) {
    auto* s = static_cast<Source*>(handle);
    if (size <= 0 || s->position >= s->bytes.size()) return 0;
    const tmsize_t n = tmsize_t(std::min<std::uint64_t>(std::uint64_t(size), s->bytes.size() - s->position));
    std::memcpy(buffer, s->bytes.data() + s->position, std::size_t(n));
    s->position += toff_t(n);
    return n;
}
tmsize_t writeProc(thandle_t, void*, tmsize_t) { return 0; }
toff_t seekProc(thandle_t handle, toff_t offset, int whence) {
    auto* s = static_cast<Source*>(handle);
    const std::uint64_t base = whence == SEEK_CUR ? s->position : whence == SEEK_END ? s->bytes.size() : 0;
    const std::uint64_t target = base + offset;  // offsets past the end read nothing
    if (target < base) return toff_t(-1);
    s->position = target;
    return s->position;
}
int closeProc(thandle_t) { return 0; }
toff_t sizeProc(thandle_t handle) { return static_cast<Source*>(handle)->bytes.size(); }
int mapProc(thandle_t, void**, toff_t*) { return 0; }
void unmapProc(thandle_t, void*, toff_t) {}

int recordError(TIFF*, void* user, const char*, const char* format, va_list args) {
    auto* s = static_cast<Source*>(user);
    if (s->firstError.empty()) {
        char text[256];
        std::vsnprintf(text, sizeof text, format, args);
        s->firstError = text;
        for (char& c : s->firstError)
            if (c == '\n' || c == '\r') c = ' ';
    }
    return 1;  // handled: nothing is printed
}
int ignoreWarning(TIFF*, void*, const char*, const char*, va_list) { return 1; }

struct TiffCloser {
    void operator()(TIFF* t) const { TIFFClose(t); }
};
struct OptionsFree {
    void operator()(TIFFOpenOptions* o) const { TIFFOpenOptionsFree(o); }
};

template <typename T>
T field(TIFF* tif, ttag_t tag, T fallback) {
    T value = fallback;
    return TIFFGetFieldDefaulted(tif, tag, &value) == 1 ? value : fallback;
}

void readFloatStrips(TIFF* tif, Source& source, const std::string& name, TiffPixels& out) {
    const auto channels = field<std::uint16_t>(tif, TIFFTAG_SAMPLESPERPIXEL, 1);
    if (TIFFIsTiled(tif) || field<std::uint16_t>(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG) != PLANARCONFIG_CONTIG ||
        field<std::uint16_t>(tif, TIFFTAG_BITSPERSAMPLE, 1) != 32 || (channels != 1 && channels < 3) || channels > 16)
        throw Error(name + ": floating-point TIFFs are read when they hold 32-bit samples, 1, 3 or more per pixel, "
                           "interleaved in strips (this one does not)");
    const std::size_t w = std::size_t(out.width);
    if (std::size_t(TIFFScanlineSize64(tif)) != w * channels * sizeof(float))
        throw Error(name + ": TIFF scanline size disagrees with its header");
    std::vector<float> row(w * channels);
    out.rgbaFloat.resize(w * std::size_t(out.height) * 4);
    for (int y = 0; y < out.height; ++y) {
        if (TIFFReadScanline(tif, row.data(), std::uint32_t(y), 0) != 1)
            throw Error(name + ": TIFF pixel data is truncated or corrupt" +
                        (source.firstError.empty() ? "" : " (" + source.firstError + ")"));
        for (std::size_t x = 0; x < w; ++x) {
            float* p = &out.rgbaFloat[(std::size_t(y) * w + x) * 4];
            const float* q = &row[x * channels];
            p[0] = q[0];
            p[1] = channels >= 3 ? q[1] : q[0];
            p[2] = channels >= 3 ? q[2] : q[0];
            p[3] = channels >= 4 ? q[3] : 1.0f;
        }
    }
}

void readRgba8(TIFF* tif, Source& source, const std::string& name, TiffPixels& out) {
    char why[1024] = {};
    if (!TIFFRGBAImageOK(tif, why)) throw Error(name + ": unsupported TIFF layout (" + why + ")");
    const std::size_t n = std::size_t(out.width) * std::size_t(out.height);
    std::vector<std::uint32_t> raster(n);
    if (!TIFFReadRGBAImageOriented(tif, std::uint32_t(out.width), std::uint32_t(out.height), raster.data(),
                                   ORIENTATION_TOPLEFT, 1))
        throw Error(name + ": TIFF pixel data is truncated or corrupt" +
                    (source.firstError.empty() ? "" : " (" + source.firstError + ")"));
    // libtiff premultiplies unassociated (straight) alpha; textures keep it straight, as PNG does.
    std::uint16_t extraCount = 0;
    std::uint16_t* extra = nullptr;
    const bool straight = TIFFGetField(tif, TIFFTAG_EXTRASAMPLES, &extraCount, &extra) == 1 && extraCount > 0 &&
                          extra[0] == EXTRASAMPLE_UNASSALPHA;
    out.rgba8.resize(n * 4);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t a = TIFFGetA(raster[i]);
        const std::uint32_t rgb[3] = {TIFFGetR(raster[i]), TIFFGetG(raster[i]), TIFFGetB(raster[i])};
        for (int c = 0; c < 3; ++c)
            out.rgba8[4 * i + std::size_t(c)] =
                std::uint8_t(straight && a > 0 && a < 255 ? std::min<std::uint32_t>(255, (rgb[c] * 255 + a / 2) / a) : rgb[c]);
        out.rgba8[4 * i + 3] = std::uint8_t(a);
    }
}

}  // namespace

bool isTiff(std::string_view bytes) {
    if (bytes.size() < 4) return false;
    const bool little = bytes[0] == 'I' && bytes[1] == 'I' && bytes[3] == 0 && (bytes[2] == 42 || bytes[2] == 43);
    const bool big = bytes[0] == 'M' && bytes[1] == 'M' && bytes[2] == 0 && (bytes[3] == 42 || bytes[3] == 43);
    return little || big;
}

TiffPixels decodeTiff(std::string_view bytes, const std::string& name, int maxSide, double maxPixelsPerByte) {
    Source source{bytes};
    std::unique_ptr<TIFFOpenOptions, OptionsFree> options(TIFFOpenOptionsAlloc());
    if (!options) throw Error(name + ": out of memory opening the TIFF");
    TIFFOpenOptionsSetMaxSingleMemAlloc(options.get(), kMaxSingleAllocation);
    TIFFOpenOptionsSetErrorHandlerExtR(options.get(), recordError, &source);
    TIFFOpenOptionsSetWarningHandlerExtR(options.get(), ignoreWarning, nullptr);
    std::unique_ptr<TIFF, TiffCloser> tif(TIFFClientOpenExt(name.c_str(), "rm", &source, readProc, writeProc, seekProc,
                                                            closeProc, sizeProc, mapProc, unmapProc, options.get()));
    if (!tif)
        throw Error(name + ": not a readable TIFF file" + (source.firstError.empty() ? "" : " (" + source.firstError + ")"));
    TiffPixels out;
    const auto w = field<std::uint32_t>(tif.get(), TIFFTAG_IMAGEWIDTH, 0);
    const auto h = field<std::uint32_t>(tif.get(), TIFFTAG_IMAGELENGTH, 0);
    if (w == 0 || h == 0 || w > std::uint32_t(maxSide) || h > std::uint32_t(maxSide))
        throw Error(name + ": TIFF image is " + std::to_string(w) + "x" + std::to_string(h) + "; sides must be 1.." +
                    std::to_string(maxSide));
    if (double(w) * double(h) > double(bytes.size()) * maxPixelsPerByte)
        throw Error(name + ": TIFF header claims " + std::to_string(w) + "x" + std::to_string(h) +
                    " pixels, more than the file's " + std::to_string(bytes.size()) + " bytes can hold");
    out.width = int(w);
    out.height = int(h);
    out.isFloat = field<std::uint16_t>(tif.get(), TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_UINT) == SAMPLEFORMAT_IEEEFP;
    if (out.isFloat)
        readFloatStrips(tif.get(), source, name, out);
    else
        readRgba8(tif.get(), source, name, out);
    return out;
}

}  // namespace penumbra
