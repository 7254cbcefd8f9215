#include "scene/doom/light_specials.h"

#include <algorithm>
#include <type_traits>

namespace penumbra::doom {
namespace {

StrobeFlash strobe(int sector, int light, int dimmest, int dark, bool inSync, LightRandom& random) {
    StrobeFlash s;
    s.sector = sector;
    s.maxLight = light;
    s.minLight = dimmest == light ? 0 : dimmest;  // nothing dimmer around: it goes dark
    s.darkTime = dark;
    s.count = inSync ? 1 : (random.next() & 7) + 1;
    return s;
}

}  // namespace

std::optional<LightThinker> makeLightThinker(int special, int sector, int light, int dimmest, LightRandom& random) {
    switch (special) {
        case 1: return LightThinker(LightFlash{sector, dimmest, light, (random.next() & 64) + 1});
        case 2:
        case 4: return LightThinker(strobe(sector, light, dimmest, kFastDark, false, random));
        case 3: return LightThinker(strobe(sector, light, dimmest, kSlowDark, false, random));
        case 8: return LightThinker(Glow{sector, dimmest, light, -1});
        case 12: return LightThinker(strobe(sector, light, dimmest, kSlowDark, true, random));
        case 13: return LightThinker(strobe(sector, light, dimmest, kFastDark, true, random));
        case 17: return LightThinker(FireFlicker{sector, dimmest + 16, light, 4});
        default: return std::nullopt;
    }
}

int ticLight(LightThinker& thinker, int light, LightRandom& random) {
    return std::visit(
        [&](auto& t) -> int {
            using T = std::decay_t<decltype(t)>;
            if constexpr (std::is_same_v<T, LightFlash>) {  // T_LightFlash
                if (--t.count > 0) return light;
                if (light == t.maxLight) {
                    t.count = (random.next() & 7) + 1;
                    return t.minLight;
                }
                t.count = (random.next() & 64) + 1;
                return t.maxLight;
            } else if constexpr (std::is_same_v<T, StrobeFlash>) {  // T_StrobeFlash
                if (--t.count > 0) return light;
                if (light == t.minLight) {
                    t.count = t.brightTime;
                    return t.maxLight;
                }
                t.count = t.darkTime;
                return t.minLight;
            } else if constexpr (std::is_same_v<T, Glow>) {  // T_Glow
                if (t.direction < 0) {
                    light -= kGlowSpeed;
                    if (light <= t.minLight) light += kGlowSpeed, t.direction = 1;
                } else {
                    light += kGlowSpeed;
                    if (light >= t.maxLight) light -= kGlowSpeed, t.direction = -1;
                }
                return light;
            } else {  // T_FireFlicker
                if (--t.count > 0) return light;
                const int amount = (random.next() & 3) * 16;
                t.count = 4;
                return light - amount < t.minLight ? t.minLight : t.maxLight - amount;
            }
        },
        thinker);
}

int lightSector(const LightThinker& thinker) {
    return std::visit([](const auto& t) { return t.sector; }, thinker);
}

}  // namespace penumbra::doom
