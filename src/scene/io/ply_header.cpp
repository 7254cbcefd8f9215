#include "scene/io/ply_header.h"

#include <charconv>
#include <limits>

#include "core/error.h"

namespace penumbra::ply {
namespace {

constexpr std::size_t kMaxHeaderBytes = std::size_t(1) << 20;
constexpr std::size_t kMaxProperties = 4096;  // over all elements
// Counts are kept in 32-bit indices downstream.
constexpr std::uint64_t kMaxCount = std::numeric_limits<std::uint32_t>::max() - 1;

struct TypeName {
    std::string_view name;
    Type type;
};
constexpr TypeName kTypeNames[] = {
    {"char", Type::Int8},       {"int8", Type::Int8},       {"uchar", Type::UInt8},
    {"uint8", Type::UInt8},     {"short", Type::Int16},     {"int16", Type::Int16},
    {"ushort", Type::UInt16},   {"uint16", Type::UInt16},   {"int", Type::Int32},
    {"int32", Type::Int32},     {"uint", Type::UInt32},     {"uint32", Type::UInt32},
    {"float", Type::Float32},   {"float32", Type::Float32}, {"double", Type::Float64},
    {"float64", Type::Float64},
};

std::string printable(std::string_view s) {
    std::string out(s.substr(0, 60));
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
    return s.size() > 60 ? out + "..." : out;
}

// Splits a header line into words (spaces and tabs).
std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        std::size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
        if (j > i) out.push_back(line.substr(i, j - i));
        i = j;
    }
    return out;
}

class HeaderParser {
public:
    HeaderParser(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

    Header run() {
        std::string_view first = nextLine();
        if (first != "ply") fail("not a PLY file (it must start with a line 'ply')");
        bool haveFormat = false;
        for (;;) {
            if (pos_ >= bytes_.size()) fail("the header has no 'end_header' line");
            if (pos_ > kMaxHeaderBytes) fail("the header is longer than 1 MiB");
            std::vector<std::string_view> w = words(nextLine());
            if (w.empty()) continue;
            if (w[0] == "end_header") break;
            if (w[0] == "comment" || w[0] == "obj_info") continue;
            if (w[0] == "format") {
                if (haveFormat) fail("a second 'format' line");
                format(w);
                haveFormat = true;
            } else if (w[0] == "element") {
                element(w);
            } else if (w[0] == "property") {
                property(w);
            } else {
                fail("unknown header keyword '" + printable(w[0]) + "'");
            }
        }
        if (!haveFormat) fail("the header has no 'format' line");
        header_.bodyOffset = pos_;
        header_.lines = line_;
        checkCounts();
        return std::move(header_);
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw Error(name_ + ":" + std::to_string(line_) + ": " + what);
    }

    // The next line without its line break (\n or \r\n).
    std::string_view nextLine() {
        std::size_t end = bytes_.find('\n', pos_);
        if (end == std::string_view::npos) end = bytes_.size();
        std::string_view line = bytes_.substr(pos_, end - pos_);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        pos_ = end + 1;
        ++line_;
        return line;
    }

    Type type(std::string_view word) const {
        for (const TypeName& t : kTypeNames)
            if (t.name == word) return t.type;
        fail("unknown property type '" + printable(word) + "'");
    }

    void format(const std::vector<std::string_view>& w) {
        if (w.size() != 3)
            fail("expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
        if (w[1] == "ascii")
            header_.format = Format::Ascii;
        else if (w[1] == "binary_little_endian")
            header_.format = Format::BinaryLittleEndian;
        else if (w[1] == "binary_big_endian")
            header_.format = Format::BinaryBigEndian;
        else
            fail("unknown format '" + printable(w[1]) + "'");
        if (w[2] != "1.0")
            fail("unsupported PLY version '" + printable(w[2]) + "' (only 1.0 exists)");
    }

    void element(const std::vector<std::string_view>& w) {
        if (w.size() != 3) fail("expected 'element <name> <count>'");
        Element e;
        e.name = std::string(w[1]);
        e.line = line_;
        auto [end, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
        if (ec != std::errc{} || end != w[2].data() + w[2].size())
            fail("element '" + printable(w[1]) +
                 "' has a count that is not a non-negative whole number: '" + printable(w[2]) +
                 "'");
        if (e.count > kMaxCount)
            fail("element '" + printable(w[1]) + "' claims " + std::string(w[2]) +
                 " entries; at most " + std::to_string(kMaxCount) + " are supported");
        header_.elements.push_back(std::move(e));
    }

    void property(const std::vector<std::string_view>& w) {
        if (header_.elements.empty()) fail("a 'property' line before any 'element' line");
        if (++properties_ > kMaxProperties) fail("more than 4096 properties");
        Property p;
        if (w.size() >= 2 && w[1] == "list") {
            if (w.size() != 5) fail("expected 'property list <count type> <item type> <name>'");
            p.isList = true;
            p.countType = type(w[2]);
            if (!isInteger(p.countType)) fail("a list's count type must be an integer type");
            p.type = type(w[3]);
            p.name = std::string(w[4]);
        } else {
            if (w.size() != 3) fail("expected 'property <type> <name>'");
            p.type = type(w[1]);
            p.name = std::string(w[2]);
        }
        Element& e = header_.elements.back();
        if (e.find(p.name) >= 0)
            fail("element '" + e.name + "' has two properties named '" + printable(p.name) + "'");
        e.properties.push_back(std::move(p));
    }

    // Refuses counts that cannot fit in the body, before anyone allocates for them: a binary
    // record takes at least its fixed part, an ASCII one at least one character and one
    // separator per property (lists: their count).
    void checkCounts() {
        const std::uint64_t body = bytes_.size() - std::min(bytes_.size(), pos_);
        std::uint64_t needed = 0;
        for (const Element& e : header_.elements) {
            const std::uint64_t each =
                header_.format == Format::Ascii ? 2 * e.properties.size() : e.minRecordBytes();
            needed += e.count * each;  // < 2^32 * 2^16: no overflow
            if (needed > body + 1) {
                line_ = e.line;
                fail("element '" + printable(e.name) + "' claims " + std::to_string(e.count) +
                     " entries, more than the file's " + std::to_string(body) +
                     " bytes after the header can hold");
            }
        }
    }

    std::string_view bytes_;
    const std::string& name_;
    std::size_t pos_ = 0, line_ = 0, properties_ = 0;
    Header header_;
};

}  // namespace

std::size_t sizeOf(Type t) {
    switch (t) {
        case Type::Int8:
        case Type::UInt8:
            return 1;
        case Type::Int16:
        case Type::UInt16:
            return 2;
        case Type::Int32:
        case Type::UInt32:
        case Type::Float32:
            return 4;
        case Type::Float64:
            return 8;
    }
    return 0;
}

bool isInteger(Type t) { return t != Type::Float32 && t != Type::Float64; }

bool Element::hasLists() const {
    for (const Property& p : properties)
        if (p.isList) return true;
    return false;
}

std::size_t Element::recordBytes() const {
    std::size_t n = 0;
    for (const Property& p : properties) n += sizeOf(p.type);
    return n;
}

std::size_t Element::minRecordBytes() const {
    std::size_t n = 0;
    for (const Property& p : properties) n += p.isList ? sizeOf(p.countType) : sizeOf(p.type);
    return n;
}

int Element::find(std::string_view property) const {
    for (std::size_t i = 0; i < properties.size(); ++i)
        if (properties[i].name == property) return int(i);
    return -1;
}

Header parseHeader(std::string_view bytes, const std::string& name) {
    return HeaderParser(bytes, name).run();
}

}  // namespace penumbra::ply
