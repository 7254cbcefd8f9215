// A Doom level that plays: the map's line specials triggered by the player (walking over lines,
// using switches and doors, keys picked up by walking over them, the exit), the sector movers
// they start (sector_movers.h) stepped on a fixed tic clock, and the heights that walking
// collides with. Plain data and arithmetic: no GPU, no window. The viewer's Navigation runs it
// (interact/navigation.h) and moves the sectors' geometry, which the WAD loader built as
// instances (Level::planeInstances).
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/doom/light_specials.h"
#include "scene/doom/line_specials.h"
#include "scene/doom/sector_movers.h"
#include "scene/io/wad/map.h"
#include "scene/scene.h"
#include "scene/walk/walk_map.h"

namespace penumbra::doom {

struct PlayerPosition {
    double x = 0, y = 0, z = 0;  // map units: centre on the ground plane, feet height
};

// The heights a sector's floor or ceiling can take once its specials run, as far as the map
// tells at load time (neighbours that move later may take it further).
struct PlaneRange {
    bool moves = false;
    double low = 0, high = 0;
};

// An instance of the scene that carries a moving plane (and the walls attached to it): placed at
// the plane's height `base` when its transform is the identity.
struct PlaneInstance {
    int sector = 0;
    Plane plane = Plane::Floor;
    std::uint32_t instance = 0;
    double base = 0;
};

// A material that gives off one sector's fill light (scene/io/wad/sector_light.h), made for that
// sector alone because its light changes: its emission is sectorRadiance(level) * scale.
struct LightMaterial {
    int sector = 0;
    std::uint32_t material = 0;
    float scale = 1;
};

// A material made for one switch's wall alone, so that the switch turns without its texture
// turning on every other wall: its albedo (and glow) texture is [0] as the map draws the switch,
// [1] the other one (SW2 for SW1). Emission textures are -1 where it does not glow.
struct SwitchMaterial {
    std::size_t line = 0;
    std::uint32_t material = 0;
    int albedo[2] = {-1, -1};
    int emission[2] = {-1, -1};
};

// A material made for one key thing's sprite alone, so that the key can vanish when it is picked
// up while its kind lies elsewhere: `shownCutoff` is its alpha cutoff while the key lies there.
struct KeyMaterial {
    std::size_t thing = 0;  // index in the map's things
    std::uint32_t material = 0;
    float shownCutoff = 0.5f;
};

constexpr double kUseRange = 64;   // USERANGE: how far the player reaches to use a line
constexpr int kButtonTics = 35;    // BUTTONTIME: a repeatable switch turns back after a second

class Level {
public:
    explicit Level(const wad::MapData& map);

    const std::string& mapName() const { return mapName_; }
    // Heights and walls as they stand now: what walking collides with.
    const walk::WalkMap& walkMap() const { return walk_; }
    double height(int sector, Plane plane) const;
    int lightLevel(int sector) const { return sectors_.at(std::size_t(sector)).light; }
    // Changes whenever a sector's light level changes (light specials, light lines).
    std::uint32_t lightChanges() const { return lightChanges_; }
    int sectorTag(int sector) const { return sectors_.at(std::size_t(sector)).tag; }

    // One tic: every active mover steps once, switches count down. `player`: where the player
    // stands (a door closing on it goes back up); none: nothing is in the way.
    void tic(const std::optional<PlayerPosition>& player);
    int tics() const { return tics_; }
    // The player at (x, y), facing `angle` (radians, map frame: 0 east, counter-clockwise), uses
    // the nearest line within kUseRange that it faces (Doom's P_UseLines). True when it did
    // something; message() then or otherwise says why not (a locked door).
    bool use(double x, double y, double angle, const std::optional<PlayerPosition>& player = std::nullopt);
    // The player's centre moved from (x0, y0) to (x1, y1): walk-over lines it crossed trigger.
    void crossed(double x0, double y0, double x1, double y1);
    // Keys the player's box touches are taken (Doom's P_TouchSpecialThing for cards and skulls).
    void touchThings(const PlayerPosition& player);
    bool hasKey(Key key) const { return key == Key::None || keys_[std::size_t(key)]; }
    // Where the keys not yet picked up lie (map units).
    std::vector<std::pair<double, double>> keyPositions() const;
    // Whether thing `thing` (index in the map's things) is a key that was picked up.
    bool thingTaken(std::size_t thing) const;

    bool exited() const { return exitTic_ >= 0; }
    bool secretExit() const { return secretExit_; }
    int exitTic() const { return exitTic_; }
    // The last thing worth telling the player ("You need a blue key to open this door"); cleared
    // by takeMessage.
    std::string takeMessage();

    // Moving sectors and what moves with them.
    PlaneRange range(int sector, Plane plane) const;
    std::vector<PlaneInstance>& planeInstances() { return planeInstances_; }
    // Sectors whose light can change (a light special, or a light line tagged to them), and the
    // materials their light drives.
    bool lightVaries(int sector) const;
    std::vector<LightMaterial>& lightMaterials() { return lightMaterials_; }
    const std::vector<LightMaterial>& lightMaterials() const { return lightMaterials_; }
    // The materials that show the switches' and keys' state (level_looks.h applies them).
    std::vector<SwitchMaterial>& switchMaterials() { return switchMaterials_; }
    const std::vector<SwitchMaterial>& switchMaterials() const { return switchMaterials_; }
    std::vector<KeyMaterial>& keyMaterials() { return keyMaterials_; }
    const std::vector<KeyMaterial>& keyMaterials() const { return keyMaterials_; }
    const std::vector<PlaneInstance>& planeInstances() const { return planeInstances_; }
    // Whether the switch on linedef `line` shows its other texture (SW2 for a switch drawn SW1).
    bool switchFlipped(std::size_t line) const { return lines_.at(line).flipped; }
    // Changes once per switch that turned, so a front end knows to redraw it.
    std::uint32_t switchChanges() const { return switchChanges_; }
    std::size_t activeMovers() const { return movers_.size(); }
    bool busySector(int sector) const { return sectors_.at(std::size_t(sector)).busy; }

    struct LineState {
        double x1 = 0, y1 = 0, x2 = 0, y2 = 0;
        int special = 0, tag = 0;   // special: 0 once a one-shot line was used
        int front = -1, back = -1;  // sectors
        bool flipped = false;       // a switch showing its other texture
        int buttonTics = 0;         // a repeatable switch turns back when this reaches 0
    };
    // The map's linedefs, in order, as the level holds them now.
    const std::vector<LineState>& lines() const { return lines_; }

    // Starts a special's action as if its line `line` was triggered (tests, and the triggers
    // above once they decided the line fires). True when something started.
    bool trigger(std::size_t line, const std::optional<PlayerPosition>& player = std::nullopt);

private:
    struct SectorState {
        int light = 0;
        std::uint16_t tag = 0;
        std::vector<int> neighbours;  // across two-sided lines, repeats removed
        bool busy = false;            // Doom's specialdata: one mover at a time
    };
    struct KeyThing {
        std::size_t thing = 0;  // index in the map's things
        double x = 0, y = 0;
        Key key = Key::None;
        bool taken = false;
    };
    class World;
    friend class World;

    std::vector<int> taggedSectors(int tag) const;
    std::optional<Mover> makeMover(Action action, int sector, const LineState& line) const;
    bool startOn(Action action, const LineState& line, int sector);
    bool doTagged(Action action, const LineState& line);
    bool useManualDoor(LineState& line, const LineSpecial& special);
    void turnSwitch(LineState& line, bool repeat);
    void stopOrResume(Action action, const LineState& line, bool stop);
    void setLights(Action action, const LineState& line);
    double lowestCeilingAround(int s) const, highestCeilingAround(int s) const;
    int dimmestAround(int s) const;  // P_FindMinSurroundingLight, from the sector's own level
    void setLight(int sector, int level);
    double lowestFloorAround(int s) const, highestFloorAround(int s) const, nextHigherFloor(int s) const;

    std::string mapName_;
    walk::WalkMap walk_;
    std::vector<SectorState> sectors_;
    std::vector<LineState> lines_;
    std::vector<KeyThing> keyThings_;
    std::vector<Mover> movers_;  // in the order they started (Doom's thinker order)
    std::vector<LightThinker> lights_;
    LightRandom random_;
    std::uint32_t lightChanges_ = 0;
    std::vector<PlaneRange> floorRanges_, ceilingRanges_;
    std::map<int, std::vector<int>> sectorsByTag_;  // tag -> its sectors, in order
    std::vector<PlaneInstance> planeInstances_;
    std::vector<LightMaterial> lightMaterials_;
    std::vector<SwitchMaterial> switchMaterials_;
    std::vector<KeyMaterial> keyMaterials_;
    std::vector<bool> lightVaries_;
    bool keys_[4] = {true, false, false, false};
    int tics_ = 0;
    int exitTic_ = -1;
    bool secretExit_ = false;
    std::uint32_t switchChanges_ = 0;
    std::string message_;
    std::optional<PlayerPosition> player_;  // during a tic or a use: what movers must not crush
};

// Moves the instances carrying the level's moving planes (Level::planeInstances) to the planes'
// heights now: a vertical translation by (height - base). True when one moved.
bool placePlaneInstances(const Level& level, std::vector<Instance>& instances);

// A level with every special line fired once (those that can start something without a key):
// every door, lift, floor and crusher of the map on its way. For benchmarks.
Level withEverythingMoving(const Level& level);

}  // namespace penumbra::doom
