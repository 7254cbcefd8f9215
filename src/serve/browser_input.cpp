#include "serve/browser_input.h"

namespace penumbra::serve {

viewer::InputState BrowserInput::merged() const {
    viewer::InputState m;
    for (const auto& [client, in] : clients_) {
        for (std::size_t k = 0; k < m.held.size(); ++k) m.held[k] = m.held[k] || in.held[k];
        m.lookX += in.lookX;
        m.lookY += in.lookY;
        m.scroll += in.scroll;
        m.pauseToggled = m.pauseToggled != in.pauseToggled;  // two browsers pressing P cancel out
        m.resetCamera |= in.resetCamera;
        m.walkToggled = m.walkToggled != in.walkToggled;
        m.gridToggled = m.gridToggled != in.gridToggled;
        m.nextInstance |= in.nextInstance;
    }
    return m;
}

void BrowserInput::endFrame() {
    for (auto& [client, in] : clients_) viewer::endInputFrame(in);
}

}  // namespace penumbra::serve
