// Which triangles can be rendered: loaders drop the others and say how many, by reason, so a
// file whose faces are all unusable is an error rather than a silently black image.
#pragma once

#include <cstddef>
#include <string>

#include "core/vec.h"
#include "scene/scene.h"

namespace penumbra {

enum class FaceDefect {
    None,
    Degenerate,  // no area (repeated or collinear corners)
    NotFinite,   // a corner, an edge, the normal or its squared length is NaN or infinite: the
                 // coordinates are not numbers or are so large that float arithmetic overflows
};

FaceDefect faceDefect(Vec3 a, Vec3 b, Vec3 c);

// The faces a loader left out, by reason.
struct SkippedFaces {
    std::size_t degenerate = 0;
    std::size_t notFinite = 0;

    void add(FaceDefect d);
    std::size_t total() const { return degenerate + notFinite; }
    // One warning per reason that occurred, prefixed with `file`.
    void warn(const std::string& file) const;
    // "1 degenerate face and 2 faces with non-finite coordinates": for the error when none is left.
    std::string describe() const;
};

// Removes the triangles of `mesh` that repeat a vertex or have a defect, counting them.
void dropBadTriangles(Mesh& mesh, SkippedFaces& skipped);

}  // namespace penumbra
