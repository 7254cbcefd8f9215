// Diagnostics on stderr. Warnings start "penumbra: warning:" so scripts can grep for them.
#pragma once

#include <string_view>

namespace penumbra {

void logWarning(std::string_view message);
void setVerbose(bool verbose);
bool isVerbose();

}  // namespace penumbra
