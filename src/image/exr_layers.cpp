#include "image/exr_layers.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

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

ExrChannels readExrChannels(const std::filesystem::path& path) {
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        ExrChannels out;
        out.width = window.max.x - window.min.x + 1;
        out.height = window.max.y - window.min.y + 1;
        if (out.width <= 0 || out.height <= 0 || std::size_t(out.width) * std::size_t(out.height) > (std::size_t(1) << 28))
            throw Error("'" + path.string() + "': image size out of range");
        const std::size_t n = std::size_t(out.width) * std::size_t(out.height);
        Imf::FrameBuffer frame;
        for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
            std::vector<float>& values = out.channels[it.name()];
            values.assign(n, 0.0f);
            // Slices are addressed from the data window's origin.
            char* base = reinterpret_cast<char*>(values.data()) -
                         (std::ptrdiff_t(window.min.x) + std::ptrdiff_t(window.min.y) * out.width) * std::ptrdiff_t(sizeof(float));
            frame.insert(it.name(), Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * std::size_t(out.width)));
        }
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        return out;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error("cannot read EXR '" + path.string() + "': " + e.what());
    }
}

}  // namespace penumbra
