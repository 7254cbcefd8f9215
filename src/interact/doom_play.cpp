#include "interact/doom_play.h"

#include <cmath>
#include <cstdio>

#include "scene/io/wad/sector_light.h"
#include "scene/io/wad/units.h"

namespace penumbra::viewer {
namespace {

// A frame never runs more than this many tics (a stalled frame does not replay seconds of level).
constexpr int kMaxTicsPerUpdate = 2 * doom::kTicsPerSecond;

}  // namespace

std::optional<doom::PlayerPosition> playerPosition(const CameraController& controller) {
    if (!controller.walking()) return std::nullopt;
    const walk::WalkState& p = controller.player();
    return doom::PlayerPosition{p.x, p.y, p.z};
}

void DoomPlay::update(CameraController& controller, const std::optional<walk::WalkState>& before, float seconds) {
    const std::optional<doom::PlayerPosition> player = playerPosition(controller);
    if (player && before) {
        level_.crossed(before->x, before->y, player->x, player->y);
        level_.touchThings(*player);
    }
    if (!(seconds > 0) || !std::isfinite(seconds)) return;
    clock_ += double(seconds);
    const double due = std::floor(clock_ * doom::kTicsPerSecond + 1e-6);
    int ran = 0;
    while (level_.tics() < due && ran < kMaxTicsPerUpdate) {
        level_.tic(player);
        ++ran;
    }
    if (level_.tics() < due) clock_ = double(level_.tics()) / doom::kTicsPerSecond;  // dropped, not owed
    if (ran > 0) controller.setSectorHeights(level_.walkMap().sectors);
}

std::string DoomPlay::use(const CameraController& controller) {
    const std::optional<doom::PlayerPosition> player = playerPosition(controller);
    if (!player) return "";
    const Camera c = controller.camera();
    const Vec3 forward = wad::sceneToMap(c.lookAt - c.position);  // linear: a direction
    const double angle = std::atan2(double(forward.y), double(forward.x));
    level_.use(player->x, player->y, angle, player);
    return level_.takeMessage();
}

bool DoomPlay::moveSectors(Scene& scene) const { return doom::placePlaneInstances(level_, scene.instances); }

std::vector<std::uint32_t> DoomPlay::applyLights(Scene& scene) {
    std::vector<std::uint32_t> changed;
    if (level_.lightChanges() == lightChangesApplied_) return changed;
    lightChangesApplied_ = level_.lightChanges();
    for (const doom::LightMaterial& l : level_.lightMaterials()) {
        if (l.material >= scene.materials.size()) continue;
        const Vec3 emission(wad::sectorRadiance(level_.lightLevel(l.sector)) * l.scale);
        Material& m = scene.materials[l.material];
        if (m.emission == emission) continue;
        m.emission = emission;
        changed.push_back(l.material);
    }
    return changed;
}

std::optional<std::string> DoomPlay::completion() const {
    if (!level_.exited()) return std::nullopt;
    char line[96];
    std::snprintf(line, sizeof line, "%s complete in %.1f s", level_.mapName().c_str(),
                  double(level_.exitTic()) / doom::kTicsPerSecond);
    return std::string(line);
}

std::optional<std::string> DoomPlay::takeCompletion() {
    if (completionTaken_) return std::nullopt;
    std::optional<std::string> line = completion();
    completionTaken_ = line.has_value();
    return line;
}

}  // namespace penumbra::viewer
