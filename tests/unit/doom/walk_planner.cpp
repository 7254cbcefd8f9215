#include "walk_planner.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <limits>
#include <queue>

#include "interact/input_script.h"
#include "interact/navigation.h"
#include "scene/doom/level.h"
#include "scene/io/wad/units.h"
#include "scene/walk/walk_physics.h"

namespace penumbra::test {
namespace {

using doom::Level;
using doom::Plane;

constexpr double kCell = 8;            // grid spacing, map units
constexpr double kMargin = 4;          // the path keeps the player's box this far from walls
constexpr double kArrive = 12;         // a waypoint is reached this close
constexpr double kTurnRate = 4.0;      // radians per second the walker turns at most
constexpr double kMousePixelRadians = 0.003;  // the controller's mouse sensitivity
constexpr double kLimitSeconds = 600;

// Where the player fits with its box grown by kMargin, and the floor there; none if it does not.
std::optional<double> standFloor(const walk::WalkMap& map, double x, double y) {
    double floor = -1e9;
    for (int i = 0; i < 5; ++i) {
        const double dx = i == 1 ? kMargin : i == 2 ? -kMargin : 0, dy = i == 3 ? kMargin : i == 4 ? -kMargin : 0;
        const walk::Opening o = walk::openingAt(map, x + dx, y + dy);
        if (o.blocked || o.ceiling - o.floor < walk::kPlayerHeight) return std::nullopt;
        if (i == 0) floor = o.floor;
    }
    return floor;
}

// The level with every door open and every moving floor at one end of its range: the planner's
// two views of what can be walked once the specials have run.
walk::WalkMap plannedMap(const Level& level, bool floorsHigh) {
    walk::WalkMap map = level.walkMap();
    for (std::size_t s = 0; s < map.sectors.size(); ++s) {
        const doom::PlaneRange c = level.range(int(s), Plane::Ceiling), f = level.range(int(s), Plane::Floor);
        if (c.moves) map.sectors[s].ceiling = c.high;
        if (f.moves) map.sectors[s].floor = floorsHigh ? f.high : f.low;
    }
    return map;
}

struct Point {
    double x = 0, y = 0;
};

// Whether one may walk from a to b (a short step or a straight segment) on this map.
bool canWalk(const walk::WalkMap& map, Point a, Point b) {
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const int steps = std::max(1, int(std::ceil(length / 4)));
    std::optional<double> last = standFloor(map, a.x, a.y);
    if (!last) return false;
    for (int i = 1; i <= steps; ++i) {
        const double t = double(i) / steps;
        const std::optional<double> f = standFloor(map, a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
        if (!f || *f - *last > walk::kMaxStepUp) return false;
        last = f;
    }
    return true;
}

class Planner {
public:
    explicit Planner(const Level& level) : low_(plannedMap(level, false)), high_(plannedMap(level, true)) {
        double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
        for (const walk::WalkLine& l : low_.lines) {
            x0 = std::min({x0, l.x1, l.x2}), x1 = std::max({x1, l.x1, l.x2});
            y0 = std::min({y0, l.y1, l.y2}), y1 = std::max({y1, l.y1, l.y2});
        }
        ox_ = x0, oy_ = y0;
        w_ = int((x1 - x0) / kCell) + 1, h_ = int((y1 - y0) / kCell) + 1;
    }

    bool walkable(Point a, Point b) const { return canWalk(low_, a, b) || canWalk(high_, a, b); }

    // One grid step, from the cells' floors on either map (cached): a wall between two cells 8
    // units apart always crosses the grown box at one of them.
    bool step(int a, int b) const {
        for (int m = 0; m < 2; ++m) {
            const float fa = floorOf(a, m), fb = floorOf(b, m);
            if (!std::isnan(fa) && !std::isnan(fb) && fb - fa <= walk::kMaxStepUp) return true;
        }
        return false;
    }
    float floorOf(int cell, int m) const {
        std::vector<float>& cache = m ? highFloors_ : lowFloors_;
        if (cache.empty()) cache.assign(std::size_t(w_) * h_, -1e30f);
        float& f = cache[std::size_t(cell)];
        if (f == -1e30f) {
            const Point p = centre(cell);
            const std::optional<double> got = standFloor(m ? high_ : low_, p.x, p.y);
            f = got ? float(*got) : std::numeric_limits<float>::quiet_NaN();
        }
        return f;
    }

    // A* over the grid from a to b (8-connected), then straightened; empty when there is no way.
    std::vector<Point> path(Point a, Point b) const {
        const int start = cellOf(a), goal = cellOf(b);
        std::vector<double> cost(std::size_t(w_) * h_, 1e18);
        std::vector<int> from(cost.size(), -1);
        using Item = std::pair<double, int>;
        std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
        cost[std::size_t(start)] = 0;
        open.push({0, start});
        while (!open.empty()) {
            const auto [f, c] = open.top();
            open.pop();
            if (c == goal) break;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int cx = c % w_ + dx, cy = c / w_ + dy;
                    if ((!dx && !dy) || cx < 0 || cy < 0 || cx >= w_ || cy >= h_) continue;
                    const int n = cy * w_ + cx;
                    const double g = cost[std::size_t(c)] + kCell * std::hypot(dx, dy);
                    if (g >= cost[std::size_t(n)]) continue;
                    const Point q = n == goal ? b : centre(n);
                    if (!step(c, n)) continue;
                    cost[std::size_t(n)] = g;
                    from[std::size_t(n)] = c;
                    open.push({g + std::hypot(q.x - b.x, q.y - b.y), n});
                }
        }
        if (from[std::size_t(goal)] < 0) return {};
        std::vector<Point> cells{b};
        for (int c = from[std::size_t(goal)]; c != start; c = from[std::size_t(c)]) cells.push_back(centre(c));
        cells.push_back(a);
        std::reverse(cells.begin(), cells.end());
        // Straightened: from each kept point, on to the furthest one still reachable in a line.
        std::vector<Point> out{cells.front()};
        for (std::size_t i = 0; i + 1 < cells.size();) {
            std::size_t j = i + 1;
            while (j + 1 < cells.size() && walkable(cells[i], cells[j + 1])) ++j;
            out.push_back(cells[j]);
            i = j;
        }
        return out;
    }

private:
    int cellOf(Point p) const {
        const int cx = std::clamp(int(std::lround((p.x - ox_) / kCell)), 0, w_ - 1);
        const int cy = std::clamp(int(std::lround((p.y - oy_) / kCell)), 0, h_ - 1);
        return cy * w_ + cx;
    }
    Point centre(int c) const { return {ox_ + (c % w_) * kCell, oy_ + (c / w_) * kCell}; }

    walk::WalkMap low_, high_;
    mutable std::vector<float> lowFloors_, highFloors_;
    double ox_ = 0, oy_ = 0;
    int w_ = 0, h_ = 0;
};

double wrapAngle(double a) {
    while (a > std::numbers::pi) a -= 2 * std::numbers::pi;
    while (a < -std::numbers::pi) a += 2 * std::numbers::pi;
    return a;
}

// The viewer's frame as `view --script` runs it, without the window: presses, then the move.
struct Session {
    const Scene& scene;
    viewer::Navigation nav;
    viewer::InputState input;
    double clock = 0;
    std::optional<std::string> completion;

    explicit Session(const Scene& s) : scene(s), nav(s, false) {}
    void frame() {
        if (std::string said = nav.handlePresses(input, scene); !said.empty()) (void)said;
        nav.update(viewer::cameraInputFrom(input), float(kWalkStep));
        if (!completion) completion = nav.takeLevelCompletion();
        viewer::endInputFrame(input);
        clock += kWalkStep;
    }
    Point position() const {
        const walk::WalkState& p = nav.controller().player();
        return {p.x, p.y};
    }
    double heading() const {
        const Camera c = nav.camera();
        const Vec3 f = wad::sceneToMap(c.lookAt - c.position);
        return std::atan2(double(f.y), double(f.x));
    }
};

// Records events into the script and feeds them to the session as the script player would.
struct Recorder {
    Session& session;
    std::string text;
    bool walking = false;

    void line(const char* what) {
        char t[32];
        std::snprintf(t, sizeof t, "%.5f ", session.clock);
        text += t;
        text += what;
        text += '\n';
    }
    void key(const char* name, int code, bool down) {
        line((std::string("key ") + name + (down ? " down" : " up")).c_str());
        viewer::applyKey(session.input, code, down);
    }
    void walk(bool on) {
        if (on != walking) key("W", GLFW_KEY_W, on);
        walking = on;
    }
    // Turns toward `angle` (map radians) by at most the turn rate this frame; the error left.
    double turnToward(double angle) {
        const double error = wrapAngle(angle - session.heading());
        const double limit = kTurnRate * kWalkStep;
        const double turn = std::clamp(error, -limit, limit);
        if (std::abs(turn) < 1e-4) return error;
        char dx[32];
        std::snprintf(dx, sizeof dx, "%.3f", -turn / kMousePixelRadians);
        line((std::string("mouse ") + dx + " 0").c_str());
        viewer::applyLook(session.input, std::strtof(dx, nullptr), 0);
        return error - turn;
    }
    void use() {
        key("SPACE", GLFW_KEY_SPACE, true);
        key("SPACE", GLFW_KEY_SPACE, false);
    }
};

// The first point of the segment a -> b where the player does not fit now but will once the
// specials have run (a closed door, a lift at the other end), as a distance from a. Walls that
// are there for good do not count: the walker slides along them.
std::optional<double> blockedAt(const walk::WalkMap& now, const Planner& planner, Point a, Point b) {
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const int steps = std::max(1, int(std::ceil(length / 4)));
    std::optional<double> last = standFloor(now, a.x, a.y);
    Point previous = a;
    for (int i = 1; i <= steps; ++i) {
        const double t = double(i) / steps;
        const Point q{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
        const std::optional<double> f = standFloor(now, q.x, q.y);
        const bool fitsNow = f && (!last || *f - *last <= walk::kMaxStepUp);
        if (!fitsNow) return planner.walkable(previous, q) ? std::optional<double>(t * length) : std::nullopt;
        last = f;
        previous = q;
    }
    return std::nullopt;
}

// The direction to face to use the nearest door or switch the player can reach from where it
// stands (a line with a manual or switch special, seen from its front), other than the exit.
std::optional<double> useAngle(const Level& level, Point p) {
    std::optional<double> best;
    double bestDistance = 56;
    for (const Level::LineState& l : level.lines()) {
        const std::optional<doom::LineSpecial> sp = doom::lineSpecial(l.special);
        if (!sp || (sp->trigger != doom::Trigger::Manual && sp->trigger != doom::Trigger::Switch) ||
            sp->action == doom::Action::ExitLevel || sp->action == doom::Action::SecretExit)
            continue;
        const double dx = l.x2 - l.x1, dy = l.y2 - l.y1, len2 = dx * dx + dy * dy;
        if (len2 <= 0 || dx * (p.y - l.y1) - dy * (p.x - l.x1) >= 0) continue;  // behind it
        const double t = std::clamp(((p.x - l.x1) * dx + (p.y - l.y1) * dy) / len2, 0.1, 0.9);
        const Point q{l.x1 + t * dx, l.y1 + t * dy};
        const double d = std::hypot(q.x - p.x, q.y - p.y);
        if (d < bestDistance) bestDistance = d, best = std::atan2(q.y - p.y, q.x - p.x);
    }
    return best;
}

}  // namespace

// A place to walk to, and optionally the line to use there (facing it from its front).
struct Stop {
    Point at;
    std::optional<std::size_t> line;
    double facing = 0;
};

// Where to stand to use a line: in front of its middle, facing it.
Stop stopToUse(const Level& level, std::size_t index) {
    const Level::LineState& l = level.lines()[index];
    const double dx = l.x2 - l.x1, dy = l.y2 - l.y1, len = std::hypot(dx, dy);
    const Point normal{dy / len, -dx / len};  // toward the front (right of v1 -> v2)
    const double reach = walk::kPlayerRadius + kMargin + 8;
    return {{(l.x1 + l.x2) / 2 + normal.x * reach, (l.y1 + l.y2) / 2 + normal.y * reach}, index,
            std::atan2(-normal.y, -normal.x)};
}

// A switch that moves the sector in the way at q (a floor to lower, say), not yet used.
std::optional<std::size_t> switchFor(const Level& level, const walk::WalkMap& now, Point q) {
    for (int i = 0; i < 49; ++i) {  // the sectors under the player's grown box there
        const double ox = (i % 7 - 3) * 8.0, oy = (i / 7 - 3) * 8.0;
        const int sector = walk::sectorAt(now, q.x + ox, q.y + oy);
        if (sector < 0 || level.sectorTag(sector) == 0) continue;
        for (std::size_t k = 0; k < level.lines().size(); ++k) {
            const Level::LineState& l = level.lines()[k];
            const std::optional<doom::LineSpecial> sp = doom::lineSpecial(l.special);
            if (sp && sp->trigger == doom::Trigger::Switch && l.tag == level.sectorTag(sector)) return k;
        }
    }
    return std::nullopt;
}

std::optional<PlannedWalk> planWalk(const Scene& scene, const std::string& title, std::string* why) {
    auto fail = [&](const std::string& reason) -> std::optional<PlannedWalk> {
        if (why) *why = reason;
        return std::nullopt;
    };
    if (!scene.doomLevel) return fail("not a Doom level");
    const Level& level = *scene.doomLevel;
    Planner planner(level);
    Session session(scene);
    if (!session.nav.walking()) return fail("the player start is not walkable");
    const bool debug = std::getenv("PENUMBRA_WALK_DEBUG") != nullptr;

    // Keys first (nearest first as listed), then the exit switch.
    std::vector<Stop> stops;
    for (const auto& key : level.keyPositions()) stops.push_back({{key.first, key.second}, std::nullopt, 0});
    for (std::size_t k = 0; k < level.lines().size(); ++k) {
        const std::optional<doom::LineSpecial> sp = doom::lineSpecial(level.lines()[k].special);
        if (sp && sp->action == doom::Action::ExitLevel && sp->trigger == doom::Trigger::Switch)
            stops.push_back(stopToUse(level, k));
    }
    if (stops.empty() || !stops.back().line) return fail("the map has no exit switch");

    Recorder rec{session};
    rec.text = "# " + title + "\n# Written by tests/unit/doom/walk_planner.cpp (PENUMBRA_WRITE_WALKS); play with\n"
               "#   penumbra view WAD --map E1M1 --script FILE --fixed-dt 0.03125\n";
    for (std::size_t stop = 0; stop < stops.size();) {
        const std::vector<Point> path = planner.path(session.position(), stops[stop].at);
        if (path.empty()) return fail("no path to stop " + std::to_string(stop));
        if (debug)
            for (const Point& q : path) std::fprintf(stderr, "  stop %zu waypoint %.0f %.0f\n", stop, q.x, q.y);
        std::size_t next = 1;
        double waitingSince = -1, blockedSince = -1;
        bool detour = false;
        while (next < path.size() && !detour) {
            if (session.clock > kLimitSeconds) return fail("out of time on the way to stop " + std::to_string(stop));
            const Point p = session.position(), target = path[next];
            const double distance = std::hypot(target.x - p.x, target.y - p.y);
            if (distance < kArrive) {
                ++next;
                continue;
            }
            if (debug && std::fmod(session.clock, 1.0) < kWalkStep / 2)
                std::fprintf(stderr, "t %.0f at %.1f %.1f z %.0f -> waypoint %zu\n", session.clock, p.x, p.y,
                             session.nav.controller().player().z, next);
            const double angle = std::atan2(target.y - p.y, target.x - p.x);
            const Level& now = session.nav.doom()->level();
            const std::optional<double> blocked = blockedAt(now.walkMap(), planner, p, target);
            // Blocked: face the door or switch within reach (if any), else wait facing the way.
            const std::optional<double> door = blocked && *blocked < 24 ? useAngle(now, p) : std::nullopt;
            if (blocked && *blocked < 24 && blockedSince >= 0 && session.clock - blockedSince > 8) {
                // Nothing here opens it: a switch elsewhere moves what is in the way.
                const Point q{p.x + (target.x - p.x) * *blocked / distance, p.y + (target.y - p.y) * *blocked / distance};
                if (const std::optional<std::size_t> sw = switchFor(now, now.walkMap(), q)) {
                    stops.insert(stops.begin() + std::ptrdiff_t(stop), stopToUse(now, *sw));
                    detour = true;
                    break;
                }
            }
            const double error = rec.turnToward(door.value_or(angle));
            if (blocked && *blocked < 24) {
                rec.walk(false);
                if (blockedSince < 0) blockedSince = session.clock;
                if (waitingSince < 0) waitingSince = session.clock;
                if (door && std::abs(error) < 0.05 && (session.clock - waitingSince > 4 || waitingSince == session.clock)) {
                    rec.use();
                    waitingSince = session.clock;
                }
            } else {
                rec.walk(std::abs(error) < 0.5);
                waitingSince = blockedSince = -1;
            }
            session.frame();
        }
        if (detour) continue;
        rec.walk(false);
        if (stops[stop].line) {
            // Face the line and use it (until it does something: a switch turns, the level ends).
            const std::size_t line = *stops[stop].line;
            const bool flippedBefore = session.nav.doom()->level().switchFlipped(line);
            for (int i = 0; i < 256; ++i) {
                const Level& now = session.nav.doom()->level();
                if (session.completion || now.switchFlipped(line) != flippedBefore) break;
                if (std::abs(rec.turnToward(stops[stop].facing)) < 0.02 && i % 32 == 0) rec.use();
                session.frame();
            }
        }
        ++stop;
    }
    if (!session.completion) return fail("the exit switch did not end the level");
    session.frame();
    return PlannedWalk{rec.text, session.clock};
}

std::optional<std::string> playWalk(const Scene& scene, const std::string& script, double limitSeconds) {
    viewer::ScriptPlayer player(viewer::parseInputScript(script, "walk"));
    Session session(scene);
    const char* trace = std::getenv("PENUMBRA_WALK_TRACE");  // frames between printed positions
    const int every = trace ? std::max(1, std::atoi(trace)) : 0;
    for (int frame = 1; session.clock <= limitSeconds && !session.completion; ++frame) {
        player.playFrame(session.input, kWalkStep);
        session.frame();
        if (every && frame % every == 0) {
            const walk::WalkState& p = session.nav.controller().player();
            std::fprintf(stderr, "frame %d: %.5g %.5g %.5g\n", frame, p.x / 32, (p.z + 41) / 32, -p.y / 32);
        }
    }
    return session.completion;
}

}  // namespace penumbra::test
