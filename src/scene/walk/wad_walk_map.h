// The WalkMap of a Doom map: its linedefs with the heights of the sectors on their sides.
#pragma once

#include "scene/io/wad/map.h"
#include "scene/walk/walk_map.h"

namespace penumbra::walk {

// Lines whose two ends coincide are left out; ML_BLOCKING lines block, ML_BLOCKMONSTERS lines
// do not (they stop monsters only).
WalkMap buildWalkMap(const wad::MapData& map);

}  // namespace penumbra::walk
