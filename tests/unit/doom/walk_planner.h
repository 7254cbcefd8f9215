// Plans and records a walk through a Doom level for `penumbra view --script`: a path from the
// player start to the exit found on the level's walk map with every door open (A* over an
// 8-unit grid, then straightened), then followed by steering the real viewer controls frame by
// frame at a fixed time step (turning by mouse, W to walk, Space to use a door in the way and,
// at the end, the exit switch). Because the same controls replay the same events at the same
// step, the script it writes reaches the exit when played. Test-side tool: it wrote the walks in
// scenes/walks/ (PENUMBRA_WRITE_WALKS, see doom_walk_test.cpp).
#pragma once

#include <optional>
#include <string>

#include "scene/scene.h"

namespace penumbra::test {

inline constexpr double kWalkStep = 1.0 / 32;  // --fixed-dt of the shipped walks (exact in binary)

struct PlannedWalk {
    std::string script;  // the --script text
    double seconds = 0;  // when the level ended
};

// none when no path or the steering does not reach the exit within the time limit.
std::optional<PlannedWalk> planWalk(const Scene& scene, const std::string& title, std::string* why = nullptr);

// Plays a script through the viewer's controls and navigation as `view --script --fixed-dt
// kWalkStep` does, until the level ends or the script has run `limitSeconds`. Returns the
// level's "E1M1 complete in T s" line, or none.
std::optional<std::string> playWalk(const Scene& scene, const std::string& script, double limitSeconds);

}  // namespace penumbra::test
