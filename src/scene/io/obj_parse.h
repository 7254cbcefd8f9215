// The statements of a Wavefront OBJ file that the importer uses, parsed on every thread
// (internal to the OBJ importer). The text is cut into chunks at line breaks; a first pass
// counts each chunk's lines and v / vt / vn statements, so the second pass knows where its
// attributes go and what relative (negative) indices mean before it starts.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::obj {

constexpr std::int32_t kAbsent = -1;

struct Corner {
    std::int32_t v = kAbsent, vt = kAbsent, vn = kAbsent;  // 0-based, relative indices resolved
};

struct MaterialUse {
    std::uint32_t firstFace;  // from this face on (until the next use)
    std::string name;
};

struct Parsed {
    std::vector<float> positions;             // x y z per `v` (extra colour values are ignored)
    std::vector<float> texcoords;             // u v per `vt`
    std::vector<float> normals;               // x y z per `vn`
    std::vector<std::uint32_t> positionLine;  // source line of each `v`, for messages
    std::vector<Corner> corners;
    std::vector<std::uint32_t> faceStart;  // face f: corners[faceStart[f], faceStart[f + 1])
    std::vector<std::uint32_t> faceLine;   // source line of each face
    std::vector<MaterialUse> materials;    // `usemtl`, in file order
    std::vector<std::string> libraries;    // `mtllib` file names, in file order

    std::size_t faceCount() const { return faceLine.size(); }
};

// Throws Error "name:line: problem" for a statement it cannot read: a number that is not one, an
// index of 0 or one that is out of range for what the file defines, a relative index reaching
// before the first element. Unknown statements (groups, smoothing, lines, points) are skipped.
Parsed parse(std::string_view text, const std::string& name);

}  // namespace penumbra::obj
