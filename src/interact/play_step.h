// One frame of play, the same for every front end (the window, the browser, `render --walk`):
// the camera moves by the input, then the world advances by the frame's time. This is the one
// place where the world moves by itself each frame: instance animations, and a Doom level's
// specials (doors, lifts, light changes, the exit: interact/doom_play.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "interact/controls.h"
#include "interact/navigation.h"
#include "scene/scene.h"

namespace penumbra::viewer {

// What the frame changed besides the camera, so the caller updates its renderer.
struct WorldChange {
    bool instancesMoved = false;   // top level only: InteractiveRenderer::setInstanceTransforms
    bool geometryChanged = false;  // meshes changed: a bottom level must be rebuilt or refitted
    // Materials whose emission changed (a Doom sector's light): InteractiveRenderer::setUnsampledEmission.
    std::vector<std::uint32_t> lightsChanged;
    // Materials whose textures changed (a Doom switch turned, a key was picked up): the front end
    // sends them up in place (InteractiveRenderer::setMaterial, Renderer::setMaterial).
    std::vector<std::uint32_t> materialsChanged;
    // The frame the level ended: "E1M1 complete in 42.3 s", for the front end to print and show.
    std::optional<std::string> levelCompleted;
};

// Moves the camera by `input` over `step` seconds, advances `clock` (seconds played) by `step`
// and moves the world to the new clock.
WorldChange playStep(Scene& scene, Navigation& nav, const InputState& input, double& clock, float step);

}  // namespace penumbra::viewer
