#include "scene/doom/level.h"

#include <algorithm>
#include <climits>
#include <cmath>

#include "scene/walk/wad_walk_map.h"
#include "scene/io/wad/things.h"
#include "scene/io/wad/units.h"
#include "scene/walk/walk_physics.h"

namespace penumbra::doom {
namespace {

constexpr double kMaxHeight = 32767;  // what "no neighbour" leaves (Doom's MAXINT, in map range)

const char* keyName(Key key) {
    switch (key) {
        case Key::Blue: return "blue";
        case Key::Yellow: return "yellow";
        case Key::Red: return "red";
        case Key::None: break;
    }
    return "";
}

// Doom's P_PointOnLineSide: 0 (front) on the right of v1 -> v2, else 1.
int pointSide(double x1, double y1, double x2, double y2, double px, double py) {
    return (x2 - x1) * (py - y1) - (y2 - y1) * (px - x1) < 0 ? 0 : 1;
}

// Where segment p0->p1 meets segment a->b, as the fraction along p0->p1; none when they miss.
std::optional<double> segmentHit(double px0, double py0, double px1, double py1, double ax, double ay, double bx,
                                 double by) {
    const double rx = px1 - px0, ry = py1 - py0, sx = bx - ax, sy = by - ay;
    const double denom = rx * sy - ry * sx;
    if (denom == 0) return std::nullopt;
    const double t = ((ax - px0) * sy - (ay - py0) * sx) / denom;
    const double u = ((ax - px0) * ry - (ay - py0) * rx) / denom;
    if (t < 0 || t > 1 || u < 0 || u > 1) return std::nullopt;
    return t;
}

bool isDoor(Action a) { return a >= Action::DoorRaise && a <= Action::DoorBlazeClose; }

}  // namespace

// The movers' view of the level: heights live in the walk map, and the player (if any) must
// still fit where it stands (Doom's P_ChangeSector, for the player only).
class Level::World final : public PlaneWorld {
public:
    explicit World(Level& level) : level_(level) {}
    double height(int sector, Plane plane) const override { return level_.height(sector, plane); }
    void setHeight(int sector, Plane plane, double h) override {
        walk::WalkSector& s = level_.walk_.sectors.at(std::size_t(sector));
        (plane == Plane::Floor ? s.floor : s.ceiling) = h;
    }
    bool thingsFit(int) const override {
        if (!level_.player_) return true;
        const walk::Opening o = walk::openingAt(level_.walk_, level_.player_->x, level_.player_->y);
        return o.blocked || o.ceiling - o.floor >= walk::kPlayerHeight;
    }

private:
    Level& level_;
};

Level::Level(const wad::MapData& map) : mapName_(map.name), walk_(walk::buildWalkMap(map)) {
    sectors_.resize(map.sectors.size());
    for (std::size_t s = 0; s < map.sectors.size(); ++s) {
        sectors_[s].light = map.sectors[s].lightLevel;
        sectors_[s].tag = map.sectors[s].tag;
        if (sectors_[s].tag != 0) sectorsByTag_[sectors_[s].tag].push_back(int(s));
    }
    auto sectorOf = [&](std::uint16_t side) {
        return side == wad::kNoSide ? -1 : int(map.sidedefs[side].sector);
    };
    for (const wad::Linedef& l : map.linedefs) {
        LineState line;
        line.x1 = map.vertices[l.v1].x, line.y1 = map.vertices[l.v1].y;
        line.x2 = map.vertices[l.v2].x, line.y2 = map.vertices[l.v2].y;
        line.special = l.special;
        line.tag = l.tag;
        line.front = sectorOf(l.front);
        line.back = sectorOf(l.back);
        if (line.front >= 0 && line.back >= 0 && line.front != line.back) {
            sectors_[std::size_t(line.front)].neighbours.push_back(line.back);
            sectors_[std::size_t(line.back)].neighbours.push_back(line.front);
        }
        lines_.push_back(line);
    }
    for (SectorState& s : sectors_) {
        std::sort(s.neighbours.begin(), s.neighbours.end());
        s.neighbours.erase(std::unique(s.neighbours.begin(), s.neighbours.end()), s.neighbours.end());
    }
    for (std::size_t s = 0; s < sectors_.size(); ++s)
        if (std::optional<LightThinker> light = makeLightThinker(map.sectors[s].special, int(s), sectors_[s].light,
                                                                  dimmestAround(int(s)), random_))
            lights_.push_back(*light);
    lightVaries_.assign(sectors_.size(), false);
    for (const LightThinker& light : lights_) lightVaries_[std::size_t(lightSector(light))] = true;
    std::set<int> lightTags;  // each tag once, however many lines name it
    for (const LineState& line : lines_) {
        const std::optional<LineSpecial> special = lineSpecial(line.special);
        if (special && special->action >= Action::LightTurnOn255 && special->action <= Action::LightStartStrobing &&
            lightTags.insert(line.tag).second)
            for (int s : taggedSectors(line.tag)) lightVaries_[std::size_t(s)] = true;
    }
    // The keys of the single-player game at medium skill: those the WAD loader draws.
    for (std::size_t i = 0; i < map.things.size(); ++i) {
        const wad::Thing& t = map.things[i];
        const Key key = keyOfThing(t.type);
        if (key != Key::None && wad::inSinglePlayerMedium(t.flags))
            keyThings_.push_back({i, double(t.x), double(t.y), key, false});
    }
    // The ranges the movers the map's lines can start would sweep, from the heights at load.
    floorRanges_.resize(sectors_.size());
    ceilingRanges_.resize(sectors_.size());
    for (std::size_t s = 0; s < sectors_.size(); ++s) {
        floorRanges_[s] = {false, height(int(s), Plane::Floor), height(int(s), Plane::Floor)};
        ceilingRanges_[s] = {false, height(int(s), Plane::Ceiling), height(int(s), Plane::Ceiling)};
    }
    auto widen = [&](int sector, Plane plane, double a, double b) {
        PlaneRange& r = (plane == Plane::Floor ? floorRanges_ : ceilingRanges_)[std::size_t(sector)];
        r.moves = true;
        r.low = std::min({r.low, a, b});
        r.high = std::max({r.high, a, b});
    };
    // Each (tag, action) and (sector, action) once: a hostile map's many lines cost no more.
    std::set<std::pair<int, Action>> predicted, tagActions;
    for (const LineState& line : lines_) {
        const std::optional<LineSpecial> special = lineSpecial(line.special);
        if (!special) continue;
        std::vector<int> targets;
        if (special->trigger == Trigger::Manual) {
            if (line.back >= 0) targets.push_back(line.back);
        } else if (tagActions.insert({line.tag, special->action}).second) {
            targets = taggedSectors(line.tag);
        }
        for (int s : targets) {
            if (!predicted.insert({s, special->action}).second) continue;
            const std::optional<Mover> m = makeMover(special->action, s, line);
            if (!m) continue;
            if (const Door* d = std::get_if<Door>(&*m)) {
                widen(s, Plane::Ceiling, height(s, Plane::Floor), d->topHeight);
            } else if (const Plat* p = std::get_if<Plat>(&*m)) {
                widen(s, Plane::Floor, p->low, p->high);
            } else if (const FloorMove* f = std::get_if<FloorMove>(&*m)) {
                widen(s, Plane::Floor, height(s, Plane::Floor), f->dest);
            } else if (const CeilingMove* c = std::get_if<CeilingMove>(&*m)) {
                widen(s, Plane::Ceiling, c->bottomHeight, c->topHeight);
            }
        }
    }
}

bool Level::lightVaries(int sector) const { return lightVaries_.at(std::size_t(sector)); }

double Level::height(int sector, Plane plane) const {
    const walk::WalkSector& s = walk_.sectors.at(std::size_t(sector));
    return plane == Plane::Floor ? s.floor : s.ceiling;
}

PlaneRange Level::range(int sector, Plane plane) const {
    return (plane == Plane::Floor ? floorRanges_ : ceilingRanges_).at(std::size_t(sector));
}

std::vector<int> Level::taggedSectors(int tag) const {
    // Vanilla's tag-0 lines move every untagged sector: a map bug, not done.
    const auto it = sectorsByTag_.find(tag);
    return it == sectorsByTag_.end() ? std::vector<int>{} : it->second;
}

double Level::lowestCeilingAround(int s) const {
    double h = kMaxHeight;
    for (int n : sectors_[std::size_t(s)].neighbours) h = std::min(h, height(n, Plane::Ceiling));
    return h;
}
double Level::highestCeilingAround(int s) const {
    double h = 0;
    for (int n : sectors_[std::size_t(s)].neighbours) h = std::max(h, height(n, Plane::Ceiling));
    return h;
}
double Level::lowestFloorAround(int s) const {
    double h = height(s, Plane::Floor);
    for (int n : sectors_[std::size_t(s)].neighbours) h = std::min(h, height(n, Plane::Floor));
    return h;
}
double Level::highestFloorAround(int s) const {
    double h = -500;
    for (int n : sectors_[std::size_t(s)].neighbours) h = std::max(h, height(n, Plane::Floor));
    return h;
}
int Level::dimmestAround(int s) const {
    int level = sectors_[std::size_t(s)].light;
    for (int n : sectors_[std::size_t(s)].neighbours) level = std::min(level, sectors_[std::size_t(n)].light);
    return level;
}

void Level::setLight(int sector, int level) {
    int& light = sectors_.at(std::size_t(sector)).light;
    if (light == level) return;
    light = level;
    ++lightChanges_;
}

double Level::nextHigherFloor(int s) const {
    const double now = height(s, Plane::Floor);
    double h = kMaxHeight;
    for (int n : sectors_[std::size_t(s)].neighbours)
        if (height(n, Plane::Floor) > now) h = std::min(h, height(n, Plane::Floor));
    return h == kMaxHeight ? now : h;
}

// The mover an action starts on a sector, from the heights now (EV_DoDoor, EV_DoPlat,
// EV_DoFloor, EV_DoCeiling); none for actions that move nothing.
std::optional<Mover> Level::makeMover(Action action, int s, const LineState&) const {
    const double floor = height(s, Plane::Floor), ceiling = height(s, Plane::Ceiling);
    auto door = [&](DoorKind kind, double speed, int direction, double top) {
        Door d;
        d.kind = kind, d.sector = s, d.speed = speed, d.direction = direction, d.topHeight = top;
        return Mover(d);
    };
    const double doorTop = lowestCeilingAround(s) - 4;
    auto plat = [&](PlatKind kind, double speed, double low, double high, int wait, PlatStatus status) {
        Plat p;
        p.kind = kind, p.sector = s, p.speed = speed, p.low = low, p.high = high, p.wait = wait, p.status = status;
        return Mover(p);
    };
    auto floorMove = [&](double dest, double speed, bool crush = false) {
        FloorMove f;
        f.sector = s, f.dest = dest, f.speed = speed, f.crush = crush, f.direction = dest >= floor ? 1 : -1;
        return Mover(f);
    };
    auto ceilingMove = [&](CeilingKind kind, double bottom, double top, int direction, double speed, bool crush) {
        CeilingMove c;
        c.kind = kind, c.sector = s, c.bottomHeight = bottom, c.topHeight = top, c.direction = direction;
        c.speed = speed, c.crush = crush;
        return Mover(c);
    };
    const double fast = 4;
    switch (action) {
        case Action::DoorRaise: return door(DoorKind::Normal, kDoorSpeed, 1, doorTop);
        case Action::DoorOpen: return door(DoorKind::Open, kDoorSpeed, 1, doorTop);
        case Action::DoorClose: return door(DoorKind::Close, kDoorSpeed, -1, doorTop);
        case Action::DoorClose30ThenOpen: return door(DoorKind::Close30ThenOpen, kDoorSpeed, -1, ceiling);
        case Action::DoorBlazeRaise: return door(DoorKind::BlazeRaise, kDoorSpeed * fast, 1, doorTop);
        case Action::DoorBlazeOpen: return door(DoorKind::BlazeOpen, kDoorSpeed * fast, 1, doorTop);
        case Action::DoorBlazeClose: return door(DoorKind::BlazeClose, kDoorSpeed * fast, -1, doorTop);
        case Action::PlatDownWaitUpStay:
            return plat(PlatKind::DownWaitUpStay, kPlatSpeed * 4, std::min(lowestFloorAround(s), floor), floor,
                        kPlatWait, PlatStatus::Down);
        case Action::PlatBlazeDownWaitUpStay:
            return plat(PlatKind::BlazeDownWaitUpStay, kPlatSpeed * 8, std::min(lowestFloorAround(s), floor), floor,
                        kPlatWait, PlatStatus::Down);
        case Action::PlatPerpetualRaise:
            // Doom starts it up or down at random; here always down, so runs repeat.
            return plat(PlatKind::PerpetualRaise, kPlatSpeed, std::min(lowestFloorAround(s), floor),
                        std::max(highestFloorAround(s), floor), kPlatWait, PlatStatus::Down);
        case Action::PlatRaiseToNearestAndChange:
            return plat(PlatKind::RaiseToNearestAndChange, kPlatSpeed / 2, floor, nextHigherFloor(s), 0, PlatStatus::Up);
        case Action::PlatRaise24AndChange:
            return plat(PlatKind::RaiseAndChange, kPlatSpeed / 2, floor, floor + 24, 0, PlatStatus::Up);
        case Action::PlatRaise32AndChange:
            return plat(PlatKind::RaiseAndChange, kPlatSpeed / 2, floor, floor + 32, 0, PlatStatus::Up);
        case Action::FloorLowerToHighest: return floorMove(highestFloorAround(s), kFloorSpeed);
        case Action::FloorLowerToLowest:
        case Action::FloorLowerAndChange: return floorMove(lowestFloorAround(s), kFloorSpeed);
        case Action::FloorTurboLower: {
            double dest = highestFloorAround(s);
            if (dest != floor) dest += 8;
            return floorMove(dest, kFloorSpeed * 4);
        }
        case Action::FloorRaiseToLowestCeiling:
            return floorMove(std::min(lowestCeilingAround(s), ceiling), kFloorSpeed);
        case Action::FloorRaiseCrush:
            return floorMove(std::min(lowestCeilingAround(s), ceiling) - 8, kFloorSpeed, true);
        case Action::FloorRaiseToNearest: return floorMove(nextHigherFloor(s), kFloorSpeed);
        case Action::FloorRaiseTurbo: return floorMove(nextHigherFloor(s), kFloorSpeed * 4);
        case Action::FloorRaise24:
        case Action::FloorRaise24AndChange: return floorMove(floor + 24, kFloorSpeed);
        case Action::FloorRaise512: return floorMove(floor + 512, kFloorSpeed);
        case Action::CeilingLowerToFloor:
            return ceilingMove(CeilingKind::LowerToFloor, floor, ceiling, -1, kCeilingSpeed, false);
        case Action::CeilingLowerAndCrush:
            return ceilingMove(CeilingKind::LowerAndCrush, floor + 8, ceiling, -1, kCeilingSpeed, false);
        case Action::CeilingCrushAndRaise:
            return ceilingMove(CeilingKind::CrushAndRaise, floor + 8, ceiling, -1, kCeilingSpeed, true);
        case Action::CeilingSilentCrushAndRaise:
            return ceilingMove(CeilingKind::SilentCrushAndRaise, floor + 8, ceiling, -1, kCeilingSpeed, true);
        case Action::CeilingFastCrushAndRaise:
            return ceilingMove(CeilingKind::FastCrushAndRaise, floor + 8, ceiling, -1, kCeilingSpeed * 2, true);
        case Action::CeilingRaiseToHighest:
        case Action::CeilingRaiseAndFloorLower:  // vanilla: the floor finds the sector busy and stays
            return ceilingMove(CeilingKind::RaiseToHighest, ceiling, highestCeilingAround(s), 1, kCeilingSpeed, false);
        default: return std::nullopt;
    }
}

bool Level::startOn(Action action, const LineState& line, int sector) {
    SectorState& s = sectors_.at(std::size_t(sector));
    if (s.busy) return false;
    std::optional<Mover> mover = makeMover(action, sector, line);
    if (!mover) return false;
    s.busy = true;
    movers_.push_back(std::move(*mover));
    return true;
}

// Stop lines freeze their tag's platforms or crushers; starting another of them wakes them first
// (P_ActivateInStasis, P_ActivateInStasisCeiling).
void Level::stopOrResume(Action action, const LineState& line, bool stop) {
    for (Mover& m : movers_) {
        const int sector = moverSector(m);
        if (sectors_[std::size_t(sector)].tag != line.tag || line.tag == 0) continue;
        if (action == Action::PlatStop || action == Action::PlatPerpetualRaise) {
            if (Plat* p = std::get_if<Plat>(&m)) p->inStasis = stop;
        } else if (CeilingMove* c = std::get_if<CeilingMove>(&m)) {
            c->inStasis = stop;
        }
    }
}

void Level::setLights(Action action, const LineState& line) {
    for (int s : taggedSectors(line.tag)) {
        SectorState& sec = sectors_[std::size_t(s)];
        int level = sec.light;
        if (action == Action::LightTurnOn255) level = 255;
        else if (action == Action::LightTurnOff35) level = 35;
        else if (action == Action::LightTurnOnBrightest) {
            level = 0;
            for (int n : sec.neighbours) level = std::max(level, sectors_[std::size_t(n)].light);
        } else if (action == Action::LightTurnOffDimmest) {
            level = dimmestAround(s);
        } else if (action == Action::LightStartStrobing) {  // EV_StartLightStrobing: slow, not in sync
            if (std::optional<LightThinker> t = makeLightThinker(3, s, sec.light, dimmestAround(s), random_))
                lights_.push_back(*t);
        }
        setLight(s, level);
    }
}

bool Level::doTagged(Action action, const LineState& line) {
    switch (action) {
        case Action::PlatStop:
        case Action::CeilingCrushStop: stopOrResume(action, line, true); return true;
        case Action::PlatPerpetualRaise:
        case Action::CeilingCrushAndRaise:
        case Action::CeilingFastCrushAndRaise:
        case Action::CeilingSilentCrushAndRaise: stopOrResume(action, line, false); break;
        case Action::LightTurnOn255:
        case Action::LightTurnOnBrightest:
        case Action::LightTurnOff35:
        case Action::LightTurnOffDimmest:
        case Action::LightStartStrobing: setLights(action, line); return true;
        case Action::ExitLevel:
        case Action::SecretExit:
            if (exitTic_ < 0) exitTic_ = tics_;
            secretExit_ = action == Action::SecretExit;
            return true;
        default: break;
    }
    bool started = false;
    for (int s : taggedSectors(line.tag)) started = startOn(action, line, s) || started;
    return started;
}

bool Level::trigger(std::size_t index, const std::optional<PlayerPosition>& player) {
    LineState& line = lines_.at(index);
    const std::optional<LineSpecial> special = lineSpecial(line.special);
    if (!special) return false;
    if (!hasKey(special->key)) {
        message_ = std::string("You need a ") + keyName(special->key) + " key to " +
                   (isDoor(special->action) ? "open this door" : "activate this object");
        return false;
    }
    if (player) player_ = player;
    if (special->trigger == Trigger::Manual) return useManualDoor(line, *special);
    const bool done = doTagged(special->action, line);
    if (special->trigger == Trigger::Walk || special->trigger == Trigger::Gun) {
        if (!special->repeat) line.special = 0;
        return done;
    }
    // A switch turns (and a one-shot one is spent) only when it did something, as in p_switch.c.
    if (done) turnSwitch(line, special->repeat);
    return done;
}

// EV_VerticalDoor: the door behind the line; used while it moves, a repeatable door reverses.
bool Level::useManualDoor(LineState& line, const LineSpecial& special) {
    if (line.back < 0) return false;
    SectorState& sec = sectors_[std::size_t(line.back)];
    if (sec.busy) {
        if (!special.repeat) return false;
        for (Mover& m : movers_)
            if (Door* d = std::get_if<Door>(&m); d && d->sector == line.back) {
                d->direction = d->direction == -1 ? 1 : -1;
                return true;
            }
        return false;
    }
    if (!startOn(special.action, line, line.back)) return false;
    if (!special.repeat) line.special = 0;
    return true;
}

void Level::turnSwitch(LineState& line, bool repeat) {
    line.flipped = !line.flipped;
    ++switchChanges_;
    if (repeat) line.buttonTics = kButtonTics;
    else line.special = 0;
}

void Level::tic(const std::optional<PlayerPosition>& player) {
    player_ = player;
    World world(*this);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < movers_.size(); ++i) {
        if (ticMover(movers_[i], world)) {
            if (kept != i) movers_[kept] = std::move(movers_[i]);
            ++kept;
        } else {
            sectors_[std::size_t(moverSector(movers_[i]))].busy = false;
        }
    }
    movers_.resize(kept);
    for (LightThinker& light : lights_) {
        const int sector = lightSector(light);
        setLight(sector, ticLight(light, sectors_[std::size_t(sector)].light, random_));
    }
    for (LineState& line : lines_)
        if (line.buttonTics > 0 && --line.buttonTics == 0) {
            line.flipped = !line.flipped;
            ++switchChanges_;
        }
    ++tics_;
}

bool Level::use(double x, double y, double angle, const std::optional<PlayerPosition>& player) {
    const double x1 = x + kUseRange * std::cos(angle), y1 = y + kUseRange * std::sin(angle);
    // The lines the use ray meets, nearest first; it stops at the first with a special or the
    // first it cannot pass (a one-sided line, or a closed opening).
    std::vector<std::pair<double, std::size_t>> hits;
    for (std::size_t i = 0; i < lines_.size(); ++i) {
        const LineState& l = lines_[i];
        if (l.x1 == l.x2 && l.y1 == l.y2) continue;
        if (std::optional<double> t = segmentHit(x, y, x1, y1, l.x1, l.y1, l.x2, l.y2)) hits.emplace_back(*t, i);
    }
    std::sort(hits.begin(), hits.end());
    for (const auto& [t, i] : hits) {
        LineState& l = lines_[i];
        if (l.special == 0) {
            if (l.front < 0 || l.back < 0) return false;
            const double top = std::min(height(l.front, Plane::Ceiling), height(l.back, Plane::Ceiling));
            const double bottom = std::max(height(l.front, Plane::Floor), height(l.back, Plane::Floor));
            if (top - bottom <= 0) return false;
            continue;
        }
        const std::optional<LineSpecial> special = lineSpecial(l.special);
        if (!special || (special->trigger != Trigger::Switch && special->trigger != Trigger::Manual)) return false;
        if (pointSide(l.x1, l.y1, l.x2, l.y2, x, y) != 0) return false;  // only from the front
        return trigger(i, player);
    }
    return false;
}

void Level::crossed(double x0, double y0, double x1, double y1) {
    if (x0 == x1 && y0 == y1) return;
    for (std::size_t i = 0; i < lines_.size(); ++i) {
        const LineState& l = lines_[i];
        if (l.special == 0) continue;
        const std::optional<LineSpecial> special = lineSpecial(l.special);
        if (!special || special->trigger != Trigger::Walk) continue;
        if (pointSide(l.x1, l.y1, l.x2, l.y2, x0, y0) == pointSide(l.x1, l.y1, l.x2, l.y2, x1, y1)) continue;
        if (!segmentHit(x0, y0, x1, y1, l.x1, l.y1, l.x2, l.y2)) continue;
        // Teleporters work from the front only (and are not done); everything else either way.
        trigger(i);
    }
}

void Level::touchThings(const PlayerPosition& player) {
    constexpr double kReach = walk::kPlayerRadius + 20;  // the player's and a key's radius
    for (KeyThing& k : keyThings_) {
        if (k.taken || std::abs(k.x - player.x) >= kReach || std::abs(k.y - player.y) >= kReach) continue;
        k.taken = true;
        keys_[std::size_t(k.key)] = true;
        message_ = std::string("Picked up a ") + keyName(k.key) + " key";
    }
}

std::vector<std::pair<double, double>> Level::keyPositions() const {
    std::vector<std::pair<double, double>> out;
    for (const KeyThing& k : keyThings_)
        if (!k.taken) out.emplace_back(k.x, k.y);
    return out;
}

bool Level::thingTaken(std::size_t thing) const {
    for (const KeyThing& k : keyThings_)
        if (k.thing == thing) return k.taken;
    return false;
}

bool placePlaneInstances(const Level& level, std::vector<Instance>& instances) {
    bool moved = false;
    for (const PlaneInstance& p : level.planeInstances()) {
        if (p.instance >= instances.size()) continue;
        const double offset = (level.height(p.sector, p.plane) - p.base) / wad::kUnitsPerMetre;
        const Affine placed = Affine::translation(Vec3(0.0f, float(offset), 0.0f));
        Affine& transform = instances[p.instance].transform;
        if (transform.m[1][3] == placed.m[1][3]) continue;
        transform = placed;
        moved = true;
    }
    return moved;
}

Level withEverythingMoving(const Level& level) {
    Level out = level;
    for (std::size_t i = 0; i < out.lines().size(); ++i) {
        const std::optional<LineSpecial> special = lineSpecial(out.lines()[i].special);
        if (!special || special->action == Action::ExitLevel || special->action == Action::SecretExit) continue;
        // A manual door already moving would be sent back: fire each door once.
        const int back = out.lines()[i].back;
        if (special->trigger == Trigger::Manual && back >= 0 && out.busySector(back)) continue;
        out.trigger(i);
    }
    return out;
}

std::string Level::takeMessage() {
    std::string m;
    std::swap(m, message_);
    return m;
}

}  // namespace penumbra::doom
