// Load: eight browsers watch for a minute (PENUMBRA_SERVE_LOAD_SECONDS), each acknowledging
// frames and sending input, on loopback. Nothing crashes, every browser keeps receiving frames,
// and the server's memory stays flat: what it holds after the first fifth of the run (every
// connection, buffer and pipeline made) it still holds at the end, within a few MiB.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <thread>

#include "serve/probe/probe_client.h"
#include "server_process.h"

namespace penumbra::test {
namespace {

TEST(ServeLoad, EightBrowsersForAMinuteAndMemoryStaysFlat) {
    const char* env = std::getenv("PENUMBRA_SERVE_LOAD_SECONDS");
    const double seconds = env ? std::clamp(std::atof(env), 5.0, 600.0) : 60.0;
    ServerProcess server({"cornell", "--port", "0", "--width", "64", "--height", "48"});
    const auto port = server.waitUntilServing();
    ASSERT_TRUE(port) << server.err();
    constexpr int kClients = 8;
    std::vector<serve::probe::ProbeResult> results(kClients);
    std::atomic<bool> stop{false};
    std::vector<std::thread> clients;
    for (int i = 0; i < kClients; ++i)
        clients.emplace_back([&, i] {
            serve::probe::ProbeOptions o;
            o.port = *port;
            o.seconds = seconds;
            o.inputEvery = 0.05 * (i + 1);
            results[std::size_t(i)] = serve::probe::runProbe(o, stop);
        });
    std::vector<long> rss;
    const auto start = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() - start < std::chrono::duration<double>(seconds)) {
        std::this_thread::sleep_for(std::chrono::seconds(1));
        rss.push_back(serve::probe::residentKiB(server.pid()));
        server.err();  // keep its pipe drained
    }
    for (auto& c : clients) c.join();
    ASSERT_TRUE(server.running()) << server.err();
    for (const auto& r : results) {
        EXPECT_EQ(r.error, "");
        EXPECT_GE(r.frames, 5u);
    }
    ASSERT_GE(rss.size(), 5u);
    const std::size_t settled = rss.size() / 5;
    const long early = *std::max_element(rss.begin(), rss.begin() + std::ptrdiff_t(settled) + 1);
    const long late = *std::max_element(rss.end() - std::ptrdiff_t(settled), rss.end());
    EXPECT_LE(late, early + 8 * 1024) << "resident memory grew from " << early << " KiB to " << late << " KiB";
    EXPECT_EQ(server.stop(), 0) << server.err();
    EXPECT_EQ(server.err().find("Validation"), std::string::npos) << server.err();
}

}  // namespace
}  // namespace penumbra::test
