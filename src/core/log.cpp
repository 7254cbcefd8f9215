#include "core/log.h"

#include <atomic>
#include <cstdio>

namespace penumbra {
namespace {
std::atomic<bool> g_verbose{false};
}

void logWarning(std::string_view message) {
    std::fprintf(stderr, "penumbra: warning: %.*s\n", int(message.size()), message.data());
}

void setVerbose(bool verbose) { g_verbose = verbose; }
bool isVerbose() { return g_verbose; }

}  // namespace penumbra
