// Durations as people type them on a command line: "90" or "90s", "2m", "1h30m", "1.5h".
#pragma once

#include <string>

namespace penumbra {

// Seconds in `text`: a plain number is seconds; otherwise one or more number+unit parts
// (h, m, s; each unit at most once, largest first). Throws UsageError naming `flag` on anything
// else, on zero or negative totals, and on more than a year.
double parseDuration(const std::string& text, const std::string& flag);

}  // namespace penumbra
