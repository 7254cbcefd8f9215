#include "interact/input_script.h"

#include <GLFW/glfw3.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <utility>

#include "core/error.h"

namespace penumbra::viewer {
namespace {

constexpr std::streamoff kMaxScriptBytes = 16 << 20;

// clang-format off
#define PN_KEY(name) {#name, GLFW_KEY_##name}
constexpr std::pair<std::string_view, int> kKeyNames[] = {
    PN_KEY(SPACE), PN_KEY(APOSTROPHE), PN_KEY(COMMA), PN_KEY(MINUS), PN_KEY(PERIOD), PN_KEY(SLASH),
    PN_KEY(0), PN_KEY(1), PN_KEY(2), PN_KEY(3), PN_KEY(4), PN_KEY(5), PN_KEY(6), PN_KEY(7), PN_KEY(8), PN_KEY(9),
    PN_KEY(SEMICOLON), PN_KEY(EQUAL),
    PN_KEY(A), PN_KEY(B), PN_KEY(C), PN_KEY(D), PN_KEY(E), PN_KEY(F), PN_KEY(G), PN_KEY(H), PN_KEY(I),
    PN_KEY(J), PN_KEY(K), PN_KEY(L), PN_KEY(M), PN_KEY(N), PN_KEY(O), PN_KEY(P), PN_KEY(Q), PN_KEY(R),
    PN_KEY(S), PN_KEY(T), PN_KEY(U), PN_KEY(V), PN_KEY(W), PN_KEY(X), PN_KEY(Y), PN_KEY(Z),
    PN_KEY(LEFT_BRACKET), PN_KEY(BACKSLASH), PN_KEY(RIGHT_BRACKET), PN_KEY(GRAVE_ACCENT),
    PN_KEY(ESCAPE), PN_KEY(ENTER), PN_KEY(TAB), PN_KEY(BACKSPACE), PN_KEY(INSERT), PN_KEY(DELETE),
    PN_KEY(RIGHT), PN_KEY(LEFT), PN_KEY(DOWN), PN_KEY(UP), PN_KEY(PAGE_UP), PN_KEY(PAGE_DOWN),
    PN_KEY(HOME), PN_KEY(END),
    PN_KEY(F1), PN_KEY(F2), PN_KEY(F3), PN_KEY(F4), PN_KEY(F5), PN_KEY(F6), PN_KEY(F7), PN_KEY(F8),
    PN_KEY(F9), PN_KEY(F10), PN_KEY(F11), PN_KEY(F12),
    PN_KEY(LEFT_SHIFT), PN_KEY(LEFT_CONTROL), PN_KEY(LEFT_ALT), PN_KEY(RIGHT_SHIFT), PN_KEY(RIGHT_CONTROL),
    PN_KEY(RIGHT_ALT),
};
#undef PN_KEY
// clang-format on

bool sameIgnoringCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        char x = a[i], y = b[i];
        if (x >= 'a' && x <= 'z') x = char(x - 'a' + 'A');
        if (y >= 'a' && y <= 'z') y = char(y - 'a' + 'A');
        if (x != y) return false;
    }
    return true;
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size() && out.size() < 5) {  // 5 are enough to tell a line is too long
        while (i < line.size() && isSpace(line[i])) ++i;
        std::size_t start = i;
        while (i < line.size() && !isSpace(line[i])) ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

// A printable, bounded copy of a word for an error message.
std::string quoted(std::string_view word) {
    std::string s = "'";
    for (std::size_t i = 0; i < word.size() && i < 40; ++i) {
        const unsigned char c = static_cast<unsigned char>(word[i]);
        s += c >= 32 && c < 127 ? char(c) : '?';
    }
    return s + (word.size() > 40 ? "...'" : "'");
}

bool parseNumber(std::string_view word, double& value) {
    const char* end = word.data() + word.size();
    auto [ptr, ec] = std::from_chars(word.data(), end, value);
    return ec == std::errc() && ptr == end && std::isfinite(value);
}

// What is wrong with a line; parseInputScript adds where.
struct BadLine {
    std::string what;
};

// One event from a line's words (at least one); times must not go below the previous event's.
ScriptEvent parseEvent(const std::vector<std::string_view>& w, double previousTime) {
    ScriptEvent e;
    if (!parseNumber(w[0], e.time) || e.time < 0 || e.time > kMaxScriptSeconds)
        throw BadLine{"the time " + quoted(w[0]) + " is not a number of seconds from 0 to 1e6"};
    if (e.time < previousTime)
        throw BadLine{"the time " + quoted(w[0]) + " is earlier than the line before"};
    if (w.size() < 2) throw BadLine{"a time with no event"};
    const bool key = sameIgnoringCase(w[1], "key"), mouse = sameIgnoringCase(w[1], "mouse");
    if (!key && !mouse) throw BadLine{"unknown event " + quoted(w[1])};
    if (w.size() != 4) throw BadLine{std::string(key ? "a key" : "a mouse") + " line has exactly 4 words"};
    if (key) {
        e.key = keyCodeFromName(w[2]);
        if (e.key < 0)
            throw BadLine{"unknown key " + quoted(w[2]) + " (GLFW names: W, SPACE, LEFT_SHIFT, F1, ...)"};
        if (sameIgnoringCase(w[3], "down")) e.kind = ScriptEvent::Kind::KeyDown;
        else if (sameIgnoringCase(w[3], "up")) e.kind = ScriptEvent::Kind::KeyUp;
        else throw BadLine{"a key goes 'down' or 'up', not " + quoted(w[3])};
        return e;
    }
    double dx = 0, dy = 0;
    if (!parseNumber(w[2], dx) || !parseNumber(w[3], dy) || std::abs(dx) > 1e6 || std::abs(dy) > 1e6)
        throw BadLine{"the mouse motion " + quoted(w[2]) + " " + quoted(w[3]) + " is not two numbers of pixels"};
    e.kind = ScriptEvent::Kind::Mouse;
    e.dx = float(dx);
    e.dy = float(dy);
    return e;
}

}  // namespace

int keyCodeFromName(std::string_view name) {
    for (const auto& [n, code] : kKeyNames)
        if (sameIgnoringCase(n, name)) return code;
    return -1;
}

std::vector<ScriptEvent> parseInputScript(std::string_view text, const std::string& name) {
    std::vector<ScriptEvent> events;
    std::size_t lineNumber = 0;
    while (!text.empty()) {
        ++lineNumber;
        const std::size_t eol = text.find('\n');
        std::string_view line = text.substr(0, eol);
        text = eol == std::string_view::npos ? std::string_view() : text.substr(eol + 1);
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
            line = line.substr(0, hash);
        const std::vector<std::string_view> w = words(line);
        if (w.empty()) continue;
        try {
            if (events.size() >= kMaxScriptEvents) throw BadLine{"more than a million events"};
            events.push_back(parseEvent(w, events.empty() ? 0.0 : events.back().time));
        } catch (const BadLine& bad) {
            throw Error(name + ":" + std::to_string(lineNumber) + ": " + bad.what +
                             " (expected 'SECONDS key NAME down|up' or 'SECONDS mouse DX DY')");
        }
    }
    return events;
}

std::vector<ScriptEvent> loadInputScript(const std::string& path, const std::string& option) {
    std::error_code ec;
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        throw Error(option + ": cannot read " + path + ": it is not a regular file");
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) throw Error(option + ": cannot read " + path);
    const std::streamoff size = in.tellg();
    if (size < 0 || size > kMaxScriptBytes)
        throw Error(option + ": " + path + " is larger than 16 MiB");
    std::string text(std::size_t(size), '\0');
    in.seekg(0);
    if (!in.read(text.data(), size)) throw Error(option + ": cannot read " + path);
    return parseInputScript(text, path);
}

void ScriptPlayer::playFrame(InputState& input, double frameSeconds) {
    for (; next_ < events_.size() && events_[next_].time <= clock_; ++next_) {
        const ScriptEvent& e = events_[next_];
        if (e.kind == ScriptEvent::Kind::Mouse)
            applyLook(input, e.dx, e.dy);
        else
            applyKey(input, e.key, e.kind == ScriptEvent::Kind::KeyDown);
    }
    if (frameSeconds > 0) clock_ += frameSeconds;
}

}  // namespace penumbra::viewer
