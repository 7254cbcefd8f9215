// Load: eight browsers watch for a minute (PENUMBRA_SERVE_LOAD_SECONDS), each acknowledging
// frames and sending input, on loopback. Nothing crashes, every browser receives frames, and the
// server's memory stays flat.
//
// Lavapipe (Mesa 22.3, the CPU Vulkan of CI) keeps 2-4 MB for every submission until its device
// is destroyed, so a server rendering all minute on it grows by gigabytes whatever the server
// does (the same load on an H100 stays flat: docs/PERFORMANCE.md, "penumbra serve"). The test
// therefore renders for the first fifth, then pauses the renderer (`playing` false: looks no
// longer move the camera, so nothing is rendered) while the browsers go on sending input and
// acknowledgements and receiving stats: the memory of everything the server itself keeps per
// browser and per message is what must stay flat.
#include <gtest/gtest.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

#include <algorithm>
#include <cstdlib>
#include <thread>

#include "serve/probe/probe_client.h"
#include "server_process.h"

namespace penumbra::test {
namespace {

namespace beast = boost::beast;
namespace asio = boost::asio;

// Sends one setting from a browser of its own, then goes.
void sendSetting(const std::string& port, const std::string& message) {
    asio::io_context io;
    beast::websocket::stream<beast::tcp_stream> ws(io);
    asio::ip::tcp::resolver resolver(io);
    beast::get_lowest_layer(ws).expires_after(std::chrono::seconds(30));
    beast::get_lowest_layer(ws).connect(resolver.resolve("127.0.0.1", port));
    ws.handshake("127.0.0.1", "/ws");
    ws.text(true);
    ws.write(asio::buffer(message));
    ws.close(beast::websocket::close_code::normal);
}

TEST(ServeLoad, EightBrowsersForAMinuteAndMemoryStaysFlat) {
    const char* env = std::getenv("PENUMBRA_SERVE_LOAD_SECONDS");
    const double seconds = env ? std::clamp(std::atof(env), 10.0, 600.0) : 60.0;
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
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    while (elapsed() < seconds / 5) std::this_thread::sleep_for(std::chrono::milliseconds(200));
    sendSetting(*port, R"({"t":"set","name":"playing","value":false})");
    std::this_thread::sleep_for(std::chrono::seconds(2));  // the frame under way finishes
    std::vector<long> rss;
    while (elapsed() < seconds) {
        rss.push_back(serve::probe::residentKiB(server.pid()));
        server.err();  // keep its pipe drained
        std::this_thread::sleep_for(std::chrono::seconds(1));
    }
    for (auto& c : clients) c.join();
    ASSERT_TRUE(server.running()) << server.err();
    for (const auto& r : results) {
        EXPECT_EQ(r.error, "");
        EXPECT_GE(r.frames, 2u);
        EXPECT_GE(r.texts, std::uint64_t(seconds));  // stats kept coming all minute (four a second)
    }
    ASSERT_GE(rss.size(), 4u);
    const std::size_t quarter = rss.size() / 4;
    const long early = *std::max_element(rss.begin(), rss.begin() + std::ptrdiff_t(quarter) + 1);
    const long late = *std::max_element(rss.end() - std::ptrdiff_t(quarter), rss.end());
    EXPECT_LE(late, early + 4 * 1024) << "resident memory grew from " << early << " KiB to " << late << " KiB";
    EXPECT_EQ(server.stop(), 0) << server.err();
    EXPECT_EQ(server.err().find("Validation"), std::string::npos) << server.err();
}

}  // namespace
}  // namespace penumbra::test
