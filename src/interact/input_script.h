// Scripted input for `penumbra view --script FILE`: timed key and mouse events, played into the
// same controls as real keys (controls.h). One event per line:
//     SECONDS key NAME down        SECONDS key NAME up        SECONDS mouse DX DY
// NAME is a GLFW key name without the GLFW_KEY_ prefix (W, A, SPACE, LEFT_SHIFT, F1, ...), any
// case; DX, DY are pointer pixels to look by; '#' starts a comment; blank lines are skipped.
// Times are seconds from the first frame and never decrease.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "interact/controls.h"

namespace penumbra::viewer {

struct ScriptEvent {
    enum class Kind { KeyDown, KeyUp, Mouse };
    double time = 0;  // seconds
    Kind kind = Kind::KeyDown;
    int key = -1;          // GLFW key code (KeyDown, KeyUp)
    float dx = 0, dy = 0;  // Mouse
};

constexpr std::size_t kMaxScriptEvents = 1'000'000;
constexpr double kMaxScriptSeconds = 1e6;

// Throws Error "NAME:LINE: what is wrong" on the first malformed line.
std::vector<ScriptEvent> parseInputScript(std::string_view text, const std::string& name);
// Reads and parses a file (Error when it cannot be read or is larger than 16 MiB); `option` is
// the flag that named it, for the message (--script, or render's --walk).
std::vector<ScriptEvent> loadInputScript(const std::string& path, const std::string& option = "--script");

// The GLFW key code of a key name (case-insensitive, without GLFW_KEY_), or -1.
int keyCodeFromName(std::string_view name);

// Plays a script frame by frame: each frame, the events due by the script's clock are applied,
// then the clock advances by the frame's time step.
class ScriptPlayer {
public:
    explicit ScriptPlayer(std::vector<ScriptEvent> events) : events_(std::move(events)) {}
    void playFrame(InputState& input, double frameSeconds);
    bool finished() const { return next_ >= events_.size(); }
    double clock() const { return clock_; }

private:
    std::vector<ScriptEvent> events_;
    std::size_t next_ = 0;
    double clock_ = 0;
};

}  // namespace penumbra::viewer
