// How the viewer's camera moves, for every front end (the window, the browser): free flight or
// walking (CameraController), or grid steps on a tile-map level (GridWalker); the keys that switch
// between them; and the keys that move the selected instance. No window, no GPU, no network.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "interact/camera_controller.h"
#include "interact/controls.h"
#include "interact/doom_play.h"
#include "interact/grid_walk.h"
#include "render/view_settings.h"
#include "scene/phantom.h"
#include "scene/scene.h"

namespace penumbra::viewer {

// Flight speed for a scene: a tenth of its size per second.
float cameraSpeedFor(const Scene& scene);

class Navigation {
public:
    // Doom levels start walking (unless fly), tile maps in grid movement, others in flight.
    Navigation(const Scene& scene, bool fly);

    Camera camera() const { return grid_ ? grid_->camera() : controller_.camera(); }
    // Moves by the held keys and the look motion over `seconds`; a Doom level plays on (its
    // specials, doors and lifts: doom_play.h).
    void update(const CameraInput& input, float seconds);
    // The frame's presses: R resets, F walks or flies, G grid movement, the wheel flight speed,
    // Space or Enter uses (walking a Doom level).
    // Returns the line to show the user ("" when nothing needs saying).
    std::string handlePresses(const InputState& input, const Scene& scene);

    bool walking() const { return !grid_ && controller_.walking(); }
    bool canWalk() const { return controller_.canWalk(); }
    float speed() const { return controller_.speed(); }
    CameraController& controller() { return controller_; }
    const CameraController& controller() const { return controller_; }
    // Doom levels: the level being played (none for other scenes).
    DoomPlay* doom() { return doom_.get(); }
    const DoomPlay* doom() const { return doom_.get(); }
    // Moves the instances of a Doom level's moving floors and ceilings to where they are now; true
    // when one moved (the renderer then takes the new transforms).
    bool moveSectors(Scene& scene) const { return doom_ && doom_->moveSectors(scene); }
    // A Doom level's sector lights as they are now, in their materials; the materials changed.
    std::vector<std::uint32_t> applyLights(Scene& scene) { return doom_ ? doom_->applyLights(scene) : std::vector<std::uint32_t>{}; }
    // A Doom level's switches and keys as they are now, in their materials; the materials changed.
    std::vector<std::uint32_t> applyLooks(Scene& scene) { return doom_ ? doom_->applyLooks(scene) : std::vector<std::uint32_t>{}; }
    // The dungeon's phantom (scene/phantom.h): whether the scene has one, and switching it off and
    // on at the clock's `seconds`; true when its instance changed (the renderer takes the new
    // transforms, and the temporal pass drops the history it uncovers or covers).
    bool hasPhantom() const { return phantom_.present(); }
    bool phantomShown() const { return phantom_.shown(); }
    bool showPhantom(Scene& scene, bool shown, double seconds) { return phantom_.set(scene, shown, seconds); }
    // "E1M1 complete in T s", once, on the first call after a Doom level ended.
    std::optional<std::string> takeLevelCompletion() { return doom_ ? doom_->takeCompletion() : std::nullopt; }

private:
    std::string toggleWalking();
    std::string toggleGrid(const Scene& scene);

    CameraController controller_;
    // Not std::optional: GCC 12 warns of it being maybe uninitialized.
    std::unique_ptr<GridWalker> grid_;
    std::unique_ptr<DoomPlay> doom_;
    PhantomSwitch phantom_;
};

// What the scene decides of the view. The torch: attached as the scene's last punctual light so
// the renderer can move it; when the scene did not ask for one it starts switched off. Russian
// roulette: from the bounce the scene asks for, if any.
void prepareSceneSettings(Scene& scene, ViewSettings& settings);

// The panel's line after an instance is selected (docs/VIEWER.md, Controls).
inline constexpr const char* kInstanceControls =
    ": drag it (Shift+drag turns it), or I/K J/L O/U move it, comma/period turn it";

// Moves the selected instance as the held keys ask, along the camera's horizontal directions;
// true when it moved.
bool moveSelectedInstance(Scene& scene, std::uint32_t instance, const ObjectInput& in, const Camera& camera,
                          float speed, float seconds);

}  // namespace penumbra::viewer
