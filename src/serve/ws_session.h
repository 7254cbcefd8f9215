// One browser's WebSocket (Boost.Beast): reads its messages into the hub, and writes frames and
// text to it one message at a time. Writes never queue up: while a write is under way, or while
// the browser has two frames it has not acknowledged, a new frame replaces the one waiting, and
// stats replace older stats. A browser that stops reading is closed by the idle timeout.
#pragma once

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/strand.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <array>
#include <chrono>
#include <deque>
#include <memory>

#include "serve/client_hub.h"

namespace penumbra::serve {

class WsSession : public ClientConnection, public std::enable_shared_from_this<WsSession> {
public:
    static constexpr std::uint32_t kMaxUnacknowledged = 2;
    // Frames and text messages larger than the protocol's 4 KiB are read and dropped up to this
    // size; a larger one closes the connection (WebSocket code 1009).
    static constexpr std::size_t kMaxReadBytes = 64 * 1024;

    WsSession(boost::asio::ip::tcp::socket&& socket, ClientHub& hub);
    ~WsSession() override;
    // Completes the upgrade the HTTP session read, then serves the browser until it goes.
    void start(boost::beast::http::request<boost::beast::http::string_body> request);

    void sendFrame(std::shared_ptr<const EncodedFrame> frame) override;
    void sendStats(std::shared_ptr<const nlohmann::json> stats) override;
    void sendText(std::shared_ptr<const std::string> text) override;

private:
    void onAccept(boost::beast::error_code ec);
    void read();
    void onRead(boost::beast::error_code ec, std::size_t bytes);
    void handleText(std::string_view text);
    void writeNext();  // on the strand
    void onWrite(boost::beast::error_code ec);
    std::string statsFor(const nlohmann::json& stats);

    boost::beast::websocket::stream<boost::beast::tcp_stream> ws_;
    ClientHub& hub_;
    std::uint64_t id_ = 0;  // 0 until joined
    boost::beast::flat_buffer buffer_;
    // Strand-confined state.
    bool writing_ = false, closed_ = false;
    std::deque<std::shared_ptr<const std::string>> texts_;
    std::shared_ptr<const nlohmann::json> stats_;
    std::shared_ptr<const EncodedFrame> pendingFrame_, writingFrame_;
    std::shared_ptr<const std::string> writingText_;
    std::array<std::uint8_t, 32> header_{};
    std::deque<std::uint32_t> unacknowledged_;  // frame numbers sent and not yet drawn
    std::deque<std::chrono::steady_clock::time_point> sentTimes_;  // last second's frames
    std::uint64_t framesDropped_ = 0;
};

}  // namespace penumbra::serve
