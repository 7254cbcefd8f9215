#include "serve/http_server.h"

#include <boost/asio/strand.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/version.hpp>
#include <boost/beast/websocket.hpp>

#include "core/error.h"
#include "serve/web_assets.h"
#include "serve/ws_session.h"

namespace penumbra::serve {

namespace beast = boost::beast;
namespace http = beast::http;
namespace asio = boost::asio;
using tcp = asio::ip::tcp;

namespace {

constexpr std::size_t kMaxHeaderBytes = 8 * 1024;
constexpr auto kRequestTimeout = std::chrono::seconds(30);

// One HTTP connection: requests one after another until it closes or upgrades.
class HttpSession : public std::enable_shared_from_this<HttpSession> {
public:
    HttpSession(tcp::socket&& socket, const std::string& token, ClientHub& hub)
        : stream_(std::move(socket)), token_(token), hub_(hub) {}

    void start() { read(); }

private:
    void read() {
        parser_.emplace();
        parser_->header_limit(kMaxHeaderBytes);
        parser_->body_limit(1024);  // GET has no body
        stream_.expires_after(kRequestTimeout);
        http::async_read(stream_, buffer_, *parser_, beast::bind_front_handler(&HttpSession::onRead, shared_from_this()));
    }

    void onRead(beast::error_code ec, std::size_t) {
        if (ec) return;  // closed, timed out or malformed: drop the connection
        http::request<http::string_body> request = parser_->release();
        const std::string_view target(request.target().data(), request.target().size());
        if (beast::websocket::is_upgrade(request) && targetPath(target) == "/ws") {
            if (!targetHasToken(target, token_)) return respond(request, http::status::forbidden, "a token is needed: add ?token=...\n");
            stream_.expires_never();
            std::make_shared<WsSession>(stream_.release_socket(), hub_)->start(std::move(request));
            return;
        }
        if (request.method() != http::verb::get && request.method() != http::verb::head)
            return respond(request, http::status::method_not_allowed, "only GET\n");
        const std::string_view path = targetPath(target);
        const std::optional<WebAsset> asset = findWebAsset(path);
        if (!asset) return respond(request, http::status::not_found, "not found\n");
        // The page opens the stream, so it asks for the token too; the element and styles do not.
        if ((path == "/" || path.ends_with(".html")) && !targetHasToken(target, token_))
            return respond(request, http::status::forbidden, "a token is needed: add ?token=...\n");
        respond(request, http::status::ok, std::string(asset->body), asset->contentType);
    }

    void respond(const http::request<http::string_body>& request, http::status status, std::string body,
                 std::string_view type = "text/plain; charset=utf-8") {
        auto response = std::make_shared<http::response<http::string_body>>(status, request.version());
        response->set(http::field::server, "penumbra");
        response->set(http::field::content_type, beast::string_view(type.data(), type.size()));
        response->set(http::field::cache_control, "no-cache");
        // The element may be loaded by pages of other origins (<script src=...>).
        response->set(http::field::access_control_allow_origin, "*");
        response->keep_alive(request.keep_alive() && status == http::status::ok);
        if (request.method() == http::verb::head) response->content_length(body.size());
        else response->body() = std::move(body);
        response->prepare_payload();
        http::async_write(stream_, *response, [self = shared_from_this(), response](beast::error_code ec, std::size_t) {
            if (!ec && response->keep_alive()) self->read();
            else self->stream_.socket().shutdown(tcp::socket::shutdown_send, ec);
        });
    }

    beast::tcp_stream stream_;
    beast::flat_buffer buffer_;
    std::optional<http::request_parser<http::string_body>> parser_;
    const std::string& token_;
    ClientHub& hub_;
};

}  // namespace

std::string_view targetPath(std::string_view target) { return target.substr(0, target.find('?')); }

bool targetHasToken(std::string_view target, std::string_view token) {
    if (token.empty()) return true;
    const std::size_t q = target.find('?');
    if (q == std::string_view::npos) return false;
    std::string_view query = target.substr(q + 1);
    while (!query.empty()) {
        const std::size_t amp = query.find('&');
        const std::string_view pair = query.substr(0, amp);
        if (pair.starts_with("token=")) {
            const std::string_view given = pair.substr(6);
            unsigned diff = given.size() != token.size();
            for (std::size_t i = 0; i < token.size(); ++i) diff |= unsigned(i < given.size() ? given[i] ^ token[i] : 1);
            if (diff == 0) return true;
        }
        query = amp == std::string_view::npos ? std::string_view() : query.substr(amp + 1);
    }
    return false;
}

HttpServer::HttpServer(asio::io_context& io, const std::string& bindAddress, unsigned short port, std::string token,
                       ClientHub& hub)
    : io_(io), acceptor_(io), retry_(io), token_(std::move(token)), hub_(hub) {
    beast::error_code ec;
    const asio::ip::address address = asio::ip::make_address(bindAddress, ec);
    if (ec) throw UsageError("--bind: '" + bindAddress + "' is not an IP address");
    const tcp::endpoint endpoint(address, port);
    const std::string where = bindAddress + ":" + std::to_string(port);
    acceptor_.open(endpoint.protocol(), ec);
    if (!ec) acceptor_.set_option(asio::socket_base::reuse_address(true), ec);
    if (!ec) acceptor_.bind(endpoint, ec);
    if (!ec) acceptor_.listen(asio::socket_base::max_listen_connections, ec);
    if (ec) throw Error("cannot listen on " + where + ": " + ec.message());
    accept();
}

unsigned short HttpServer::port() const { return acceptor_.local_endpoint().port(); }

void HttpServer::close() {
    beast::error_code ec;
    acceptor_.close(ec);
    retry_.cancel();
}

void HttpServer::accept() {
    acceptor_.async_accept(asio::make_strand(io_), [this](beast::error_code ec, tcp::socket socket) {
        if (ec == asio::error::operation_aborted || !acceptor_.is_open()) return;
        if (ec) {  // e.g. out of file descriptors: try again shortly rather than spin
            logDropped("a connection: " + ec.message());
            retry_.expires_after(std::chrono::milliseconds(100));
            retry_.async_wait([this](beast::error_code waited) {
                if (!waited) accept();
            });
            return;
        }
        beast::error_code ignored;
        socket.set_option(tcp::no_delay(true), ignored);  // frames and inputs go out at once
        std::make_shared<HttpSession>(std::move(socket), token_, hub_)->start();
        accept();
    });
}

}  // namespace penumbra::serve
