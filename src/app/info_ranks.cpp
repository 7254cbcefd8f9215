#include "app/info_ranks.h"

#include <cstdio>

#include "app/common_options.h"
#include "app/render_ranks.h"
#include "distributed/agree.h"

namespace penumbra::app {

void printRanksInfo(distributed::Comm& comm, const std::string& deviceSelector) {
    std::string line = "rank " + std::to_string(comm.rank()) + " of " + std::to_string(comm.size()) + " on " +
                       comm.host() + " (local rank " + std::to_string(comm.localRank()) + "): ";
    std::string error;
    try {
        const std::unique_ptr<gpu::Context> ctx = openDevice(deviceForRank(comm, deviceSelector));
        const gpu::DeviceInfo& d = ctx->info();
        line += "device " + std::to_string(d.index) + ", " + d.name + " (" + gpu::deviceTypeName(d.type) + "), " +
                std::to_string(d.deviceLocalBytes >> 20) + " MiB device-local";
    } catch (const std::exception& e) {
        error = e.what();
        line += "no device: " + error;
    }
    const std::vector<std::string> lines = comm.allGather(line);
    if (comm.primary())
        for (const std::string& l : lines) std::printf("%s\n", l.c_str());
    std::fflush(stdout);
    distributed::agree(comm, [&] {
        if (!error.empty()) throw Error(error);
    });
}

}  // namespace penumbra::app
