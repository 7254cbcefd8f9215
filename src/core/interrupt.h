// Ctrl-C and `kill` as requests to stop cleanly: while a StopOnSignals is alive, SIGINT and
// SIGTERM only set a flag that long loops poll between units of work (a render finishes its
// pass, writes what it has and exits). A second signal of the same kind while the first is
// being honoured ends the process the usual way, so a stuck program can still be stopped.
#pragma once

#include <atomic>

namespace penumbra {

class StopOnSignals {
public:
    StopOnSignals();   // installs the handlers
    ~StopOnSignals();  // restores the previous ones
    StopOnSignals(const StopOnSignals&) = delete;
    StopOnSignals& operator=(const StopOnSignals&) = delete;

    // The flag the handlers set; loops poll it.
    static const std::atomic<int>& signal();  // 0, or the number of the signal received
    static const char* signalName(int signal);  // "SIGINT", "SIGTERM"
};

}  // namespace penumbra
