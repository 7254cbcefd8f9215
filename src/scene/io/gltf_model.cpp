#include "scene/io/gltf_model.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "core/log.h"

namespace penumbra::gltf {
namespace {

constexpr int kMaxJsonDepth = 200;  // tinygltf converts extras recursively

struct FsContext {
    std::string prefix;  // only files below this path are read
};

bool fileExists(const std::string& path, void* user) {
    const auto* ctx = static_cast<const FsContext*>(user);
    if (path.compare(0, ctx->prefix.size(), ctx->prefix) != 0) return false;  // e.g. tinygltf's "." fallback
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

std::string expandFilePath(const std::string& path, void*) { return path; }  // no wordexp

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    if (!fileExists(path, user)) {
        if (err) *err += "not found";
        return false;
    }
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || size > kMaxFileBytes) {
        if (err) *err += ec ? ec.message() : "larger than 2 GiB";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out->resize(static_cast<std::size_t>(size));
    if (!in || !in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))) {
        if (err) *err += "read error";
        return false;
    }
    return true;
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is disabled";
    return false;
}

// Keeps the encoded bytes (URI images); images in buffer views are read later, after their view
// has been checked (tinygltf passes an unchecked pointer for those, so we must not touch it).
bool keepImageBytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                    const unsigned char* bytes, int size, void*) {
    image->as_is = true;
    if (image->bufferView >= 0) return true;
    if (bytes && size > 0) image->image.assign(bytes, bytes + size);
    return true;
}

// Nesting depth of a JSON text (brackets outside strings); refuses stack-exhausting inputs early.
int jsonDepth(std::string_view json) {
    int depth = 0, maxDepth = 0;
    bool inString = false, escape = false;
    for (char c : json) {
        if (inString) {
            if (escape)
                escape = false;
            else if (c == '\\')
                escape = true;
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '"') inString = true;
        if (c == '[' || c == '{') maxDepth = std::max(maxDepth, ++depth);
        if (c == ']' || c == '}') --depth;
    }
    return maxDepth;
}

std::uint32_t readU32(std::string_view b, std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, b.data() + at, 4);
    return v;  // GLB is little-endian, as are our targets
}

}  // namespace

std::string clampName(std::string s) {
    if (s.size() > 80) s = s.substr(0, 77) + "...";
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 32) c = '?';
    return s;
}

namespace {

std::string firstLines(const std::string& text, std::size_t maxLines) {
    std::string out;
    std::size_t pos = 0, lines = 0;
    while (pos < text.size() && lines < maxLines) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        std::string line = clampName(text.substr(pos, end - pos));
        if (!line.empty()) {
            if (!out.empty()) out += "; ";
            out += line;
            ++lines;
        }
        pos = end + 1;
    }
    return out;
}

}  // namespace

tinygltf::Model parseModel(std::string_view bytes, const std::filesystem::path& baseDir, const std::string& name) {
    if (bytes.size() > kMaxFileBytes) throw Error(name + ": file is larger than 2 GiB");
    const bool binary = bytes.size() >= 4 && bytes.substr(0, 4) == "glTF";
    std::string_view json = bytes;
    if (binary) {
        if (bytes.size() < 20) throw Error(name + ": GLB file is truncated (no JSON chunk header)");
        const std::uint32_t jsonLength = readU32(bytes, 12);
        if (jsonLength > bytes.size() - 20) throw Error(name + ": GLB JSON chunk runs past the end of the file");
        json = bytes.substr(20, jsonLength);
    }
    if (jsonDepth(json) > kMaxJsonDepth)
        throw Error(name + ": JSON nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");

    std::string base = baseDir.empty() ? std::string(".") : baseDir.string();
    FsContext fs{base.back() == '/' ? base : base + "/"};
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&fileExists, &expandFilePath, &readWholeFile, &writeWholeFile, &fs});
    loader.SetImageLoader(&keepImageBytes, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    bool ok = false;
    try {
        if (binary)
            ok = loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                             static_cast<unsigned int>(bytes.size()), base);
        else
            ok = loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()),
                                            base);
    } catch (const std::exception& e) {
        throw Error(name + ": invalid glTF: " + clampName(e.what()));
    }
    if (!ok) throw Error(name + ": invalid glTF: " + (err.empty() ? std::string("parse failed") : firstLines(err, 3)));
    if (!warn.empty()) logWarning(name + ": " + firstLines(warn, 4));
    for (const std::string& ext : model.extensionsRequired)
        if (ext != "KHR_lights_punctual" && ext != "KHR_materials_emissive_strength" &&
            ext != "KHR_materials_transmission" && ext != "KHR_materials_ior" && ext != "KHR_texture_transform")
            logWarning(name + ": required extension " + clampName(ext) + " is not supported; the result may be wrong");
    return model;
}

}  // namespace penumbra::gltf
