// The browsers' input merged into one set of controls: each browser has its own InputState (so
// one that goes away releases its keys), and a frame sees a key held while any browser holds it,
// the sum of their pointer motion and every browser's presses.
#pragma once

#include <cstdint>
#include <map>

#include "interact/controls.h"

namespace penumbra::serve {

class BrowserInput {
public:
    viewer::InputState& of(std::uint64_t client) { return clients_[client]; }
    void remove(std::uint64_t client) { clients_.erase(client); }
    // This frame's input of all browsers together.
    viewer::InputState merged() const;
    // Forgets every browser's one-frame parts once the frame used them.
    void endFrame();

private:
    std::map<std::uint64_t, viewer::InputState> clients_;
};

}  // namespace penumbra::serve
