// Where the render loop and the browsers' connections meet. Connections (network threads) join,
// post what their browser sent and leave; the render loop drains those messages once a frame and
// broadcasts frames and stats. Every queue here is bounded: a flood of messages is cut off with a
// log line, and frames are never queued (each connection keeps only the newest it has not sent).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "serve/frame_encoder.h"
#include "serve/protocol.h"

namespace penumbra::serve {

// One browser's connection, as the hub sees it (implemented by the WebSocket session).
class ClientConnection {
public:
    virtual ~ClientConnection() = default;
    virtual void sendFrame(std::shared_ptr<const EncodedFrame> frame) = 0;
    // Stats: the connection adds its own figures (frames per second it sent) before sending.
    virtual void sendStats(std::shared_ptr<const nlohmann::json> stats) = 0;
    virtual void sendText(std::shared_ptr<const std::string> text) = 0;
};

struct InboxItem {
    enum class Kind { Joined, Message, Left };
    Kind kind = Kind::Message;
    std::uint64_t client = 0;
    ClientMessage message;  // Kind::Message
};

class ClientHub {
public:
    static constexpr std::size_t kMaxInbox = 4096;  // messages waiting for the render loop
    static constexpr std::size_t kMaxClients = 64;  // browsers watching at once

    // Network side. join sends the hello at once; it returns 0 (and the connection should close)
    // when kMaxClients already watch.
    std::uint64_t join(std::weak_ptr<ClientConnection> connection);
    void leave(std::uint64_t client);
    void post(std::uint64_t client, ClientMessage message);

    // Render side.
    std::vector<InboxItem> drain();
    void broadcastFrame(std::shared_ptr<const EncodedFrame> frame);
    void broadcastStats(nlohmann::json stats);
    void setHello(nlohmann::json hello);
    std::size_t clients() const;
    // Sleeps until a browser connects or `timeout` passes; true when one is connected.
    bool waitForClient(std::chrono::milliseconds timeout);

private:
    std::vector<std::shared_ptr<ClientConnection>> live() const;  // under no lock

    struct Entry {
        std::uint64_t id;
        std::weak_ptr<ClientConnection> connection;
    };
    mutable std::mutex mutex_;
    std::condition_variable joined_;
    std::vector<Entry> clients_;
    std::vector<InboxItem> inbox_;
    std::uint64_t nextId_ = 1;
    std::uint64_t inboxDropped_ = 0;
    std::shared_ptr<const std::string> hello_;
};

// At most a few log lines a second, however many bad messages arrive; the rest are counted and
// summed up in the next line that goes out.
void logDropped(const std::string& what);

}  // namespace penumbra::serve
