#include "distributed/agree.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "core/error.h"

namespace penumbra::distributed {

std::string verdictLine(const std::vector<int>& codes, const std::vector<std::string>& messages,
                        const std::vector<std::string>& hosts) {
    PN_CHECK(codes.size() == messages.size() && codes.size() == hosts.size());
    const auto first = std::find_if(codes.begin(), codes.end(), [](int c) { return c != 0; });
    if (first == codes.end()) return "";
    const std::size_t r = std::size_t(first - codes.begin());
    const auto failed = std::size_t(std::count_if(codes.begin(), codes.end(), [](int c) { return c != 0; }));
    const bool allSame = failed == codes.size() &&
                         std::all_of(messages.begin(), messages.end(), [&](const std::string& m) { return m == messages[r]; });
    if (allSame) return messages[r];
    std::string line = "rank " + std::to_string(r) + " on " + hosts[r] + ": " + messages[r];
    if (failed > 1) line += " (" + std::to_string(failed) + " of " + std::to_string(codes.size()) + " ranks failed)";
    return line;
}

void agree(Comm& comm, const std::function<void()>& setup) {
    int code = 0;
    std::string message;
    try {
        setup();
    } catch (const std::exception& e) {
        code = exitCodeOf(e);
        message = messageOf(e);
    }
    // One gather carries both: "<code> <message>".
    const std::vector<std::string> all = comm.allGather(std::to_string(code) + " " + message);
    std::vector<int> codes;
    std::vector<std::string> messages, hosts;
    for (int r = 0; r < comm.size(); ++r) {
        const std::string& s = all[std::size_t(r)];
        const std::size_t space = s.find(' ');
        codes.push_back(std::atoi(s.substr(0, space).c_str()));
        messages.push_back(space == std::string::npos ? "" : s.substr(space + 1));
        hosts.push_back(comm.hostOf(r));
    }
    const auto first = std::find_if(codes.begin(), codes.end(), [](int c) { return c != 0; });
    if (first == codes.end()) return;
    if (comm.primary()) {
        std::fprintf(stderr, "penumbra: error: %s\n", verdictLine(codes, messages, hosts).c_str());
        std::fflush(stderr);
    }
    throw Reported(*first);
}

void failOnError(Comm& comm, const std::function<void()>& work) {
    try {
        work();
    } catch (const Reported&) {
        throw;
    } catch (const std::exception& e) {
        comm.fail(messageOf(e), exitCodeOf(e));
    }
}

}  // namespace penumbra::distributed
