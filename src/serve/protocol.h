// What a browser sends (docs/SERVE.md, "Browser to server"), read from one JSON text message.
// Anything malformed is refused with a reason, never thrown: a bad message is one log line.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

namespace penumbra::serve {

inline constexpr std::size_t kMaxClientMessageBytes = 4096;

struct KeyMessage {
    int key = -1;  // GLFW key code (interact/controls.h); -1: a key no control uses
    bool down = false;
};
struct LookMessage {
    float dx = 0, dy = 0;  // pointer pixels
};
struct WheelMessage {
    float notches = 0;
};
// Positions are fractions of the picture, 0..1 from its top left.
struct ClickMessage {
    float x = 0, y = 0;
};
struct GrabMessage {
    float x = 0, y = 0;
    bool turn = false;
};
struct DragMessage {
    float x = 0, y = 0;
};
struct ReleaseMessage {};
struct SetMessage {
    std::string name;
    nlohmann::json value;
};
struct AckMessage {
    std::uint32_t frame = 0;
};

using ClientBody = std::variant<KeyMessage, LookMessage, WheelMessage, ClickMessage, GrabMessage, DragMessage,
                                ReleaseMessage, SetMessage, AckMessage>;

struct ClientMessage {
    ClientBody body;
    std::uint32_t seq = 0;  // 0: none given
};

// The message, or nothing with `error` saying why it was refused.
std::optional<ClientMessage> parseClientMessage(std::string_view text, std::string& error);

// The GLFW key code for a KeyboardEvent.code ("KeyW", "ShiftLeft", "ArrowUp", ...), or -1.
int keyFromBrowserCode(std::string_view code);

}  // namespace penumbra::serve
