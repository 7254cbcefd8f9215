// penumbra::Error carries a message meant for the user. Only main() catches it (exceptions
// inside, exit codes at the edge); the CLI prints "penumbra: error: <message>" and exits 1.
#pragma once

#include <stdexcept>
#include <string>

namespace penumbra {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// A mistake in how the program was called (bad flag value): exit code 2.
class UsageError : public Error {
public:
    explicit UsageError(const std::string& message) : Error(message) {}
};

// A render stopped by SIGINT or SIGTERM after writing what it had: the message says what was
// kept and how to continue; main() prints it as an error and exits with exitCode (128 + signal).
class Interrupted : public Error {
public:
    Interrupted(const std::string& message, int exitCode) : Error(message), exitCode(exitCode) {}
    int exitCode;
};

// Cheap invariant checks that stay on in every build.
[[noreturn]] void checkFailed(const char* expr, const char* file, int line);
#define PN_CHECK(expr) ((expr) ? (void)0 : ::penumbra::checkFailed(#expr, __FILE__, __LINE__))

}  // namespace penumbra
