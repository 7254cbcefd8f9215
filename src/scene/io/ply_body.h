// Reading the elements of a PLY body (internal to the PLY importer): value readers for the
// ASCII and the two binary encodings, and the element walks built on them. The walks are
// templates over the reader, so no value goes through a virtual call.
#pragma once

#include <array>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "core/error.h"
#include "scene/io/ply_header.h"

namespace penumbra::ply {

// Where a reader is, for messages: "dragon.ply:12: face 7: ..." (ASCII) or
// "dragon.ply: face 7: ..." (binary).
struct Place {
    const std::string* file;
    const Element* element = nullptr;
    std::uint64_t index = 0;
};

class BinaryReader {
public:
    BinaryReader(std::string_view body, bool swap, const std::string& file)
        : p_(body.data()), end_(body.data() + body.size()), swap_(swap), place_{&file} {}

    Place& place() { return place_; }
    [[noreturn]] void fail(const std::string& what) const;

    double real(Type t) { return value(t); }
    // An integer property or list count; a float type here is refused by the caller's checks.
    std::int64_t integer(Type t) { return std::int64_t(value(t)); }
    void skip(Type t) { advance(sizeOf(t)); }
    void skipMany(Type t, std::uint64_t n) {
        if (n > std::uint64_t(end_ - p_) / sizeOf(t)) fail("the file ends inside it");
        p_ += n * sizeOf(t);
    }
    std::size_t left() const { return std::size_t(end_ - p_); }
    const char* position() const { return p_; }
    void seek(const char* p) { p_ = p; }

private:
    const char* advance(std::size_t n) {
        if (std::size_t(end_ - p_) < n) fail("the file ends inside it");
        const char* at = p_;
        p_ += n;
        return at;
    }
    template <typename T>
    T load() {
        std::array<char, sizeof(T)> raw;
        std::memcpy(raw.data(), advance(sizeof(T)), sizeof(T));
        if (swap_)
            for (std::size_t i = 0; i < sizeof(T) / 2; ++i)
                std::swap(raw[i], raw[sizeof(T) - 1 - i]);
        T v;
        std::memcpy(&v, raw.data(), sizeof(T));
        return v;
    }
    double value(Type t) {
        switch (t) {
            case Type::Int8:
                return load<std::int8_t>();
            case Type::UInt8:
                return load<std::uint8_t>();
            case Type::Int16:
                return load<std::int16_t>();
            case Type::UInt16:
                return load<std::uint16_t>();
            case Type::Int32:
                return load<std::int32_t>();
            case Type::UInt32:
                return load<std::uint32_t>();
            case Type::Float32:
                return load<float>();
            case Type::Float64:
                return load<double>();
        }
        return 0;
    }

    const char* p_;
    const char* end_;
    bool swap_;
    Place place_;
};

class AsciiReader {
public:
    AsciiReader(std::string_view body, std::size_t firstLine, const std::string& file)
        : p_(body.data()), end_(body.data() + body.size()), line_(firstLine), place_{&file} {}

    Place& place() { return place_; }
    [[noreturn]] void fail(const std::string& what) const;

    double real(Type t) {
        std::string_view w = token();
        if (isInteger(t)) return double(parseInteger(w));
        double v = 0;
        auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
        if (end != w.data() + w.size() ||
            (ec != std::errc{} && ec != std::errc::result_out_of_range))
            fail("expected a number, found '" + printable(w) + "'");
        return v;
    }
    std::int64_t integer(Type t) {
        std::string_view w = token();
        if (!isInteger(t)) return std::int64_t(real(t));
        return parseInteger(w);
    }
    void skip(Type) { token(); }
    void skipMany(Type t, std::uint64_t n) {
        for (std::uint64_t i = 0; i < n; ++i) skip(t);
    }

private:
    static std::string printable(std::string_view s);
    std::int64_t parseInteger(std::string_view w) const {
        std::int64_t v = 0;
        const char* b = w.data() + (w.size() > 1 && w[0] == '+' ? 1 : 0);
        auto [end, ec] = std::from_chars(b, w.data() + w.size(), v);
        if (ec != std::errc{} || end != w.data() + w.size())
            fail("expected a whole number, found '" + printable(w) + "'");
        return v;
    }
    std::string_view token() {
        while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\n'))
            line_ += *p_++ == '\n';
        if (p_ == end_) fail("the file ends inside it");
        const char* b = p_;
        while (p_ < end_ && *p_ != ' ' && *p_ != '\t' && *p_ != '\r' && *p_ != '\n') ++p_;
        return {b, std::size_t(p_ - b)};
    }

    const char* p_;
    const char* end_;
    std::size_t line_;
    Place place_;
};

}  // namespace penumbra::ply
