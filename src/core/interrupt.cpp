#include "core/interrupt.h"

#include <csignal>

namespace penumbra {
namespace {

std::atomic<int> received{0};
struct sigaction previousInt, previousTerm;

extern "C" void onSignal(int sig) {
    // Only async-signal-safe work here (a lock-free atomic store). SA_RESETHAND has already put
    // the default action back, so a second signal ends the process.
    received.store(sig);
}

}  // namespace

StopOnSignals::StopOnSignals() {
    received = 0;
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;  // the second Ctrl-C kills, as users expect
    sigaction(SIGINT, &action, &previousInt);
    sigaction(SIGTERM, &action, &previousTerm);
}

StopOnSignals::~StopOnSignals() {
    sigaction(SIGINT, &previousInt, nullptr);
    sigaction(SIGTERM, &previousTerm, nullptr);
}

const std::atomic<int>& StopOnSignals::signal() { return received; }

const char* StopOnSignals::signalName(int sig) {
    return sig == SIGINT ? "SIGINT" : (sig == SIGTERM ? "SIGTERM" : "a signal");
}

}  // namespace penumbra
