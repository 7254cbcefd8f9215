#include "interact/play_step.h"

#include "scene/animation.h"

namespace penumbra::viewer {

WorldChange playStep(Scene& scene, Navigation& nav, const InputState& input, double& clock, float step) {
    nav.update(cameraInputFrom(input), step);  // a Doom level's tics run here too
    clock += step;
    WorldChange change;
    change.instancesMoved = nav.moveSectors(scene);  // doors and lifts
    change.lightsChanged = nav.applyLights(scene);
    change.materialsChanged = nav.applyLooks(scene);  // switches that turned, keys picked up
    change.levelCompleted = nav.takeLevelCompletion();
    // Animated instances (glTF animations, scene-file motions) follow the clock.
    if (animatesGeometry(scene)) {
        applyInstanceAnimations(scene, clock);
        change.instancesMoved = true;
    }
    return change;
}

}  // namespace penumbra::viewer
