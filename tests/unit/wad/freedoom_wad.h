// Freedoom's WADs as Debian's freedoom package installs them, for the tests that read real
// levels: skipped where the package is missing, a failure on CI (which installs it).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace penumbra::test {

inline const char* kDoomDir = "/usr/share/games/doom/";

// The file's bytes, or nothing when it cannot be read.
inline std::string readWad(const std::string& name) {
    std::ifstream in(std::filesystem::path(kDoomDir) / name, std::ios::binary);
    if (!in) return {};
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The level's meshes: the world's, then those of the instances that carry its moving floors and
// ceilings (placed where the map has them: their transforms are the identity at load).
inline std::vector<Mesh> worldAndMovingMeshes(const Scene& scene) {
    std::vector<Mesh> out = scene.meshes;
    for (const Instance& i : scene.instances)
        for (const Mesh& m : scene.prototypes[i.prototype].meshes) out.push_back(m);
    return out;
}

}  // namespace penumbra::test

#define REQUIRE_WAD(bytes, name)                                                   \
    std::string bytes = ::penumbra::test::readWad(name);                           \
    if (bytes.empty()) {                                                           \
        if (std::getenv("CI")) FAIL() << name << " is missing (install freedoom)"; \
        GTEST_SKIP() << name << " is not installed (apt install freedoom)";        \
    }
