// The dungeon's phantom switched off and on (docs/VIEWER.md, "The phantom"), the WebGPU renderer's
// phantom toggle. Off, it is not drawn and does not move: its patrol is taken off the clock and
// its instance is parked, shrunk to a thousandth, 10 m under the scene, where no ray from inside
// the level reaches (the renderer has no per-instance visibility; parking changes only the top
// level, like any move, so the temporal pass sees the phantom leave as it sees a door open: the
// wall it uncovers has another surface id and takes no history). On, its patrol is back on the
// clock and it stands where the patrol is at that moment. Plain data: no window, no GPU.
#pragma once

#include <cstdint>
#include <optional>

#include "core/transform.h"
#include "scene/scene.h"

namespace penumbra {

// The name of the prototype the switch looks for (the dungeon preset's phantom).
inline constexpr const char* kPhantomPrototype = "phantom";

class PhantomSwitch {
public:
    PhantomSwitch() = default;  // no phantom
    // Finds the first instance of the prototype named kPhantomPrototype; the scene's phantom is
    // shown when the switch is made.
    explicit PhantomSwitch(const Scene& scene);

    bool present() const { return instance_.has_value(); }
    bool shown() const { return shown_; }
    // Shows or hides it at the scene's clock `seconds`; true when the scene's instances changed
    // (the renderer then takes the new transforms). Nothing happens without a phantom.
    bool set(Scene& scene, bool shown, double seconds);

private:
    std::optional<std::uint32_t> instance_;
    std::optional<InstanceAnimation> patrol_;  // taken off the clock while hidden
    Affine shownTransform_;                    // where it stood when hidden (for a phantom that does not move)
    bool shown_ = true;
};

// Where a hidden phantom is parked: under the middle of the scene's bounds, 10 m below them,
// shrunk a thousandfold (an invertible transform, as instances need).
Affine phantomParking(const Scene& scene);

}  // namespace penumbra
