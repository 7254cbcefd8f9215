#include "interact/controls.h"

#include <GLFW/glfw3.h>

namespace penumbra::viewer {

static_assert(std::tuple_size_v<decltype(InputState::held)> == GLFW_KEY_LAST + 1);

void applyKey(InputState& in, int key, bool pressed) {
    if (key < 0 || key > GLFW_KEY_LAST) return;
    in.held[std::size_t(key)] = pressed;
    if (!pressed) return;
    switch (key) {
        case GLFW_KEY_P: in.pauseToggled = true; break;
        case GLFW_KEY_R: in.resetCamera = true; break;
        case GLFW_KEY_F: in.walkToggled = true; break;
        case GLFW_KEY_TAB: in.panelToggled = true; break;
        case GLFW_KEY_F12: in.screenshot = true; break;
        case GLFW_KEY_ESCAPE: in.escape = true; break;
        case GLFW_KEY_N: in.nextInstance = true; break;
        case GLFW_KEY_G: in.gridToggled = true; break;
        // Space also moves up, in free flight; walking, it is Doom's use key (Enter is the other).
        case GLFW_KEY_SPACE:
        case GLFW_KEY_ENTER: in.use = true; break;
        case GLFW_KEY_V: in.previewToggled = true; break;
        case GLFW_KEY_M: in.addModel = true; break;
        case GLFW_KEY_H: in.phantomToggled = true; break;
        default: break;
    }
}

void applyLook(InputState& in, float dx, float dy) {
    in.lookX += dx;
    in.lookY += dy;
}

CameraInput cameraInputFrom(const InputState& in) {
    auto key = [&](int k) { return in.held[std::size_t(k)] ? 1.0f : 0.0f; };
    auto either = [&](int a, int b) { return key(a) + key(b) > 0 ? 1.0f : 0.0f; };
    CameraInput move;
    // WASD, or the arrows as in Doom (up/down move, left/right turn).
    move.forward = either(GLFW_KEY_W, GLFW_KEY_UP) - either(GLFW_KEY_S, GLFW_KEY_DOWN);
    move.right = key(GLFW_KEY_D) - key(GLFW_KEY_A);
    move.up = key(GLFW_KEY_SPACE) - key(GLFW_KEY_C);
    move.turn = either(GLFW_KEY_Q, GLFW_KEY_LEFT) - either(GLFW_KEY_E, GLFW_KEY_RIGHT);
    move.fast = either(GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT) > 0;
    move.lookX = in.lookX;
    move.lookY = in.lookY;
    return move;
}

ObjectInput objectInputFrom(const InputState& in) {
    auto key = [&](int k) { return in.held[std::size_t(k)] ? 1.0f : 0.0f; };
    ObjectInput o;
    o.forward = key(GLFW_KEY_I) - key(GLFW_KEY_K);
    o.right = key(GLFW_KEY_L) - key(GLFW_KEY_J);
    o.up = key(GLFW_KEY_O) - key(GLFW_KEY_U);
    o.turn = key(GLFW_KEY_COMMA) - key(GLFW_KEY_PERIOD);
    return o;
}

void endInputFrame(InputState& in) {
    in.lookX = in.lookY = in.scroll = 0;
    in.pauseToggled = in.resetCamera = in.screenshot = false;
    in.walkToggled = in.panelToggled = in.escape = false;
    in.nextInstance = in.gridToggled = in.use = false;
    in.previewToggled = in.addModel = in.phantomToggled = false;
}

}  // namespace penumbra::viewer
