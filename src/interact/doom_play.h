// Playing a Doom level while walking it: the level's specials (scene/doom/level.h) run on a tic
// clock of 35 a second fed by the frame's (simulated) seconds, so a --fixed-dt run plays the same
// every time; the player's moves trigger walk-over lines and pick up keys, "use" opens doors and
// turns switches, the walking collides with the heights as they move, and the instances that
// carry the moving floors and ceilings follow them. Shared by the window and the browser server
// through Navigation. No window, no GPU.
#pragma once

#include <optional>
#include <string>

#include "interact/camera_controller.h"
#include "scene/doom/level.h"
#include "scene/doom/level_looks.h"
#include "scene/scene.h"

namespace penumbra::viewer {

class DoomPlay {
public:
    explicit DoomPlay(const doom::Level& level) : level_(level) {}

    // After the controller moved over `seconds` from `before` (the player then; none when it was
    // not walking): lines crossed and keys touched, then the tics that are due.
    void update(CameraController& controller, const std::optional<walk::WalkState>& before, float seconds);
    // The player uses what it faces (walking only). Returns the line to show, if any.
    std::string use(const CameraController& controller);
    // Moves the instances of the moving planes to their heights now; true when one moved.
    bool moveSectors(Scene& scene) const;
    // Sets the fill light of sectors whose light changed (light specials) in their materials;
    // returns the materials changed (for InteractiveRenderer::setUnsampledEmission).
    std::vector<std::uint32_t> applyLights(Scene& scene);
    // Turns the switches' textures and hides the keys picked up (scene/doom/level_looks.h) in their
    // materials; returns the materials changed (for InteractiveRenderer::setMaterial).
    std::vector<std::uint32_t> applyLooks(Scene& scene) const { return doom::applyLooks(level_, scene.materials); }

    const doom::Level& level() const { return level_; }
    // Once the level has ended: "E1M1 complete in 42.3 s" (level time: tics / 35).
    std::optional<std::string> completion() const;
    // The same, once: the first call after the level ended (the front ends print and show it).
    std::optional<std::string> takeCompletion();
    // What the level said since last asked (a locked door, a key picked up), else "".
    std::string takeMessage() { return level_.takeMessage(); }

private:
    doom::Level level_;
    double clock_ = 0;  // seconds played; the level runs floor(clock_ * 35) tics
    bool completionTaken_ = false;
    std::uint32_t lightChangesApplied_ = 0;
};

// The player's position for the level (map units), when walking.
std::optional<doom::PlayerPosition> playerPosition(const CameraController& controller);

}  // namespace penumbra::viewer
