// How this process was started: by Open MPI's mpirun (which says so in the environment) or on
// its own. Read before MPI is initialised, so main() can keep N copies of one message quiet.
#pragma once

#include <exception>
#include <string>

namespace penumbra::distributed {

struct Launch {
    bool underMpirun = false;  // OMPI_COMM_WORLD_SIZE is set
    int rank = 0;              // OMPI_COMM_WORLD_RANK
    int size = 1;              // OMPI_COMM_WORLD_SIZE
};
Launch launchFromEnvironment();

// Whether this binary was built with MPI (PENUMBRA_MPI).
bool mpiBuilt();

// An error every rank knows about and one rank has already printed: main() exits with
// exitCode and prints nothing more.
class Reported : public std::exception {
public:
    explicit Reported(int exitCode) : exitCode(exitCode) {}
    const char* what() const noexcept override { return "already reported"; }
    int exitCode;
};

// The exit code main() gives an exception (2 usage, 128+signal interrupted, 1 otherwise), and
// the message it prints after "penumbra: error: ".
int exitCodeOf(const std::exception& e);
std::string messageOf(const std::exception& e);

}  // namespace penumbra::distributed
