#include "scene/io/wad/triangulate.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace penumbra::wad {
namespace {

std::uint32_t vertexKey(const Vertex& v) {
    return (std::uint32_t(std::uint16_t(v.x)) << 16) | std::uint16_t(v.y);
}
Point2 keyPoint(std::uint32_t key) {
    return {double(std::int16_t(key >> 16)), double(std::int16_t(key & 0xFFFF))};
}

struct KeyEdge {
    std::uint32_t from, to;
};

// Closes open chains so every vertex is balanced; returns the number of chains closed.
int closeChains(std::vector<KeyEdge>& edges) {
    std::unordered_map<std::uint32_t, int> balance;  // out - in
    for (const KeyEdge& e : edges) {
        ++balance[e.from];
        --balance[e.to];
    }
    bool balanced = true;
    for (const auto& [key, b] : balance) balanced = balanced && b == 0;
    if (balanced) return 0;

    // Walk from each vertex with surplus outgoing edges along unused edges until stuck; the
    // end has surplus incoming edges. Each step uses up an edge, so the walks terminate.
    std::unordered_map<std::uint32_t, std::vector<std::size_t>> outgoing;
    for (std::size_t i = 0; i < edges.size(); ++i) outgoing[edges[i].from].push_back(i);
    std::vector<KeyEdge> closing;
    std::vector<std::uint32_t> starts;
    for (const auto& [key, b] : balance)
        for (int k = 0; k < b; ++k) starts.push_back(key);
    std::sort(starts.begin(), starts.end());  // deterministic order
    for (std::uint32_t start : starts) {
        std::uint32_t at = start;
        for (;;) {
            auto it = outgoing.find(at);
            if (it == outgoing.end() || it->second.empty()) break;
            std::size_t e = it->second.back();
            it->second.pop_back();
            at = edges[e].to;
        }
        if (at != start) closing.push_back({at, start});
    }
    edges.insert(edges.end(), closing.begin(), closing.end());
    return int(closing.size());
}

struct SlabEdge {
    double x0, y0, x1, y1;  // x0 < x1
    int dir;                // +1 when the directed edge runs towards +x

    double yAt(double x) const {
        if (x <= x0) return y0;
        if (x >= x1) return y1;
        return y0 + (y1 - y0) * ((x - x0) / (x1 - x0));
    }
};

// Output triangles are charged to the budget too, which bounds the memory a map can take.
constexpr std::int64_t kTriangleCost = 50;

struct OpenTrap {
    int top, bottom;
    double xStart;
};

class SlabFill {
public:
    SlabFill(const std::vector<SlabEdge>& edges, std::vector<Triangle2>& out, std::int64_t& budget)
        : edges_(edges), out_(out), budget_(budget) {}

    // Processes [xa, xb] with the given active edges; false when the budget ran out.
    bool slab(const std::vector<int>& active, double xa, double xb, int depth) {
        budget_ -= std::int64_t(active.size()) + 1;
        if (budget_ < 0) return false;
        const double xm = 0.5 * (xa + xb);
        sorted_ = active;
        std::sort(sorted_.begin(), sorted_.end(), [&](int a, int b) {
            double ya = edges_[a].yAt(xm), yb = edges_[b].yAt(xm);
            return ya != yb ? ya > yb : a < b;
        });
        // Crossing lines swap order inside the slab: split the slab at the crossing.
        if (depth < 24) {
            for (std::size_t i = 0; i + 1 < sorted_.size(); ++i) {
                const SlabEdge& p = edges_[sorted_[i]];
                const SlabEdge& q = edges_[sorted_[i + 1]];
                double da = p.yAt(xa) - q.yAt(xa), db = p.yAt(xb) - q.yAt(xb);
                if (da < -1e-9 || db < -1e-9) {
                    double xc = xa + (xb - xa) * (da / (da - db));
                    if (std::isfinite(xc) && xc > xa + 1e-7 && xc < xb - 1e-7) {
                        std::vector<int> copy = active;
                        return slab(copy, xa, xc, depth + 1) && slab(copy, xc, xb, depth + 1);
                    }
                }
            }
        }
        current_.clear();
        int winding = 0;
        for (std::size_t i = 0; i + 1 < sorted_.size(); ++i) {
            winding += edges_[sorted_[i]].dir;
            if (winding != 0) current_.push_back({sorted_[i], sorted_[i + 1], xa});
        }
        // Continue trapezoids bounded by the same pair of edges; close the others at xa.
        for (OpenTrap& c : current_)
            for (const OpenTrap& o : open_)
                if (o.top == c.top && o.bottom == c.bottom) c.xStart = o.xStart;
        for (const OpenTrap& o : open_) {
            bool continues = false;
            for (const OpenTrap& c : current_)
                continues = continues || (o.top == c.top && o.bottom == c.bottom);
            if (!continues) emit(o, xa);
        }
        budget_ -= std::int64_t(current_.size() * open_.size());
        std::swap(open_, current_);
        return budget_ >= 0;
    }

    void finish(double x) {
        for (const OpenTrap& o : open_) emit(o, x);
        open_.clear();
    }

private:
    void emit(const OpenTrap& t, double xEnd) {
        const SlabEdge& top = edges_[t.top];
        const SlabEdge& bottom = edges_[t.bottom];
        double xl = t.xStart, xr = xEnd;
        Point2 tl{xl, top.yAt(xl)}, tr{xr, top.yAt(xr)};
        Point2 bl{xl, bottom.yAt(xl)}, br{xr, bottom.yAt(xr)};
        addTriangle({bl, br, tr});
        addTriangle({bl, tr, tl});
    }
    void addTriangle(const Triangle2& t) {
        double area = (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y);
        if (std::abs(area) > 1e-9) {
            out_.push_back(t);
            budget_ -= kTriangleCost;
        }
    }

    const std::vector<SlabEdge>& edges_;
    std::vector<Triangle2>& out_;
    std::int64_t& budget_;
    std::vector<int> sorted_;
    std::vector<OpenTrap> open_, current_;
};

}  // namespace

std::vector<SectorOutline> buildSectorOutlines(const MapData& map) {
    std::vector<std::vector<KeyEdge>> perSector(map.sectors.size());
    for (const Linedef& line : map.linedefs) {
        std::uint32_t a = vertexKey(map.vertices[line.v1]);
        std::uint32_t b = vertexKey(map.vertices[line.v2]);
        if (a == b) continue;
        int front = line.front != kNoSide ? map.sidedefs[line.front].sector : -1;
        int back = line.back != kNoSide ? map.sidedefs[line.back].sector : -1;
        if (front == back) continue;
        if (front >= 0) perSector[std::size_t(front)].push_back({a, b});
        if (back >= 0) perSector[std::size_t(back)].push_back({b, a});
    }
    std::vector<SectorOutline> outlines(map.sectors.size());
    for (std::size_t s = 0; s < perSector.size(); ++s) {
        outlines[s].closedChains = closeChains(perSector[s]);
        outlines[s].edges.reserve(perSector[s].size());
        for (const KeyEdge& e : perSector[s])
            if (e.from != e.to) outlines[s].edges.push_back({keyPoint(e.from), keyPoint(e.to)});
    }
    return outlines;
}

bool fillNonzero(const std::vector<Edge2>& input, std::vector<Triangle2>& out,
                 std::int64_t& budget) {
    std::vector<SlabEdge> edges;
    std::vector<double> xs;
    edges.reserve(input.size());
    for (const Edge2& e : input) {
        xs.push_back(e.a.x);
        xs.push_back(e.b.x);
        if (e.a.x == e.b.x) continue;  // vertical edges bound slabs but are never crossed
        if (e.a.x < e.b.x)
            edges.push_back({e.a.x, e.a.y, e.b.x, e.b.y, +1});
        else
            edges.push_back({e.b.x, e.b.y, e.a.x, e.a.y, -1});
    }
    if (edges.empty()) return true;
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    std::vector<int> byStart(edges.size());
    for (std::size_t i = 0; i < edges.size(); ++i) byStart[i] = int(i);
    std::sort(byStart.begin(), byStart.end(),
              [&](int a, int b) { return edges[a].x0 < edges[b].x0; });

    const std::size_t keep = out.size();
    SlabFill fill(edges, out, budget);
    std::vector<int> active;
    std::size_t next = 0;
    for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
        const double xa = xs[k], xb = xs[k + 1];
        while (next < byStart.size() && edges[byStart[next]].x0 <= xa) active.push_back(byStart[next++]);
        std::erase_if(active, [&](int e) { return edges[e].x1 <= xa; });
        if (!fill.slab(active, xa, xb, 0)) {
            out.resize(keep);
            return false;
        }
    }
    fill.finish(xs.back());
    if (budget < 0) {
        out.resize(keep);
        return false;
    }
    return true;
}

}  // namespace penumbra::wad
