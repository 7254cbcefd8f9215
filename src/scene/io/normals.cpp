#include "scene/io/normals.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

#include "core/big_buffer.h"
#include "core/parallel.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

// Above this many faces around one position, smoothing would cost O(n^2); such fans (cone tips,
// hostile files) get flat normals instead.
constexpr std::size_t kMaxFan = 256;
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// acos to within 7e-5 radians (Abramowitz & Stegun 4.4.45), several times cheaper than the
// library's: three of these per triangle are most of the arithmetic for a big mesh, and normals
// weighted by angles that far off are indistinguishable.
float fastAcos(float x) {
    const float a = std::fabs(x);
    const float r = std::sqrt(1.0f - a) * (1.5707288f + a * (-0.2121144f + a * (0.0742610f - 0.0187293f * a)));
    return x < 0 ? kPiF - r : r;
}

// Angle at vertex `a` of the triangle a-b-c, in radians; 0 for degenerate corners.
float cornerAngle(Vec3 a, Vec3 b, Vec3 c) {
    Vec3 u = normalize(b - a), v = normalize(c - a);
    float d = std::clamp(dot(u, v), -1.0f, 1.0f);
    float angle = fastAcos(d);
    return std::isfinite(angle) ? angle : 0.0f;
}

}  // namespace

namespace {

// Welds vertices with bit-identical positions: posId[v] numbers the distinct positions in order
// of first appearance. An open-addressing hash table, linear in the vertex count.
std::uint32_t weldPositions(const std::vector<Vec3>& positions, std::vector<std::uint32_t>& posId) {
    const std::size_t n = positions.size();
    std::size_t slots = 16;
    while (slots < 2 * n) slots *= 2;
    std::vector<std::uint32_t> table = hugeVector<std::uint32_t>(slots, kNone);  // vertex whose position owns the slot
    posId = hugeVector<std::uint32_t>(n);
    std::uint32_t ids = 0;
    for (std::size_t v = 0; v < n; ++v) {
        const Vec3& p = positions[v];
        const std::uint64_t bx = std::bit_cast<std::uint32_t>(p.x), by = std::bit_cast<std::uint32_t>(p.y),
                            bz = std::bit_cast<std::uint32_t>(p.z);
        std::uint64_t h = (bx * 0x9E3779B97F4A7C15ull) ^ (by * 0xC2B2AE3D27D4EB4Full) ^ (bz * 0x165667B19E3779F9ull);
        h ^= h >> 29;
        for (std::size_t s = h & (slots - 1);; s = (s + 1) & (slots - 1)) {
            const std::uint32_t owner = table[s];
            if (owner == kNone) {
                table[s] = std::uint32_t(v);
                posId[v] = ids++;
                break;
            }
            const Vec3& q = positions[owner];
            if (std::bit_cast<std::uint32_t>(q.x) == bx && std::bit_cast<std::uint32_t>(q.y) == by &&
                std::bit_cast<std::uint32_t>(q.z) == bz) {
                posId[v] = posId[owner];
                break;
            }
        }
    }
    return ids;
}

// Unit face normals (zero for degenerate faces) and the angle at each corner.
void faceNormalsAndAngles(const Mesh& mesh, std::vector<Vec3>& faceNormal, std::vector<float>& angle) {
    const std::size_t triCount = mesh.indices.size() / 3;
    faceNormal = hugeVector<Vec3>(triCount);
    angle = hugeVector<float>(triCount * 3);
    parallelFor(triCount, 16 * 1024, [&](std::size_t lo, std::size_t hi) {
        for (std::size_t t = lo; t < hi; ++t) {
            const Vec3 p0 = mesh.positions[mesh.indices[3 * t]];
            const Vec3 p1 = mesh.positions[mesh.indices[3 * t + 1]];
            const Vec3 p2 = mesh.positions[mesh.indices[3 * t + 2]];
            Vec3 n = normalize(cross(p1 - p0, p2 - p0));
            faceNormal[t] = isFinite(n) ? n : Vec3{};
            angle[3 * t] = cornerAngle(p0, p1, p2);
            angle[3 * t + 1] = cornerAngle(p1, p2, p0);
            angle[3 * t + 2] = cornerAngle(p2, p0, p1);
        }
    });
}

// The corners (index-buffer positions) around each welded position, as compressed rows: those of
// position id i are corners[start[i] .. start[i + 1]).
struct CornerFans {
    std::vector<std::uint32_t> start, corners;
};

CornerFans cornersAroundPositions(const std::vector<std::uint32_t>& indices, const std::vector<std::uint32_t>& posId,
                                  std::size_t idCount) {
    CornerFans fans;
    fans.start = hugeVector<std::uint32_t>(idCount + 1, 0);
    for (std::uint32_t v : indices) ++fans.start[posId[v] + 1];
    std::partial_sum(fans.start.begin(), fans.start.end(), fans.start.begin());
    fans.corners = hugeVector<std::uint32_t>(indices.size());
    std::vector<std::uint32_t> fill(fans.start.begin(), fans.start.end() - 1);
    for (std::size_t c = 0; c < indices.size(); ++c) fans.corners[fill[posId[indices[c]]]++] = static_cast<std::uint32_t>(c);
    return fans;
}

// One normal per corner: the angle-weighted sum of the faces around its position within the
// crease (flat beyond kMaxFan faces).
std::vector<Vec3> smoothCornerNormals(const CornerFans& fans, const std::vector<Vec3>& faceNormal,
                                      const std::vector<float>& angle, float cosCrease) {
    std::vector<Vec3> cornerNormal = hugeVector<Vec3>(fans.corners.size());
    parallelFor(fans.start.size() - 1, 16 * 1024, [&](std::size_t lo, std::size_t hi) {
        for (std::size_t id = lo; id < hi; ++id) {
            const std::uint32_t* begin = fans.corners.data() + fans.start[id];
            const std::uint32_t* end = fans.corners.data() + fans.start[id + 1];
            const bool tooMany = std::size_t(end - begin) > kMaxFan;
            for (const std::uint32_t* c = begin; c != end; ++c) {
                const Vec3 fn = faceNormal[*c / 3];
                Vec3 sum{};
                if (!tooMany && dot(fn, fn) > 0) {
                    // Same iteration order for every corner, so corners with the same set of
                    // faces get bit-identical sums and share a vertex below.
                    for (const std::uint32_t* o = begin; o != end; ++o) {
                        const Vec3 on = faceNormal[*o / 3];
                        if (dot(fn, on) >= cosCrease) sum += on * angle[*o];
                    }
                }
                Vec3 n = normalize(sum);
                if (dot(n, n) == 0) n = dot(fn, fn) > 0 ? fn : Vec3{0, 1, 0};
                cornerNormal[*c] = n;
            }
        }
    });
    return cornerNormal;
}

// Gives every corner its normal, splitting vertices whose corners ended up with different ones.
void splitVerticesByNormal(Mesh& mesh, const std::vector<Vec3>& cornerNormal) {
    const std::size_t vertexCount = mesh.positions.size();
    struct Entry {  // one of a vertex's normals so far, in a list per vertex
        Vec3 normal;
        std::uint32_t index;
        std::uint32_t next;
    };
    std::vector<std::uint32_t> head = hugeVector<std::uint32_t>(vertexCount, kNone);
    std::vector<Entry> entries;
    reserveHuge(entries, vertexCount + vertexCount / 2);
    std::vector<Vec3> positions;
    std::vector<Vec2> uvs;
    std::vector<Vec3> normals;
    reserveHuge(positions, vertexCount);
    reserveHuge(normals, vertexCount);
    const bool hasUvs = !mesh.uvs.empty();
    if (hasUvs) reserveHuge(uvs, vertexCount);
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const std::uint32_t v = mesh.indices[c];
        const Vec3 n = cornerNormal[c];
        std::uint32_t found = kNone;
        for (std::uint32_t e = head[v]; e != kNone; e = entries[e].next)
            if (entries[e].normal == n) {
                found = entries[e].index;
                break;
            }
        if (found == kNone) {
            found = static_cast<std::uint32_t>(positions.size());
            positions.push_back(mesh.positions[v]);
            normals.push_back(n);
            if (hasUvs) uvs.push_back(mesh.uvs[v]);
            entries.push_back({n, found, head[v]});
            head[v] = static_cast<std::uint32_t>(entries.size() - 1);
        }
        mesh.indices[c] = found;
    }
    mesh.positions = std::move(positions);
    mesh.normals = std::move(normals);
    mesh.uvs = std::move(uvs);
}

}  // namespace

void generateCreaseNormals(Mesh& mesh, float creaseDegrees) {
    if (mesh.positions.empty() || mesh.indices.size() < 3) {
        mesh.normals.clear();
        return;
    }
    // Vertices with bit-identical positions share a position id, so smoothing crosses seams.
    std::vector<std::uint32_t> posId;
    const std::size_t idCount = weldPositions(mesh.positions, posId);
    std::vector<Vec3> faceNormal;
    std::vector<float> angle;
    faceNormalsAndAngles(mesh, faceNormal, angle);
    const CornerFans fans = cornersAroundPositions(mesh.indices, posId, idCount);
    const float cosCrease = std::cos(degreesToRadians(creaseDegrees));
    splitVerticesByNormal(mesh, smoothCornerNormals(fans, faceNormal, angle, cosCrease));
}

Camera cameraFittingBounds(const Aabb& bounds, float fovYDegrees) {
    Camera camera;
    camera.fovYDegrees = fovYDegrees;
    if (bounds.empty() || !isFinite(bounds.lo) || !isFinite(bounds.hi)) return camera;
    const Vec3 center = bounds.center();
    float radius = 0.5f * length(bounds.extent());
    if (!(radius > 0) || !std::isfinite(radius)) radius = 1.0f;
    const float distance = radius / std::sin(degreesToRadians(0.5f * fovYDegrees));
    Camera fitted = camera;
    fitted.position = center + Vec3{0, 0, distance};
    fitted.lookAt = center;
    fitted.up = {0, 1, 0};
    // Coordinates near the float limit would put the camera at infinity or on the centre.
    if (!isFinite(fitted.position) || fitted.position == fitted.lookAt) return camera;
    return fitted;
}

}  // namespace penumbra
