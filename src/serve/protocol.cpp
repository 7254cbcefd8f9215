#include "serve/protocol.h"

#include <GLFW/glfw3.h>

#include <cmath>
#include <utility>

namespace penumbra::serve {
namespace {

// A field that must be a finite number within [-limit, limit].
bool number(const nlohmann::json& j, const char* name, float limit, float& out, std::string& error) {
    const auto it = j.find(name);
    if (it == j.end() || !it->is_number()) {
        error = std::string("'") + name + "' must be a number";
        return false;
    }
    const double v = it->get<double>();
    if (!std::isfinite(v) || std::abs(v) > limit) {
        error = std::string("'") + name + "' is out of range";
        return false;
    }
    out = float(v);
    return true;
}

bool position(const nlohmann::json& j, float& x, float& y, std::string& error) {
    return number(j, "x", 1e3f, x, error) && number(j, "y", 1e3f, y, error);
}

bool flag(const nlohmann::json& j, const char* name, bool& out, std::string& error) {
    const auto it = j.find(name);
    if (it == j.end()) return true;  // flags are optional: false
    if (!it->is_boolean()) {
        error = std::string("'") + name + "' must be true or false";
        return false;
    }
    out = it->get<bool>();
    return true;
}

std::optional<ClientBody> parseKey(const nlohmann::json& j, std::string& error) {
    const auto code = j.find("code");
    if (code == j.end() || !code->is_string()) {
        error = "'code' must be a string";
        return std::nullopt;
    }
    KeyMessage m;
    m.key = keyFromBrowserCode(code->get_ref<const std::string&>());
    const auto down = j.find("down");
    if (down == j.end() || !down->is_boolean()) {
        error = "'down' must be true or false";
        return std::nullopt;
    }
    m.down = down->get<bool>();
    return m;
}

std::optional<ClientBody> parseBody(const std::string& type, const nlohmann::json& j, std::string& error) {
    constexpr float kPixels = 1e5f;  // more pointer motion than any screen gives in one message
    if (type == "key") return parseKey(j, error);
    if (type == "look") {
        LookMessage m;
        if (number(j, "dx", kPixels, m.dx, error) && number(j, "dy", kPixels, m.dy, error)) return m;
    } else if (type == "wheel") {
        WheelMessage m;
        if (number(j, "dy", 100.0f, m.notches, error)) return m;
    } else if (type == "click") {
        ClickMessage m;
        if (position(j, m.x, m.y, error)) return m;
    } else if (type == "grab") {
        GrabMessage m;
        if (position(j, m.x, m.y, error) && flag(j, "turn", m.turn, error)) return m;
    } else if (type == "drag") {
        DragMessage m;
        if (position(j, m.x, m.y, error)) return m;
    } else if (type == "release") {
        return ReleaseMessage{};
    } else if (type == "set") {
        const auto name = j.find("name");
        const auto value = j.find("value");
        if (name == j.end() || !name->is_string() || value == j.end()) {
            error = "'set' needs a string 'name' and a 'value'";
            return std::nullopt;
        }
        return SetMessage{name->get<std::string>(), *value};
    } else if (type == "ack") {
        const auto frame = j.find("frame");
        if (frame == j.end() || !frame->is_number_unsigned() || frame->get<std::uint64_t>() > 0xffffffffu) {
            error = "'frame' must be a frame number";
            return std::nullopt;
        }
        return AckMessage{frame->get<std::uint32_t>()};
    } else {
        error = "unknown message type '" + type.substr(0, 32) + "'";
    }
    return std::nullopt;
}

}  // namespace

std::optional<ClientMessage> parseClientMessage(std::string_view text, std::string& error) {
    if (text.size() > kMaxClientMessageBytes) {
        error = "message longer than " + std::to_string(kMaxClientMessageBytes) + " bytes";
        return std::nullopt;
    }
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        error = "not a JSON object";
        return std::nullopt;
    }
    const auto type = j.find("t");
    if (type == j.end() || !type->is_string()) {
        error = "no message type 't'";
        return std::nullopt;
    }
    ClientMessage message;
    if (const auto seq = j.find("seq"); seq != j.end()) {
        if (!seq->is_number_unsigned() || seq->get<std::uint64_t>() > 0xffffffffu) {
            error = "'seq' must be a positive integer";
            return std::nullopt;
        }
        message.seq = seq->get<std::uint32_t>();
    }
    std::optional<ClientBody> body = parseBody(type->get_ref<const std::string&>(), j, error);
    if (!body) return std::nullopt;
    message.body = std::move(*body);
    return message;
}

int keyFromBrowserCode(std::string_view code) {
    // Letters and digits by rule: GLFW's codes for them are their ASCII characters.
    if (code.size() == 4 && code.substr(0, 3) == "Key" && code[3] >= 'A' && code[3] <= 'Z') return code[3];
    if (code.size() == 6 && code.substr(0, 5) == "Digit" && code[5] >= '0' && code[5] <= '9') return code[5];
    static constexpr std::pair<std::string_view, int> kNamed[] = {
        {"Space", GLFW_KEY_SPACE},         {"ShiftLeft", GLFW_KEY_LEFT_SHIFT}, {"ShiftRight", GLFW_KEY_RIGHT_SHIFT},
        {"ArrowUp", GLFW_KEY_UP},          {"ArrowDown", GLFW_KEY_DOWN},       {"ArrowLeft", GLFW_KEY_LEFT},
        {"ArrowRight", GLFW_KEY_RIGHT},    {"Comma", GLFW_KEY_COMMA},          {"Period", GLFW_KEY_PERIOD},
        {"Escape", GLFW_KEY_ESCAPE},       {"Tab", GLFW_KEY_TAB},              {"Enter", GLFW_KEY_ENTER},
        {"ControlLeft", GLFW_KEY_LEFT_CONTROL}, {"ControlRight", GLFW_KEY_RIGHT_CONTROL},
        {"F12", GLFW_KEY_F12},
    };
    for (const auto& [name, key] : kNamed)
        if (name == code) return key;
    return -1;
}

}  // namespace penumbra::serve
