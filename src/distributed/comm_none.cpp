// Built without MPI: there is no job to join.
#include "core/error.h"
#include "distributed/comm.h"

namespace penumbra::distributed {

std::unique_ptr<Comm> Comm::start() {
    throw UsageError("this penumbra was built without MPI support; install libopenmpi-dev and openmpi-bin "
                     "(scripts/setup.sh) and rebuild to render across ranks");
}

namespace {
[[noreturn]] void unreachable() { checkFailed("a Comm without MPI support", __FILE__, __LINE__); }
}  // namespace

// Unreachable: no Comm can exist.
Comm::~Comm() = default;
void Comm::barrier() { unreachable(); }
std::vector<std::string> Comm::allGather(const std::string&) { unreachable(); }
void Comm::sumOnPrimary(std::span<double>) { unreachable(); }
void Comm::sumEverywhere(std::span<double>) { unreachable(); }
bool Comm::primaryDecides(bool) { unreachable(); }
void Comm::send(int, int, std::span<const std::int64_t>) { unreachable(); }
bool Comm::tryReceive(int, int*, std::vector<std::int64_t>&) { unreachable(); }
std::vector<std::int64_t> Comm::receive(int, int) { unreachable(); }
void Comm::fail(const std::string&, int) { unreachable(); }

}  // namespace penumbra::distributed
