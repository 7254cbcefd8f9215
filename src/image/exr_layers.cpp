#include "image/exr_layers.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <Iex.h>
#include <ImfIO.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <set>

#include "core/atomic_file.h"
#include "core/error.h"

namespace penumbra {

void appendRgbChannels(std::vector<ExrChannel>& channels, const ImageRgb& image, const std::string& layer,
                       const char* names) {
    const std::string prefix = layer.empty() ? "" : layer + ".";
    for (int c = 0; c < 3; ++c) {
        ExrChannel ch{prefix + names[c], std::vector<float>(image.pixels.size())};
        for (std::size_t i = 0; i < image.pixels.size(); ++i) ch.values[i] = image.pixels[i][c];
        channels.push_back(std::move(ch));
    }
}

void writeExrChannels(const std::filesystem::path& path, int width, int height, const std::vector<ExrChannel>& channels) {
    PN_CHECK(width > 0 && height > 0);
    std::set<std::string> names;
    for (const ExrChannel& c : channels) {
        PN_CHECK(c.values.size() == std::size_t(width) * std::size_t(height));
        PN_CHECK(names.insert(c.name).second);
    }
    writeFileAtomically(path, [&](const std::filesystem::path& tmp) {
        try {
            Imf::Header header(width, height);
            header.compression() = Imf::ZIP_COMPRESSION;
            Imf::FrameBuffer frame;
            for (const ExrChannel& c : channels) {
                header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
                frame.insert(c.name, Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(c.values.data())),
                                                sizeof(float), sizeof(float) * std::size_t(width)));
            }
            Imf::OutputFile file(tmp.c_str(), header);
            file.setFrameBuffer(frame);
            file.writePixels(height);
        } catch (const std::exception& e) {
            throw Error(std::string("OpenEXR: ") + e.what());
        }
    });
}

namespace {

// Pixel counts above this are refused: 2^28 float channels are 1 GiB each.
constexpr std::size_t kMaxExrPixels = std::size_t(1) << 28;

// OpenEXR reads through this from bytes already in memory (an environment map, a texture
// embedded in a model, a file read once).
class MemoryStream : public Imf::IStream {
public:
    MemoryStream(std::string_view bytes, const std::string& name) : Imf::IStream(name.c_str()), bytes_(bytes) {}
    bool read(char c[], int n) override {
        if (n < 0 || std::uint64_t(n) > bytes_.size() - position_) throw Iex::InputExc("unexpected end of file");
        std::memcpy(c, bytes_.data() + position_, std::size_t(n));
        position_ += std::uint64_t(n);
        return position_ < bytes_.size();
    }
    std::uint64_t tellg() override { return position_; }
    void seekg(std::uint64_t pos) override {
        if (pos > bytes_.size()) throw Iex::InputExc("seek past the end of file");
        position_ = pos;
    }

private:
    std::string_view bytes_;
    std::uint64_t position_ = 0;
};

// Runs `body`, turning OpenEXR's exceptions into an Error that names the file.
template <typename F>
auto guarded(const std::string& name, F&& body) {
    try {
        return body();
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        std::string what = e.what();
        std::replace(what.begin(), what.end(), '\n', ' ');
        // OpenEXR repeats the file name: 'Cannot read image file "x.exr". <why>'.
        if (what.rfind("Cannot read image file \"", 0) == 0 && what.find("\". ") != std::string::npos)
            what = what.substr(what.find("\". ") + 3);
        throw Error("cannot read OpenEXR file '" + name + "': " + what);
    }
}

}  // namespace

ExrHeaderInfo readExrHeader(std::string_view bytes, const std::string& name) {
    return guarded(name, [&] {
        MemoryStream stream(bytes, name);
        Imf::InputFile file(stream);
        const Imath::Box2i window = file.header().dataWindow();
        ExrHeaderInfo info;
        info.width = (long long)window.max.x - window.min.x + 1;
        info.height = (long long)window.max.y - window.min.y + 1;
        for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
            info.channels.push_back(it.name());
        return info;
    });
}

ExrChannels decodeExrChannels(std::string_view bytes, const std::string& name, const std::vector<std::string>& only) {
    return guarded(name, [&] {
        MemoryStream stream(bytes, name);
        Imf::InputFile file(stream);
        const Imath::Box2i window = file.header().dataWindow();
        const long long w = (long long)window.max.x - window.min.x + 1, h = (long long)window.max.y - window.min.y + 1;
        if (w <= 0 || h <= 0 || std::size_t(w) * std::size_t(h) > kMaxExrPixels)
            throw Error("'" + name + "': image size " + std::to_string(w) + "x" + std::to_string(h) + " out of range");
        ExrChannels out;
        out.width = int(w);
        out.height = int(h);
        const std::size_t n = std::size_t(w) * std::size_t(h);
        Imf::FrameBuffer frame;
        for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
            if (!only.empty() && std::find(only.begin(), only.end(), it.name()) == only.end()) continue;
            std::vector<float>& values = out.channels[it.name()];
            values.assign(n, 0.0f);
            // Slices are addressed from the data window's origin.
            char* base = reinterpret_cast<char*>(values.data()) -
                         (std::ptrdiff_t(window.min.x) + std::ptrdiff_t(window.min.y) * out.width) * std::ptrdiff_t(sizeof(float));
            frame.insert(it.name(), Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * std::size_t(out.width)));
        }
        for (const std::string& wanted : only)
            if (!out.channels.count(wanted)) throw Error("'" + name + "' has no channel '" + wanted + "'");
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        return out;
    });
}

ExrChannels readExrChannels(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw Error("cannot read EXR '" + path.string() + "': no such file");
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || size > (std::uintmax_t(4) << 30)) throw Error("cannot read EXR '" + path.string() + "': too large or unreadable");
    std::ifstream in(path, std::ios::binary);
    std::string bytes(std::size_t(size), '\0');
    if (!in.read(bytes.data(), std::streamsize(size))) throw Error("cannot read EXR '" + path.string() + "'");
    return decodeExrChannels(bytes, path.string());
}

std::optional<std::array<std::string, 3>> beautyChannels(const std::vector<std::string>& names) {
    const std::set<std::string> has(names.begin(), names.end());
    if (has.count("R") && has.count("G") && has.count("B")) return std::array<std::string, 3>{"R", "G", "B"};
    if (has.count("Y")) return std::array<std::string, 3>{"Y", "Y", "Y"};
    for (const std::string& n : has) {  // sorted: the first layer by name
        if (n.size() < 3 || n.compare(n.size() - 2, 2, ".R") != 0) continue;
        const std::string layer = n.substr(0, n.size() - 1);
        if (has.count(layer + "G") && has.count(layer + "B")) return std::array<std::string, 3>{n, layer + "G", layer + "B"};
    }
    return std::nullopt;
}

}  // namespace penumbra
