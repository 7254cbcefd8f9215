#include "interact/navigation.h"

#include <algorithm>
#include <cmath>

#include "scene/objects.h"

namespace penumbra::viewer {

float cameraSpeedFor(const Scene& scene) {
    const Aabb bounds = scene.bounds();
    const float sceneSize = bounds.empty() ? 1.0f : length(bounds.extent());
    return std::max(0.1f, 0.1f * sceneSize);
}

Navigation::Navigation(const Scene& scene, bool fly)
    : controller_(scene.camera, cameraSpeedFor(scene), scene.walkMap), phantom_(scene) {
    if (fly) controller_.setWalking(false);
    if (scene.tileGrid && !fly) grid_ = std::make_unique<GridWalker>(*scene.tileGrid, scene.camera);
    if (scene.doomLevel) {
        doom_ = std::make_unique<DoomPlay>(*scene.doomLevel);
        // Walking meets the heights the level holds (as loaded, at the start).
        controller_.setSectorHeights(doom_->level().walkMap().sectors);
    }
}

void Navigation::update(const CameraInput& input, float seconds) {
    if (grid_) {
        grid_->update(input, seconds);
        return;
    }
    std::optional<walk::WalkState> before;
    if (controller_.walking()) before = controller_.player();
    controller_.update(input, seconds);
    if (doom_) doom_->update(controller_, before, seconds);
}

std::string Navigation::handlePresses(const InputState& input, const Scene& scene) {
    std::string message;
    if (input.resetCamera) {
        controller_.reset();
        if (grid_) grid_ = std::make_unique<GridWalker>(*scene.tileGrid, scene.camera);  // the start tile
    }
    if (input.walkToggled) message = toggleWalking();
    if (input.gridToggled) message = toggleGrid(scene);
    if (input.scroll != 0) controller_.scaleSpeed(std::pow(1.25f, input.scroll));
    if (input.use && doom_ && walking())
        if (std::string said = doom_->use(controller_); !said.empty()) message = said;
    if (doom_)
        if (std::string said = doom_->takeMessage(); !said.empty()) message = said;
    return message;
}

std::string Navigation::toggleWalking() {
    if (controller_.walking()) {
        controller_.setWalking(false);
        return "free flight (F walks again)";
    }
    if (!controller_.canWalk()) return "only Doom levels can be walked; this scene is flown";
    if (controller_.setWalking(true)) return "walking (F flies)";
    return "cannot walk here: the player does not fit (inside a wall, outside the map or too low a room)";
}

// G: grid movement on a tile-map level, or free flight from where the grid walker stands.
std::string Navigation::toggleGrid(const Scene& scene) {
    if (grid_) {
        controller_ = CameraController(grid_->camera(), cameraSpeedFor(scene), scene.walkMap);
        if (doom_) controller_.setSectorHeights(doom_->level().walkMap().sectors);
        controller_.setWalking(false);
        grid_.reset();
        return "free flight (G: grid movement)";
    }
    if (!scene.tileGrid) return "grid movement needs a tile-map level (the dungeon)";
    grid_ = std::make_unique<GridWalker>(*scene.tileGrid, controller_.camera());
    return "grid movement (G: free flight)";
}

void prepareSceneSettings(Scene& scene, ViewSettings& settings) {
    settings.torch = scene.torch.enabled && scene.torch.intensity > 0;
    if (!settings.torch) {
        scene.torch.enabled = true;
        if (!(scene.torch.intensity > 0)) scene.torch.intensity = Torch{}.intensity;
        attachTorch(scene);
    }
    settings.torchColor = scene.torch.color;
    settings.torchIntensity = scene.torch.intensity;
    settings.torchRange = scene.torch.range;
    settings.rouletteStart = scene.viewerRouletteStart.value_or(ViewSettings{}.rouletteStart);
}

bool moveSelectedInstance(Scene& scene, std::uint32_t instance, const ObjectInput& in, const Camera& camera,
                          float speed, float seconds) {
    if (instance >= scene.instances.size() || !in.any() || !(seconds > 0)) return false;
    Vec3 forward = camera.lookAt - camera.position;
    forward.y = 0;
    forward = length(forward) > 0 ? normalize(forward) : Vec3{0, 0, -1};
    const Vec3 right{-forward.z, 0, forward.x};
    const Vec3 offset = (forward * in.forward + right * in.right + Vec3{0, in.up, 0}) * (speed * seconds);
    moveInstance(scene, instance, offset, in.turn * 90.0f * seconds);  // a quarter turn per second
    return true;
}

}  // namespace penumbra::viewer
