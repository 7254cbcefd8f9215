#include "scene/phantom.h"

#include <algorithm>

#include "scene/node_animation.h"

namespace penumbra {

PhantomSwitch::PhantomSwitch(const Scene& scene) {
    for (std::uint32_t i = 0; i < scene.instances.size(); ++i) {
        const std::uint32_t p = scene.instances[i].prototype;
        if (p < scene.prototypes.size() && scene.prototypes[p].name == kPhantomPrototype) {
            instance_ = i;
            return;
        }
    }
}

Affine phantomParking(const Scene& scene) {
    // The bounds without the phantom would be nicer, but a parked phantom is a point-sized speck
    // and the margin of 10 m keeps it clear of everything either way.
    const Aabb b = scene.bounds();
    const Vec3 below{0.5f * (b.lo.x + b.hi.x), b.lo.y - 10.0f, 0.5f * (b.lo.z + b.hi.z)};
    return Affine::translation(below) * Affine::scaling(Vec3{1e-3f});
}

bool PhantomSwitch::set(Scene& scene, bool shown, double seconds) {
    if (!instance_ || shown == shown_ || *instance_ >= scene.instances.size()) return false;
    const std::uint32_t index = *instance_;
    Instance& phantom = scene.instances[index];
    if (!shown) {
        shownTransform_ = phantom.transform;
        auto& animations = scene.instanceAnimations;
        const auto it = std::find_if(animations.begin(), animations.end(),
                                     [&](const InstanceAnimation& a) { return a.instance == index; });
        if (it != animations.end()) {
            patrol_ = std::move(*it);
            animations.erase(it);
        }
        phantom.transform = phantomParking(scene);
    } else if (patrol_) {
        phantom.transform = editedTransform(patrol_->userEdit, chainTransform(patrol_->chain, seconds));
        scene.instanceAnimations.push_back(std::move(*patrol_));
        patrol_.reset();
    } else {
        phantom.transform = shownTransform_;
    }
    shown_ = shown;
    return true;
}

}  // namespace penumbra
