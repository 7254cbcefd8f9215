// Errors across ranks. During setup (loading the scene, opening the device, compiling) any rank
// may fail on its own: a missing file on one host, a bad device on another. agree() runs the
// setup on every rank and then lets every rank know whether all succeeded; if not, rank 0 prints
// one line naming the first rank that failed, its host and why, and every rank throws Reported
// with that rank's exit code. Nobody hangs in a collective that a failed rank never joins.
//
// After setup, ranks wait on each other inside collectives, so a rank that fails ends the whole
// job instead (failOnError: Comm::fail, one line, MPI_Abort).
#pragma once

#include <exception>
#include <functional>
#include <string>

#include "distributed/comm.h"
#include "distributed/launch.h"

namespace penumbra::distributed {

// The line rank 0 prints for the ranks' outcomes (codes[r] == 0: rank r succeeded), without
// "penumbra: error: ": the message alone when every rank failed the same way, else the first
// failed rank, its host, the message, and how many ranks failed. Pure, for tests.
std::string verdictLine(const std::vector<int>& codes, const std::vector<std::string>& messages,
                        const std::vector<std::string>& hosts);

void agree(Comm& comm, const std::function<void()>& setup);

// Runs work; any exception ends the job through comm.fail with the exception's message and code.
void failOnError(Comm& comm, const std::function<void()>& work);

}  // namespace penumbra::distributed
