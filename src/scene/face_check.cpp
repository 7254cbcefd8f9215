#include "scene/face_check.h"

#include <cmath>

#include "core/log.h"

namespace penumbra {

FaceDefect faceDefect(Vec3 a, Vec3 b, Vec3 c) {
    const Vec3 e1 = b - a, e2 = c - a;
    const Vec3 n = cross(e1, e2);
    const float area2 = dot(n, n);  // the renderer normalises n: this must not overflow either
    if (!isFinite(a) || !isFinite(b) || !isFinite(c) || !isFinite(e1) || !isFinite(e2) || !isFinite(n) ||
        !std::isfinite(area2))
        return FaceDefect::NotFinite;
    return area2 > 0 ? FaceDefect::None : FaceDefect::Degenerate;
}

void SkippedFaces::add(FaceDefect d) {
    if (d == FaceDefect::Degenerate) ++degenerate;
    if (d == FaceDefect::NotFinite) ++notFinite;
}

namespace {
std::string faces(std::size_t n, const char* what) {
    return std::to_string(n) + (n == 1 ? " face " : " faces ") + what;
}
constexpr const char* kDegenerate = "without area (degenerate)";
constexpr const char* kNotFinite = "with coordinates that are not finite numbers or too large to compute with";
}  // namespace

void SkippedFaces::warn(const std::string& file) const {
    if (degenerate > 0) logWarning(file + ": skipped " + faces(degenerate, kDegenerate));
    if (notFinite > 0) logWarning(file + ": skipped " + faces(notFinite, kNotFinite));
}

std::string SkippedFaces::describe() const {
    std::string out;
    if (degenerate > 0) out = faces(degenerate, kDegenerate);
    if (notFinite > 0) out += (out.empty() ? "" : " and ") + faces(notFinite, kNotFinite);
    return out;
}

void dropBadTriangles(Mesh& mesh, SkippedFaces& skipped) {
    std::vector<std::uint32_t>& idx = mesh.indices;
    std::size_t kept = 0;
    for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
        const std::uint32_t a = idx[t], b = idx[t + 1], c = idx[t + 2];
        const FaceDefect d = a == b || b == c || a == c
                                 ? FaceDefect::Degenerate
                                 : faceDefect(mesh.positions[a], mesh.positions[b], mesh.positions[c]);
        if (d != FaceDefect::None) {
            skipped.add(d);
            continue;
        }
        idx[kept++] = a;
        idx[kept++] = b;
        idx[kept++] = c;
    }
    idx.resize(kept);
}

}  // namespace penumbra
