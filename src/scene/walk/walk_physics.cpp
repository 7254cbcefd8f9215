#include "scene/walk/walk_physics.h"

#include <algorithm>
#include <cmath>

namespace penumbra::walk {
namespace {

constexpr int kMaxSubsteps = 4096;      // bounds the work of one call, whatever dt and speed
constexpr double kMinSubstepRate = 70;  // falls are integrated at 70 Hz or finer
constexpr int kBisections = 10;         // a blocked move stops within 8 / 1024 units of the wall

// Moves the player to (x, y) if it may stand there (Doom's P_TryMove for a player).
bool tryMove(const WalkMap& map, WalkState& s, double x, double y) {
    if (!canStandAt(map, x, y, s.z)) return false;
    s.x = x;
    s.y = y;
    return true;
}

// Moves as far along (mx, my) as the player may go, by bisection (the start is valid). Returns
// the fraction moved; the position at fraction `blockedAt` is one the player may not take.
double moveUntilBlocked(const WalkMap& map, WalkState& s, double mx, double my,
                        double* blockedAt = nullptr) {
    if (tryMove(map, s, s.x + mx, s.y + my)) return 1.0;
    double lo = 0, hi = 1;
    for (int i = 0; i < kBisections; ++i) {
        const double mid = 0.5 * (lo + hi);
        (canStandAt(map, s.x + mid * mx, s.y + mid * my, s.z) ? lo : hi) = mid;
    }
    if (lo > 0) tryMove(map, s, s.x + lo * mx, s.y + lo * my);
    if (blockedAt) *blockedAt = (hi - lo) / std::max(1.0 - lo, 1e-12);  // in terms of what is left
    return lo;
}

// Whether a line alone stops a player with feet at z (Doom's line opening tests).
bool lineStops(const WalkMap& map, const WalkLine& l, double z) {
    if (l.impassable()) return true;
    const WalkSector& f = map.sectors[std::size_t(l.front)];
    const WalkSector& b = map.sectors[std::size_t(l.back)];
    const double top = std::min(f.ceiling, b.ceiling), bottom = std::max(f.floor, b.floor);
    return top - bottom < kPlayerHeight || top - z < kPlayerHeight || bottom - z > kMaxStepUp;
}

double distanceToLine(const WalkLine& l, double px, double py) {
    const double dx = l.x2 - l.x1, dy = l.y2 - l.y1;
    const double len2 = dx * dx + dy * dy;
    const double t =
        len2 > 0 ? std::clamp(((px - l.x1) * dx + (py - l.y1) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(l.x1 + t * dx - px, l.y1 + t * dy - py);
}

// The stopping line nearest the player among those its box would cross at (x, y); null if the
// stop comes from something else (the map's edge, several openings together).
const WalkLine* stoppingLine(const WalkMap& map, const WalkState& s, double x, double y) {
    const WalkLine* best = nullptr;
    double bestDistance = INFINITY;
    const double r = kPlayerRadius;
    forEachLineNear(map, x - r, y - r, x + r, y + r, [&](std::uint32_t i) {
        const WalkLine& l = map.lines[i];
        if (!lineCrossesBox(l, x - r, y - r, x + r, y + r) || !lineStops(map, l, s.z)) return;
        const double d = distanceToLine(l, s.x, s.y);
        if (d < bestDistance) bestDistance = d, best = &l;
    });
    return best;
}

// One piece of horizontal movement: straight if possible, else up to the obstacle and then the
// rest along the wall that stopped it, or failing that along whichever axis is free.
void moveHorizontally(const WalkMap& map, WalkState& s, double mx, double my) {
    double blockedAt = 1;
    const double moved = moveUntilBlocked(map, s, mx, my, &blockedAt);
    if (moved >= 1.0) return;
    const double rx = (1 - moved) * mx, ry = (1 - moved) * my;
    if (const WalkLine* wall = stoppingLine(map, s, s.x + blockedAt * rx, s.y + blockedAt * ry)) {
        const double dx = wall->x2 - wall->x1, dy = wall->y2 - wall->y1;
        const double len2 = dx * dx + dy * dy;
        const double along = (rx * dx + ry * dy) / len2;
        if (along != 0 && moveUntilBlocked(map, s, along * dx, along * dy) > 0) return;
    }
    // A corner, or no single wall to blame: Doom's "stairstep", each axis on its own.
    if (!tryMove(map, s, s.x + rx, s.y)) tryMove(map, s, s.x, s.y + ry);
}

// Gravity, landing, stepping up onto the floor and keeping the head under the ceiling.
void moveVertically(const WalkMap& map, WalkState& s, double dt) {
    const Opening o = openingAt(map, s.x, s.y);
    if (o.blocked) return;  // not a valid position (a caller's state): leave height alone
    if (s.z > o.floor || s.vz > 0) {
        s.vz -= kGravity * dt;
        s.z += s.vz * dt;
    }
    if (s.z <= o.floor) {
        s.z = o.floor;
        s.vz = 0;
    }
    if (s.z + kPlayerHeight > o.ceiling) {
        s.z = std::max(o.floor, o.ceiling - kPlayerHeight);
        s.vz = std::min(s.vz, 0.0);
    }
}

}  // namespace

Opening openingAt(const WalkMap& map, double x, double y) {
    Opening o;
    const std::int32_t sector = sectorAt(map, x, y);
    if (sector < 0) return o;
    o.floor = map.sectors[std::size_t(sector)].floor;
    o.ceiling = map.sectors[std::size_t(sector)].ceiling;
    bool blocked = false;
    const double r = kPlayerRadius;
    forEachLineNear(map, x - r, y - r, x + r, y + r, [&](std::uint32_t i) {
        const WalkLine& l = map.lines[i];
        if (blocked || !lineCrossesBox(l, x - r, y - r, x + r, y + r)) return;
        if (l.impassable()) {
            blocked = true;
            return;
        }
        const WalkSector& f = map.sectors[std::size_t(l.front)];
        const WalkSector& b = map.sectors[std::size_t(l.back)];
        o.floor = std::max({o.floor, f.floor, b.floor});
        o.ceiling = std::min({o.ceiling, f.ceiling, b.ceiling});
    });
    o.blocked = blocked;
    return o;
}

bool canStandAt(const WalkMap& map, double x, double y, double z, Opening* opening) {
    const Opening o = openingAt(map, x, y);
    if (opening) *opening = o;
    return !o.blocked && o.ceiling - o.floor >= kPlayerHeight && o.ceiling - z >= kPlayerHeight &&
           o.floor - z <= kMaxStepUp;
}

std::optional<WalkState> placePlayer(const WalkMap& map, double x, double y, double z) {
    if (!std::isfinite(z)) return std::nullopt;
    const Opening o = openingAt(map, x, y);
    if (o.blocked || o.ceiling - o.floor < kPlayerHeight) return std::nullopt;
    WalkState s;
    s.x = x;
    s.y = y;
    s.z = std::clamp(z, o.floor, o.ceiling - kPlayerHeight);
    return s;
}

WalkState stepWalk(const WalkMap& map, WalkState s, double vx, double vy, double dt) {
    if (!(dt > 0) || !std::isfinite(dt) || !std::isfinite(vx) || !std::isfinite(vy)) return s;
    double mx = vx * dt, my = vy * dt;
    const double distance = std::hypot(mx, my);
    const double wanted =
        std::max(std::ceil(distance / kMaxSubstep), std::ceil(dt * kMinSubstepRate));
    const int steps = int(std::clamp(wanted, 1.0, double(kMaxSubsteps)));
    if (distance > steps * kMaxSubstep) {  // longer than the work bound allows: shortened
        mx *= steps * kMaxSubstep / distance;
        my *= steps * kMaxSubstep / distance;
    }
    for (int i = 0; i < steps; ++i) {
        if (mx != 0 || my != 0) moveHorizontally(map, s, mx / steps, my / steps);
        moveVertically(map, s, dt / steps);
    }
    return s;
}

}  // namespace penumbra::walk
