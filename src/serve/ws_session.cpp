#include "serve/ws_session.h"

#include <boost/asio/dispatch.hpp>
#include <boost/asio/post.hpp>

namespace penumbra::serve {

namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace asio = boost::asio;
using Clock = std::chrono::steady_clock;

namespace {
constexpr std::size_t kMaxTexts = 16;  // hello and replies; stats have their own slot
}

WsSession::WsSession(asio::ip::tcp::socket&& socket, ClientHub& hub) : ws_(std::move(socket)), hub_(hub) {}

WsSession::~WsSession() {
    if (id_ != 0) hub_.leave(id_);
}

void WsSession::start(beast::http::request<beast::http::string_body> request) {
    websocket::stream_base::timeout timeout = websocket::stream_base::timeout::suggested(beast::role_type::server);
    timeout.idle_timeout = std::chrono::seconds(20);  // a browser that stops answering pings goes
    timeout.keep_alive_pings = true;
    ws_.set_option(timeout);
    ws_.read_message_max(kMaxReadBytes);
    ws_.async_accept(request, beast::bind_front_handler(&WsSession::onAccept, shared_from_this()));
}

void WsSession::onAccept(beast::error_code ec) {
    if (ec) return;  // the upgrade failed: the browser sees the closed connection
    ws_.auto_fragment(false);
    id_ = hub_.join(weak_from_this());
    if (id_ == 0) {  // full: say so and go
        ws_.async_close(websocket::close_reason(websocket::close_code::try_again_later),
                        [self = shared_from_this()](beast::error_code) {});
        return;
    }
    read();
}

void WsSession::read() {
    ws_.async_read(buffer_, beast::bind_front_handler(&WsSession::onRead, shared_from_this()));
}

void WsSession::onRead(beast::error_code ec, std::size_t) {
    if (ec) {
        if (ec == websocket::error::message_too_big) logDropped("a message over 64 KiB (connection closed)");
        asio::dispatch(ws_.get_executor(), [self = shared_from_this()] { self->closed_ = true; });
        return;  // closed, reset or timed out: the session ends with its last handler
    }
    if (!ws_.got_text()) logDropped("a binary message from a browser (the protocol has none)");
    else handleText(std::string_view(static_cast<const char*>(buffer_.data().data()), buffer_.size()));
    buffer_.consume(buffer_.size());
    read();
}

void WsSession::handleText(std::string_view text) {
    std::string error;
    std::optional<ClientMessage> message = parseClientMessage(text, error);
    if (!message) {
        logDropped("a message: " + error);
        return;
    }
    if (const auto* ack = std::get_if<AckMessage>(&message->body)) {
        // Drawn: that frame and every earlier one are no longer outstanding.
        while (!unacknowledged_.empty() && std::int32_t(unacknowledged_.front() - ack->frame) <= 0)
            unacknowledged_.pop_front();
        writeNext();
        return;
    }
    hub_.post(id_, std::move(*message));
}

void WsSession::sendFrame(std::shared_ptr<const EncodedFrame> frame) {
    asio::post(ws_.get_executor(), [self = shared_from_this(), frame = std::move(frame)]() mutable {
        if (self->pendingFrame_) ++self->framesDropped_;
        self->pendingFrame_ = std::move(frame);
        self->writeNext();
    });
}

void WsSession::sendStats(std::shared_ptr<const nlohmann::json> stats) {
    asio::post(ws_.get_executor(), [self = shared_from_this(), stats = std::move(stats)]() mutable {
        self->stats_ = std::move(stats);
        self->writeNext();
    });
}

void WsSession::sendText(std::shared_ptr<const std::string> text) {
    asio::post(ws_.get_executor(), [self = shared_from_this(), text = std::move(text)]() mutable {
        if (self->texts_.size() >= kMaxTexts) return;  // a browser far behind misses replies
        self->texts_.push_back(std::move(text));
        self->writeNext();
    });
}

std::string WsSession::statsFor(const nlohmann::json& stats) {
    const auto now = Clock::now();
    while (!sentTimes_.empty() && now - sentTimes_.front() > std::chrono::seconds(1)) sentTimes_.pop_front();
    nlohmann::json mine = stats;
    mine["fps"] = sentTimes_.size();
    mine["framesDropped"] = framesDropped_;
    return mine.dump();
}

void WsSession::writeNext() {
    if (writing_ || closed_ || id_ == 0) return;
    if (!texts_.empty() || stats_) {
        if (!texts_.empty()) {
            writingText_ = std::move(texts_.front());
            texts_.pop_front();
        } else {
            writingText_ = std::make_shared<const std::string>(statsFor(*stats_));
            stats_.reset();
        }
        writing_ = true;
        ws_.text(true);
        ws_.async_write(asio::buffer(*writingText_), [self = shared_from_this()](beast::error_code ec, std::size_t) {
            self->onWrite(ec);
        });
        return;
    }
    if (!pendingFrame_ || unacknowledged_.size() >= kMaxUnacknowledged) return;
    writingFrame_ = std::move(pendingFrame_);
    const EncodedFrame& f = *writingFrame_;
    std::uint32_t ack = 0;
    for (const auto& [client, seq] : f.acks)
        if (client == id_) ack = seq;
    header_ = frameHeader(f.info, ack, f.stripCount);
    unacknowledged_.push_back(f.info.frame);
    sentTimes_.push_back(Clock::now());
    writing_ = true;
    ws_.binary(true);
    const std::array<asio::const_buffer, 2> message{asio::buffer(header_), asio::buffer(f.strips)};
    ws_.async_write(message, [self = shared_from_this()](beast::error_code ec, std::size_t) { self->onWrite(ec); });
}

void WsSession::onWrite(beast::error_code ec) {
    writing_ = false;
    writingFrame_.reset();
    writingText_.reset();
    if (ec) {
        closed_ = true;
        return;
    }
    writeNext();
}

}  // namespace penumbra::serve
