#include "serve/client_hub.h"

#include <algorithm>

#include "core/log.h"

namespace penumbra::serve {

std::uint64_t ClientHub::join(std::weak_ptr<ClientConnection> connection) {
    std::shared_ptr<const std::string> hello;
    std::uint64_t id = 0;
    {
        std::lock_guard lock(mutex_);
        if (clients_.size() >= kMaxClients) {
            logDropped("a browser: " + std::to_string(kMaxClients) + " already watch");
            return 0;
        }
        id = nextId_++;
        clients_.push_back({id, connection});
        inbox_.push_back({InboxItem::Kind::Joined, id, {}});
        hello = hello_;
    }
    joined_.notify_all();
    if (auto c = connection.lock(); c && hello) c->sendText(hello);
    return id;
}

void ClientHub::leave(std::uint64_t client) {
    std::lock_guard lock(mutex_);
    std::erase_if(clients_, [&](const Entry& e) { return e.id == client; });
    // Always delivered, even past the bound: the render loop must release the browser's keys.
    inbox_.push_back({InboxItem::Kind::Left, client, {}});
}

void ClientHub::post(std::uint64_t client, ClientMessage message) {
    std::lock_guard lock(mutex_);
    if (inbox_.size() >= kMaxInbox) {
        ++inboxDropped_;
        logDropped("input message: the render loop is behind by " + std::to_string(kMaxInbox) + " messages");
        return;
    }
    inbox_.push_back({InboxItem::Kind::Message, client, std::move(message)});
}

std::vector<InboxItem> ClientHub::drain() {
    std::lock_guard lock(mutex_);
    std::vector<InboxItem> items;
    items.swap(inbox_);
    return items;
}

std::vector<std::shared_ptr<ClientConnection>> ClientHub::live() const {
    std::lock_guard lock(mutex_);
    std::vector<std::shared_ptr<ClientConnection>> out;
    for (const Entry& e : clients_)
        if (auto c = e.connection.lock()) out.push_back(std::move(c));
    return out;
}

void ClientHub::broadcastFrame(std::shared_ptr<const EncodedFrame> frame) {
    for (const auto& c : live()) c->sendFrame(frame);
}

void ClientHub::broadcastStats(nlohmann::json stats) {
    auto shared = std::make_shared<const nlohmann::json>(std::move(stats));
    for (const auto& c : live()) c->sendStats(shared);
}

void ClientHub::setHello(nlohmann::json hello) {
    auto text = std::make_shared<const std::string>(hello.dump());
    std::lock_guard lock(mutex_);
    hello_ = std::move(text);
}

std::size_t ClientHub::clients() const {
    std::lock_guard lock(mutex_);
    return clients_.size();
}

bool ClientHub::waitForClient(std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    return joined_.wait_for(lock, timeout, [&] { return !clients_.empty(); });
}

void logDropped(const std::string& what) {
    using Clock = std::chrono::steady_clock;
    constexpr int kLinesPerSecond = 5;
    static std::mutex mutex;
    static Clock::time_point windowStart;
    static int linesInWindow = 0;
    static std::uint64_t silenced = 0;
    std::lock_guard lock(mutex);
    const auto now = Clock::now();
    if (now - windowStart > std::chrono::seconds(1)) {
        windowStart = now;
        linesInWindow = 0;
    }
    if (linesInWindow >= kLinesPerSecond) {
        ++silenced;
        return;
    }
    ++linesInWindow;
    std::string line = "serve: dropped " + what;
    if (silenced > 0) line += " (and " + std::to_string(silenced) + " more not logged)";
    silenced = 0;
    logWarning(line);
}

}  // namespace penumbra::serve
