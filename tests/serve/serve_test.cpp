// `penumbra serve` as a process, watched by headless clients (serve/probe): frames reach every
// browser, input and settings reach the renderer, bad and slow browsers disturb nobody, signals
// end it cleanly, and a scene that cannot load is one line and exit 2 before anything listens.
// Runs the real shaders on lavapipe at a tiny size, with validation on.
#include <gtest/gtest.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

#include <thread>

#include "serve/frame_message.h"
#include "serve/probe/probe_client.h"
#include "server_process.h"

namespace penumbra::test {
namespace {

namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace asio = boost::asio;
using serve::probe::ProbeOptions;
using serve::probe::ProbeResult;
using Ws = websocket::stream<beast::tcp_stream>;

const std::vector<std::string> kSmall = {"cornell", "--port", "0", "--width", "48", "--height", "32",
                                         "--max-fps", "0", "--rest-fps", "0"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

// A raw browser connection for the tests that send what the probe never would.
struct Browser {
    asio::io_context io;
    Ws ws{io};
    explicit Browser(const std::string& port, const std::string& target = "/ws") {
        asio::ip::tcp::resolver resolver(io);
        beast::get_lowest_layer(ws).expires_after(std::chrono::seconds(30));
        beast::get_lowest_layer(ws).connect(resolver.resolve("127.0.0.1", port));
        ws.handshake("127.0.0.1", target);
        ws.read_message_max(16 << 20);
    }
    void send(const std::string& text) {
        ws.text(true);
        ws.write(asio::buffer(text));
    }
    // The next message; binary frames are acknowledged, as a page does once it drew them.
    std::string next(bool& binary) {
        beast::flat_buffer buffer;
        beast::get_lowest_layer(ws).expires_after(std::chrono::seconds(60));
        ws.read(buffer);
        binary = !ws.got_text();
        std::string bytes = beast::buffers_to_string(buffer.data());
        if (binary)
            if (auto f = serve::parseFrame(bytes)) send(R"({"t":"ack","frame":)" + std::to_string(f->info.frame) + "}");
        return bytes;
    }
    // Reads until `frames` frames came; returns the last stats message seen (or "{}").
    nlohmann::json readFrames(int frames) {
        nlohmann::json stats = nlohmann::json::object();
        for (int got = 0; got < frames;) {
            bool binary = false;
            const std::string m = next(binary);
            if (binary) ++got;
            else if (auto j = nlohmann::json::parse(m, nullptr, false); j.is_object() && j.value("t", "") == "stats")
                stats = j;
        }
        return stats;
    }
    // Reads until a stats message satisfies `ok`, at most `messages` messages.
    nlohmann::json statsWhere(const std::function<bool(const nlohmann::json&)>& ok, int messages = 400) {
        for (int i = 0; i < messages; ++i) {
            bool binary = false;
            const std::string m = next(binary);
            if (binary) continue;
            const auto j = nlohmann::json::parse(m, nullptr, false);
            if (j.is_object() && j.value("t", "") == "stats" && ok(j)) return j;
        }
        return nlohmann::json();
    }
};

ProbeResult watch(const std::string& port, double seconds, bool ack = true) {
    ProbeOptions o;
    o.port = port;
    o.seconds = seconds;
    o.ackFrames = ack;
    o.inputEvery = 0.2;
    std::atomic<bool> stop{false};
    return serve::probe::runProbe(o, stop);
}

void expectCleanLog(ServerProcess& server) {
    EXPECT_EQ(server.err().find("Validation"), std::string::npos) << server.err();
    EXPECT_EQ(server.err().find("error"), std::string::npos) << server.err();
}

TEST(Serve, TwoBrowsersBothReceiveFramesAndInputIsAcknowledged) {
    ServerProcess server(kSmall);
    const auto port = server.waitUntilServing();
    ASSERT_TRUE(port) << server.err();
    ProbeResult a, b;
    std::thread other([&] { b = watch(*port, 6); });
    a = watch(*port, 6);
    other.join();
    for (const ProbeResult* r : {&a, &b}) {
        EXPECT_EQ(r->error, "");
        EXPECT_GE(r->frames, 3u);
        EXPECT_EQ(r->width, 48u);
        EXPECT_EQ(r->height, 32u);
        EXPECT_FALSE(r->latencyMs.empty());  // frames said which of its inputs they show
        const auto hello = nlohmann::json::parse(r->hello, nullptr, false);
        EXPECT_EQ(hello.value("t", ""), "hello");
        EXPECT_EQ(hello.value("scene", ""), "cornell");
    }
    EXPECT_EQ(server.stop(), 0) << server.err();
    expectCleanLog(server);
}

TEST(Serve, KeysMoveTheCameraAndSettingsReachTheRenderer) {
    ServerProcess server(kSmall);
    const auto port = server.waitUntilServing();
    ASSERT_TRUE(port) << server.err();
    Browser browser(*port);
    const nlohmann::json before = browser.readFrames(2);
    ASSERT_TRUE(before.contains("camera")) << before.dump();
    browser.send(R"({"t":"key","code":"KeyW","down":true,"seq":1})");
    const nlohmann::json moved = browser.statsWhere([&](const nlohmann::json& s) { return s["camera"] != before["camera"]; });
    EXPECT_TRUE(moved.is_object()) << "the camera never moved with W held";
    browser.send(R"({"t":"key","code":"KeyW","down":false,"seq":2})");
    browser.send(R"({"t":"set","name":"debug","value":"normals","seq":3})");
    browser.send(R"({"t":"set","name":"spp","value":2,"seq":4})");
    const nlohmann::json set = browser.statsWhere([](const nlohmann::json& s) {
        return s["settings"]["debug"] == "normals" && s["settings"]["spp"] == 2;
    });
    EXPECT_TRUE(set.is_object()) << "the settings never reached the renderer";
    EXPECT_EQ(server.stop(), 0);
    expectCleanLog(server);
}

TEST(Serve, MalformedAndOversizedMessagesAreDroppedWithALogLine) {
    ServerProcess server(kSmall);
    const auto port = server.waitUntilServing();
    ASSERT_TRUE(port) << server.err();
    Browser browser(*port);
    browser.readFrames(1);
    for (const char* bad : {"", "{", "[]", R"({"t":"warp"})", R"({"t":"key","code":"KeyW"})", R"({"t":"set","name":"spp","value":"lots"})"})
        browser.send(bad);
    browser.send(std::string(10 * 1024, 'x'));  // over the protocol's 4 KiB, under the reader's limit
    // Seven bad messages in a second: five lines, the rest counted in the next line that goes out.
    std::this_thread::sleep_for(std::chrono::milliseconds(1200));
    browser.ws.binary(true);
    browser.ws.write(asio::buffer(std::string("\x01\x02\x03", 3)));
    browser.readFrames(3);  // still served
    {
        Browser flooder(*port);  // over 64 KiB: that connection is closed, nobody else's
        bool binary = false;
        // The close may come while the message is still being written (a broken pipe) or after.
        EXPECT_THROW(
            {
                flooder.send(std::string(100 * 1024, 'y'));
                for (int i = 0; i < 1000; ++i) flooder.next(binary);
            },
            beast::system_error);
    }
    browser.readFrames(3);
    EXPECT_TRUE(server.running());
    EXPECT_EQ(server.stop(), 0);
    EXPECT_NE(server.err().find("serve: dropped a message"), std::string::npos) << server.err();
    EXPECT_NE(server.err().find("binary message from a browser (the protocol has none) (and 2 more not logged)"),
              std::string::npos)
        << server.err();
}

TEST(Serve, ABrowserThatStopsDrawingGetsNoMoreFramesAndHoldsUpNobody) {
    ServerProcess server(kSmall);
    const auto port = server.waitUntilServing();
    ASSERT_TRUE(port) << server.err();
    ProbeResult slow, fast;
    std::thread other([&] { slow = watch(*port, 6, false); });
    fast = watch(*port, 6);
    other.join();
    EXPECT_LE(slow.frames, 2u);  // two frames unacknowledged, then nothing is queued for it
    EXPECT_GE(fast.frames, 3u);
    EXPECT_GT(fast.frames, slow.frames);
    EXPECT_EQ(server.stop(), 0);
}

TEST(Serve, ABrowserThatGoesMidFrameReleasesItsKeysAndDisturbsNobody) {
    ServerProcess server(kSmall);
    const auto port = server.waitUntilServing();
    ASSERT_TRUE(port) << server.err();
    Browser watcher(*port);
    watcher.readFrames(1);
    {
        Browser leaver(*port);
        leaver.send(R"({"t":"key","code":"KeyS","down":true})");
        leaver.readFrames(1);
        // Gone without a close handshake, with a frame on its way: the socket is reset.
        beast::get_lowest_layer(leaver.ws).socket().set_option(asio::socket_base::linger(true, 0));
        beast::get_lowest_layer(leaver.ws).socket().close();
    }
    // Its S is released: the camera comes to rest (two stats a quarter second apart agree).
    nlohmann::json last;
    const nlohmann::json still = watcher.statsWhere([&](const nlohmann::json& s) {
        const bool same = last.is_object() && last["camera"] == s["camera"] && s["clients"] == 1;
        last = s;
        return same;
    });
    EXPECT_TRUE(still.is_object()) << "the camera kept moving after the browser holding S went";
    watcher.readFrames(3);
    EXPECT_EQ(server.stop(), 0);
    expectCleanLog(server);
}

TEST(Serve, SigintAndSigtermEndItCleanly) {
    for (int signal : {SIGINT, SIGTERM}) {
        ServerProcess server(kSmall);
        const auto port = server.waitUntilServing();
        ASSERT_TRUE(port) << server.err();
        Browser browser(*port);
        browser.readFrames(1);
        EXPECT_EQ(server.stop(signal), 0) << server.err();
        EXPECT_NE(server.err().find("server stopped"), std::string::npos) << server.err();
    }
}

TEST(Serve, ASceneThatCannotLoadIsOneLineAndExitTwoBeforeListening) {
    ServerProcess server({"/nonexistent/scene.obj", "--port", "0"});
    EXPECT_EQ(server.wait(std::chrono::seconds(60)), 2);
    EXPECT_EQ(server.out().find("serving"), std::string::npos) << server.out();
    EXPECT_EQ(server.err().rfind("penumbra: error: ", 0), 0u) << server.err();
    EXPECT_EQ(std::count(server.err().begin(), server.err().end(), '\n'), 1) << server.err();
}

TEST(Serve, BadOptionsAreOneLineAndExitTwo) {
    for (const std::vector<std::string>& args : {std::vector<std::string>{"--port", "70000"}, {"--token", "a b"},
                                               {"--bind", "not-an-address", "--port", "0"}, {"--quality", "0"},
                                               {"--debug", "sideways"}}) {
        ServerProcess server(with({"cornell"}, args));
        EXPECT_EQ(server.wait(std::chrono::seconds(60)), 2) << args[0];
        EXPECT_EQ(server.err().rfind("penumbra: error: ", 0), 0u) << server.err();
        EXPECT_EQ(server.out().find("serving"), std::string::npos);
    }
}

TEST(Serve, EveryAddressWarnsAndTheTokenGuardsTheStream) {
    // Bound to every address for this test; it talks to loopback only.
    ServerProcess server(with(kSmall, {"--bind", "0.0.0.0", "--token", "t0k3n"}));
    const auto port = server.waitUntilServing();
    ASSERT_TRUE(port) << server.err();
    EXPECT_NE(server.err().find("penumbra: warning: serving on 0.0.0.0"), std::string::npos) << server.err();
    EXPECT_NE(server.out().find("?token=t0k3n"), std::string::npos) << server.out();
    EXPECT_THROW(Browser(*port, "/ws"), beast::system_error);
    EXPECT_THROW(Browser(*port, "/ws?token=wrong"), beast::system_error);
    Browser browser(*port, "/ws?token=t0k3n");
    browser.readFrames(1);
    EXPECT_EQ(server.stop(), 0);
}

}  // namespace
}  // namespace penumbra::test
