// Shared helpers for the importer tests: test-data paths and Debian asset lookup.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/error.h"

namespace penumbra::test {

inline std::filesystem::path dataDir() {
    const char* env = std::getenv("PENUMBRA_TEST_DATA");
    return env ? std::filesystem::path(env) : std::filesystem::path("tests/data");
}

inline std::string readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The message of the Error that fn throws, or "<no error>".
std::string errorOf(auto&& fn) {
    try {
        fn();
    } catch (const Error& e) {
        return e.what();
    }
    return "<no error>";
}

// Debian test assets are optional locally but required in CI.
#define PENUMBRA_REQUIRE_ASSET(path)                                                  \
    do {                                                                              \
        if (!std::filesystem::exists(path)) {                                         \
            if (std::getenv("CI")) FAIL() << "missing test asset " << (path);         \
            GTEST_SKIP() << "asset not installed: " << (path);                        \
        }                                                                             \
    } while (0)

}  // namespace penumbra::test
