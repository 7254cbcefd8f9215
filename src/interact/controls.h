// What the keys and the mouse do, in one place. Real keys (GLFW callbacks) and a script's
// events (input_script.h) both arrive here, so there is one copy of the controls. No GLFW calls:
// keys are GLFW's key codes, so this compiles and tests without a window.
#pragma once

#include <array>

#include "interact/camera_controller.h"

namespace penumbra::viewer {

struct InputState {
    std::array<bool, 349> held{};  // GLFW_KEY_LAST + 1 key codes
    float lookX = 0, lookY = 0;    // pointer motion to look with since the last frame, pixels
    float scroll = 0;
    // Presses not yet handled by the frame loop.
    bool pauseToggled = false, resetCamera = false, screenshot = false;
    bool walkToggled = false, panelToggled = false, escape = false;
    bool nextInstance = false, gridToggled = false;
    bool use = false;  // Doom's "use" (Space or Enter): opens doors and turns switches while walking
    bool previewToggled = false;  // V: the fast preview while moving (ViewSettings::preview)
    bool addModel = false;        // M: add the model named in the panel's Add model field
    bool phantomToggled = false;  // H: the dungeon's phantom off / on (scene/phantom.h)
};

// What the held keys ask of the selected instance: I/K forward/back, J/L left/right (along the
// camera's horizontal directions), O/U up/down, comma/period turn left/right. Each in [-1, 1].
struct ObjectInput {
    float forward = 0, right = 0, up = 0, turn = 0;
    bool any() const { return forward != 0 || right != 0 || up != 0 || turn != 0; }
};
ObjectInput objectInputFrom(const InputState& input);

// A key went down (pressed) or up. Unknown or out-of-range codes are ignored.
void applyKey(InputState& input, int key, bool pressed);
// Pointer motion that looks around (captured pointer, right-button drag, a script's mouse line).
void applyLook(InputState& input, float dx, float dy);

// The movement the held keys ask for, plus the look motion gathered since the last frame.
CameraInput cameraInputFrom(const InputState& input);
// Forgets the one-frame parts (look motion, scroll, presses) once the frame used them.
void endInputFrame(InputState& input);

}  // namespace penumbra::viewer
