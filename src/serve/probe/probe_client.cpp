#include "serve/probe/probe_client.h"

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <stb_image_write.h>

#include <deque>
#include <filesystem>
#include <fstream>

#include "serve/frame_message.h"
#include "serve/jpeg_encoder.h"

namespace penumbra::serve::probe {
namespace {

namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace asio = boost::asio;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// The frame's strips decoded into one RGB picture and written as PNG.
void saveFrame(const ParsedFrame& frame, const std::string& path) {
    const int w = frame.info.width, h = frame.info.height;
    std::string rgb(std::size_t(w) * std::size_t(h) * 3, '\0');
    for (const Strip& s : frame.strips) {
        int sw = 0, sh = 0;
        std::string strip;
        if (!decodeJpeg(s.jpeg, sw, sh, strip) || sw != w || s.y + sh > h) return;
        std::copy(strip.begin(), strip.end(), rgb.begin() + std::ptrdiff_t(std::size_t(s.y) * std::size_t(w) * 3));
    }
    stbi_write_png(path.c_str(), w, h, 3, rgb.data(), w * 3);
}

struct Pending {
    std::uint32_t seq;
    Clock::time_point sent;
};

}  // namespace

ProbeResult runProbe(const ProbeOptions& o, const std::atomic<bool>& stop) {
    ProbeResult r;
    try {
        asio::io_context io;
        asio::ip::tcp::resolver resolver(io);
        websocket::stream<beast::tcp_stream> ws(io);
        beast::get_lowest_layer(ws).expires_after(std::chrono::seconds(10));
        beast::get_lowest_layer(ws).connect(resolver.resolve(o.host, o.port));
        // As browsers do: an ack and an input written back to back must not wait for Nagle.
        beast::get_lowest_layer(ws).socket().set_option(asio::ip::tcp::no_delay(true));
        ws.handshake(o.host + ":" + o.port, o.target);
        beast::get_lowest_layer(ws).expires_never();
        ws.read_message_max(64 * 1024 * 1024);
        const auto start = Clock::now();
        auto nextInput = start;
        std::uint32_t seq = 0;
        std::deque<Pending> pending;
        int saved = 0;
        beast::flat_buffer buffer;
        while (!stop && msSince(start) < o.seconds * 1000) {
            beast::get_lowest_layer(ws).expires_after(std::chrono::seconds(10));
            ws.read(buffer);
            const std::string_view bytes(static_cast<const char*>(buffer.data().data()), buffer.size());
            if (ws.got_text()) {
                ++r.texts;
                (r.hello.empty() ? r.hello : r.lastStats).assign(bytes);
            } else if (std::optional<ParsedFrame> f = parseFrame(bytes)) {
                ++r.frames;
                r.bytes += bytes.size();
                r.width = f->info.width;
                r.height = f->info.height;
                r.lastQuality = f->info.quality;
                r.renderMs.push_back(f->info.renderMs);
                r.encodeMs.push_back(f->info.encodeMs);
                while (!pending.empty() && std::int32_t(pending.front().seq - f->ack) <= 0) {
                    r.latencyMs.push_back(msSince(pending.front().sent));
                    pending.pop_front();
                }
                if (!o.saveDir.empty() && saved < o.saveCount && r.frames % 10 == 0)
                    saveFrame(*f, (std::filesystem::path(o.saveDir) / ("frame-" + std::to_string(saved++) + ".png")).string());
                if (o.ackFrames) {
                    ws.text(true);
                    ws.write(asio::buffer("{\"t\":\"ack\",\"frame\":" + std::to_string(f->info.frame) + "}"));
                }
            } else {
                r.error = "a malformed frame";
                break;
            }
            buffer.consume(buffer.size());
            if (o.inputEvery > 0 && Clock::now() >= nextInput) {
                // A small look to and fro: the camera moves, but stays where it was over time.
                const int dx = (seq % 2 == 0) ? 2 : -2;
                pending.push_back({++seq, Clock::now()});
                ws.text(true);
                ws.write(asio::buffer("{\"t\":\"look\",\"dx\":" + std::to_string(dx) + ",\"dy\":0,\"seq\":" +
                                      std::to_string(seq) + "}"));
                nextInput = Clock::now() + std::chrono::microseconds(std::int64_t(o.inputEvery * 1e6));
            }
        }
        r.seconds = msSince(start) / 1000;
        beast::error_code ec;
        ws.close(websocket::close_code::normal, ec);
    } catch (const std::exception& e) {
        r.error = e.what();
    }
    return r;
}

long residentKiB(int pid) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    std::string key;
    long value = 0;
    while (status >> key) {
        if (key == "VmRSS:") return (status >> value) ? value : 0;
        status.ignore(1 << 12, '\n');
    }
    return 0;
}

}  // namespace penumbra::serve::probe
