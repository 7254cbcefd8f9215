// Diagnostics on stderr. Warnings start "penumbra: warning:" so scripts can grep for them.
#pragma once

#include <string_view>

namespace penumbra {

void logWarning(std::string_view message);
void logInfo(std::string_view message);  // only shown when verbose
void setVerbose(bool verbose);
bool isVerbose();

}  // namespace penumbra
