#include "core/environment.h"

#include <cerrno>
#include <cstdlib>
#include <string>

#include "core/error.h"

namespace penumbra {

std::uint64_t environmentSetting(const char* name, std::uint64_t fallback, std::uint64_t low, std::uint64_t high) {
    const char* text = std::getenv(name);
    if (!text || !*text) return fallback;
    char* end = nullptr;
    errno = 0;
    const unsigned long long value = std::strtoull(text, &end, 10);
    const bool digitsOnly = *end == '\0' && text[0] >= '0' && text[0] <= '9';
    if (!digitsOnly || errno == ERANGE || value < low || value > high)
        throw UsageError(std::string(name) + " must be a whole number from " + std::to_string(low) + " to " +
                         std::to_string(high) + " (got '" + text + "')");
    return value;
}

}  // namespace penumbra
