#include "core/duration.h"

#include <cmath>
#include <cstdlib>

#include "core/error.h"

namespace penumbra {

double parseDuration(const std::string& text, const std::string& flag) {
    auto bad = [&]() {
        return UsageError(flag + " expects a duration like 90, 90s, 2m or 1h30m (got '" + text + "')");
    };
    if (text.empty()) throw bad();
    const char* p = text.c_str();
    double total = 0;
    int lastUnit = 4;  // h = 3, m = 2, s = 1: each part's unit must be smaller than the one before
    bool plainNumber = false;
    while (*p) {
        if (plainNumber) throw bad();  // "90 5": a unitless number must stand alone
        char* end = nullptr;
        if (!(*p >= '0' && *p <= '9') && *p != '.') throw bad();
        const double value = std::strtod(p, &end);
        if (end == p || !std::isfinite(value)) throw bad();
        p = end;
        int unit = 0;
        double scale = 1;
        switch (*p) {
            case 'h': unit = 3; scale = 3600; break;
            case 'm': unit = 2; scale = 60; break;
            case 's': unit = 1; scale = 1; break;
            case '\0': plainNumber = true; break;
            default: throw bad();
        }
        if (!plainNumber) {
            if (unit >= lastUnit) throw bad();
            lastUnit = unit;
            ++p;
        } else if (lastUnit != 4) {
            throw bad();  // "1m30": the seconds need their unit
        }
        total += value * scale;
    }
    constexpr double kYear = 365.0 * 24 * 3600;
    if (!(total > 0) || total > kYear) throw UsageError(flag + " must be more than 0 and at most a year (got '" + text + "')");
    return total;
}

}  // namespace penumbra
