// Random rays through a scene's box, shared by the GPU walk comparisons.
#pragma once

#include <random>
#include <vector>

#include "core/aabb.h"
#include "shared/types.h"

namespace penumbra::test {

// Rays from anywhere in (and around) the scene's box toward random points in it; every seventh is
// axis-parallel and every fifth a shadow ray with a short tMax.
inline std::vector<shader::RayDesc> boxRays(const Aabb& box, std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const Vec3 e = box.extent();
    auto point = [&](float margin) {
        return Vec3{box.lo.x + e.x * (u(rng) * (1 + 2 * margin) - margin),
                    box.lo.y + e.y * (u(rng) * (1 + 2 * margin) - margin),
                    box.lo.z + e.z * (u(rng) * (1 + 2 * margin) - margin)};
    };
    std::vector<shader::RayDesc> rays;
    for (std::size_t i = 0; i < count; ++i) {
        shader::RayDesc r{};
        r.origin = point(0.1f);
        Vec3 d = point(0.0f) - r.origin;
        if (i % 7 == 0) d = Vec3{0, 0, 0}, d[int(i / 7 % 3)] = (i % 2 ? 1.0f : -1.0f);
        r.direction = length(d) > 0 ? normalize(d) : Vec3{0, 1, 0};
        r.tMax = i % 5 == 0 ? 0.3f * length(e) * u(rng) : 1e30f;
        rays.push_back(r);
    }
    return rays;
}

}  // namespace penumbra::test
