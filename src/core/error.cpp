#include "core/error.h"

namespace penumbra {

void checkFailed(const char* expr, const char* file, int line) {
    throw Error(std::string("internal check failed: ") + expr + " at " + file + ":" +
                std::to_string(line) + " (this is a bug in penumbra; please report it)");
}

}  // namespace penumbra
