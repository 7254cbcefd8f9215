// The HTTP side of `penumbra serve` (Boost.Beast): GET serves the embedded page and element,
// GET /ws upgrades to the frame stream (ws_session.h). With a token, the page and the stream ask
// for `?token=` in the URL; the element and styles are public, so other pages can load them.
#pragma once

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>

#include <memory>
#include <string>

#include "serve/client_hub.h"

namespace penumbra::serve {

class HttpServer {
public:
    // Listens at once; Error (one line) when the address cannot be bound.
    HttpServer(boost::asio::io_context& io, const std::string& bindAddress, unsigned short port, std::string token,
               ClientHub& hub);
    unsigned short port() const;  // the port bound (the one the system chose for port 0)
    void close();                 // stops accepting

private:
    void accept();
    boost::asio::io_context& io_;
    boost::asio::ip::tcp::acceptor acceptor_;
    boost::asio::steady_timer retry_;  // after a failed accept (no file descriptors left, ...)
    std::string token_;
    ClientHub& hub_;
};

// Whether a request target carries the token (constant time in the token's length); always true
// when the server has none.
bool targetHasToken(std::string_view target, std::string_view token);
// The path part of a request target (before '?').
std::string_view targetPath(std::string_view target);

}  // namespace penumbra::serve
