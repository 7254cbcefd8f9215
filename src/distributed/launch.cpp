#include "distributed/launch.h"

#include <cstdlib>
#include <new>

#include "core/error.h"

namespace penumbra::distributed {
namespace {

int envInt(const char* name, int fallback) {
    const char* v = std::getenv(name);
    if (!v || !*v) return fallback;
    char* end = nullptr;
    const long n = std::strtol(v, &end, 10);
    return (*end == '\0' && n >= 0 && n < (1 << 24)) ? int(n) : fallback;
}

}  // namespace

Launch launchFromEnvironment() {
    Launch l;
    l.underMpirun = std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr;
    l.size = envInt("OMPI_COMM_WORLD_SIZE", 1);
    l.rank = envInt("OMPI_COMM_WORLD_RANK", 0);
    return l;
}

bool mpiBuilt() {
#ifdef PENUMBRA_HAVE_MPI
    return true;
#else
    return false;
#endif
}

int exitCodeOf(const std::exception& e) {
    if (const auto* r = dynamic_cast<const Reported*>(&e)) return r->exitCode;
    if (const auto* i = dynamic_cast<const Interrupted*>(&e)) return i->exitCode;
    if (dynamic_cast<const UsageError*>(&e)) return 2;
    return 1;
}

std::string messageOf(const std::exception& e) {
    if (dynamic_cast<const std::bad_alloc*>(&e)) return "out of memory; try a smaller image or scene";
    return e.what();
}

}  // namespace penumbra::distributed
