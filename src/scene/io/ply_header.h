// The header of a Stanford PLY file (internal to the PLY importer): format, elements and their
// properties, checked against the size of the body before anything is allocated for it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::ply {

enum class Format { Ascii, BinaryLittleEndian, BinaryBigEndian };
enum class Type : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::size_t sizeOf(Type t);
bool isInteger(Type t);

struct Property {
    std::string name;
    Type type = Type::Float32;  // of the value, or of each item of a list
    bool isList = false;
    Type countType = Type::UInt8;  // lists only: the type of the item count
};

struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> properties;
    std::size_t line = 0;  // of its `element` line, for messages

    bool hasLists() const;
    std::size_t recordBytes() const;     // binary, without lists: the size of one record
    std::size_t minRecordBytes() const;  // binary: the smallest a record can be (lists empty)
    int find(std::string_view property) const;  // index, or -1
};

struct Header {
    Format format = Format::Ascii;
    std::vector<Element> elements;
    std::size_t bodyOffset = 0;  // first byte after the end_header line
    std::size_t lines = 0;       // lines in the header, so body line numbers can follow on
};

// Parses and validates the header. Throws Error "name:line: problem" on anything malformed,
// and refuses element counts that could not fit in the bytes after the header.
Header parseHeader(std::string_view bytes, const std::string& name);

}  // namespace penumbra::ply
