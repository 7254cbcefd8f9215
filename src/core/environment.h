// Numeric settings read from environment variables (measurement knobs and test limits), parsed
// one way everywhere: a malformed value is a usage error naming the variable, never ignored.
#pragma once

#include <cstdint>

namespace penumbra {

// The whole number in environment variable `name`, or `fallback` when it is unset or empty.
// Throws UsageError, naming the variable and the range, for anything but a whole number in
// [low, high].
std::uint64_t environmentSetting(const char* name, std::uint64_t fallback, std::uint64_t low, std::uint64_t high);

}  // namespace penumbra
