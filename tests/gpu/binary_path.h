// The penumbra executable the CLI tests run: PENUMBRA_BINARY when set (a packed copy on another
// machine, see scripts/gpu-tests.sh), else the one this build made.
#pragma once

#include <cstdlib>
#include <string>

namespace penumbra::test {

inline std::string penumbraBinary() {
    const char* env = std::getenv("PENUMBRA_BINARY");
    return env && *env ? env : PENUMBRA_BINARY_PATH;
}

}  // namespace penumbra::test
