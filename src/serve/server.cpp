#include "serve/server.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>

#include <cstdio>
#include <thread>

#include "core/error.h"
#include "core/interrupt.h"
#include "core/log.h"
#include "interact/navigation.h"
#include "serve/client_hub.h"
#include "serve/frame_encoder.h"
#include "serve/frame_readback.h"
#include "serve/http_server.h"
#include "serve/serve_loop.h"

namespace penumbra::serve {
namespace {

bool isLoopback(const std::string& address) {
    return address.starts_with("127.") || address == "::1" || address == "localhost";
}

// The network thread: runs the HTTP and WebSocket handlers until stopped.
class NetworkThread {
public:
    explicit NetworkThread(boost::asio::io_context& io) : io_(io), thread_([this] { io_.run(); }) {}
    ~NetworkThread() {
        io_.stop();
        thread_.join();
    }

private:
    boost::asio::io_context& io_;
    std::thread thread_;
};

}  // namespace

void runServer(Scene scene, const ServeOptions& options) {
    ViewSettings start = options.view;
    viewer::prepareSceneSettings(scene, start);
    ServeOptions o = options;
    o.view = start;

    gpu::ContextOptions ctxOptions;
    ctxOptions.deviceSelector = o.device;
    gpu::ContextResult result = gpu::Context::create(ctxOptions);
    if (!result.context) throw Error(result.error);

    // They go in reverse order: the encoder (which posts frames to the sessions) first, then the
    // network thread, then the sessions with the io_context, and the hub they all use last.
    ClientHub hub;
    FrameReadback readback(*result.context);
    ServeLoop loop(*result.context, scene, o, hub);
    boost::asio::io_context io(1);
    HttpServer http(io, o.bind, o.port, o.token, hub);
    StopOnSignals signals;
    NetworkThread network(io);
    FrameEncoder encoder(readback, o.encode, [&hub](std::shared_ptr<const EncodedFrame> frame) {
        hub.broadcastFrame(std::move(frame));
    });

    if (!isLoopback(o.bind))
        logWarning("serving on " + o.bind + ", reachable from other machines" +
                   (o.token.empty() ? std::string(" by anyone: consider --token") : std::string()));
    const std::string host = o.bind.find(':') != std::string::npos ? "[" + o.bind + "]" : o.bind;
    std::printf("penumbra: serving http://%s:%u/%s\n", host.c_str(), unsigned(http.port()),
                o.token.empty() ? "" : ("?token=" + o.token).c_str());
    std::fflush(stdout);

    loop.run(readback, encoder, [] { return StopOnSignals::signal() != 0; });
    boost::asio::post(io, [&http] { http.close(); });
    if (const int sig = StopOnSignals::signal())
        std::fprintf(stderr, "penumbra: %s: server stopped\n", StopOnSignals::signalName(sig));
}

}  // namespace penumbra::serve
