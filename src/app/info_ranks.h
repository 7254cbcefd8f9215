// penumbra info under mpirun: one line per rank (its host, its place on the host, the device it
// would render on), printed by rank 0 in rank order.
#pragma once

#include <string>

#include "distributed/comm.h"

namespace penumbra::app {

// Throws Reported after the lines when some rank has no usable device (rank 0 says which).
void printRanksInfo(distributed::Comm& comm, const std::string& deviceSelector);

}  // namespace penumbra::app
