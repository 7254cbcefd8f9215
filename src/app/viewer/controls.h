// What the keys and the mouse do, in one place. Real keys (GLFW callbacks) and a script's
// events (input_script.h) both arrive here, so there is one copy of the controls. No GLFW calls:
// keys are GLFW's key codes, so this compiles and tests without a window.
#pragma once

#include <array>

#include "app/viewer/camera_controller.h"

namespace penumbra::viewer {

struct InputState {
    std::array<bool, 349> held{};  // GLFW_KEY_LAST + 1 key codes
    float lookX = 0, lookY = 0;    // pointer motion to look with since the last frame, pixels
    float scroll = 0;
    // Presses not yet handled by the frame loop.
    bool pauseToggled = false, resetCamera = false, screenshot = false;
    bool walkToggled = false, panelToggled = false, escape = false;
};

// A key went down (pressed) or up. Unknown or out-of-range codes are ignored.
void applyKey(InputState& input, int key, bool pressed);
// Pointer motion that looks around (captured pointer, right-button drag, a script's mouse line).
void applyLook(InputState& input, float dx, float dy);

// The movement the held keys ask for, plus the look motion gathered since the last frame.
CameraInput cameraInputFrom(const InputState& input);
// Forgets the one-frame parts (look motion, scroll, presses) once the frame used them.
void endInputFrame(InputState& input);

}  // namespace penumbra::viewer
