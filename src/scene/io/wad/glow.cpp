#include "scene/io/wad/glow.h"

#include <algorithm>
#include <cmath>

#include "shared/color.h"

namespace penumbra::wad {
namespace {

// Radiances (W/(m^2 sr) for a texel of linear colour 1). A sector at full light shows a surface
// at its texture colour (docs/SCENES.md), so lamps several times brighter read as light sources
// and light their rooms; liquids that glow only show their colour in the dark; screens are dim.
constexpr float kLampGlow = 6.0f;
constexpr float kPanelGlow = 4.0f;
constexpr float kHotLiquidGlow = 4.0f;  // nukage, lava, molten rock, fire
constexpr float kDullLiquidGlow =
    1.0f;  // water and blood: their palette colour, as Doom shows a lit pool
constexpr float kScreenGlow = 2.0f;

struct GlowEntry {
    const char* pattern;  // a name, or a prefix followed by '*'
    bool flat;
    GlowKind kind;
    float strength;
};

// First match wins. Names are Doom's, Doom II's and Freedoom's (which keeps Doom's names for the
// same things and adds its own, e.g. the AQ* set).
constexpr GlowEntry kGlows[] = {
    // Liquids (flats), the animated ones of Doom's table: hot ones (nukage, lava, Doom II's
    // molten rock and red SLIME09-12) light their surroundings; water, blood and Doom II's brown
    // sludge (SLIME01-08) only keep their colour in the dark.
    {"NUKAGE*", true, GlowKind::Whole, kHotLiquidGlow},
    {"LAVA*", true, GlowKind::Whole, kHotLiquidGlow},
    {"RROCK05", true, GlowKind::Whole, kHotLiquidGlow},
    {"RROCK06", true, GlowKind::Whole, kHotLiquidGlow},
    {"RROCK07", true, GlowKind::Whole, kHotLiquidGlow},
    {"RROCK08", true, GlowKind::Whole, kHotLiquidGlow},
    {"SLIME09", true, GlowKind::Whole, kHotLiquidGlow},
    {"SLIME10", true, GlowKind::Whole, kHotLiquidGlow},
    {"SLIME11", true, GlowKind::Whole, kHotLiquidGlow},
    {"SLIME12", true, GlowKind::Whole, kHotLiquidGlow},
    {"SLIME0*", true, GlowKind::Whole, kDullLiquidGlow},
    {"FWATER*", true, GlowKind::Whole, kDullLiquidGlow},
    {"SWATER*", true, GlowKind::Whole, kDullLiquidGlow},
    {"BLOOD*", true, GlowKind::Whole, kDullLiquidGlow},
    // Ceiling and floor lights (flats).
    {"TLITE6_*", true, GlowKind::Bright, kLampGlow},
    {"FLOOR1_7", true, GlowKind::Bright, kLampGlow},
    {"CEIL1_2", true, GlowKind::Bright, kLampGlow},
    {"CEIL1_3", true, GlowKind::Bright, kLampGlow},
    {"CEIL3_4", true, GlowKind::Bright, kLampGlow},
    {"CEIL3_6", true, GlowKind::Bright, kLampGlow},
    {"GRNLITE1", true, GlowKind::Bright, kLampGlow},
    {"FLAT2", true, GlowKind::Bright, kLampGlow},
    {"FLAT17", true, GlowKind::Bright, kLampGlow},
    {"FLAT22", true, GlowKind::Bright, kLampGlow},
    {"COMP01", true, GlowKind::Bright, kLampGlow},
    // Freedoom's light panel flats: white ones, then blue, green, orange, red and yellow pairs.
    {"AQF010", true, GlowKind::Panel, kPanelGlow},
    {"AQF011", true, GlowKind::Panel, kPanelGlow},
    {"AQF012", true, GlowKind::Panel, kPanelGlow},
    {"AQF014", true, GlowKind::Panel, kPanelGlow},
    {"AQF015", true, GlowKind::Panel, kPanelGlow},
    {"AQF035", true, GlowKind::Panel, kPanelGlow},
    {"AQF036", true, GlowKind::Panel, kPanelGlow},
    {"AQF037", true, GlowKind::Panel, kPanelGlow},
    {"AQF038", true, GlowKind::Panel, kPanelGlow},
    {"AQF039", true, GlowKind::Panel, kPanelGlow},
    {"AQF040", true, GlowKind::Panel, kPanelGlow},
    {"AQF041", true, GlowKind::Panel, kPanelGlow},
    {"AQF042", true, GlowKind::Panel, kPanelGlow},
    {"AQF043", true, GlowKind::Panel, kPanelGlow},
    {"AQF044", true, GlowKind::Panel, kPanelGlow},
    {"AQF058", true, GlowKind::Panel, kPanelGlow},
    {"AQF059", true, GlowKind::Panel, kPanelGlow},
    {"AQF060", true, GlowKind::Panel, kPanelGlow},
    {"AQF061", true, GlowKind::Panel, kPanelGlow},
    {"AQF062", true, GlowKind::Panel, kPanelGlow},
    {"AQF063", true, GlowKind::Panel, kPanelGlow},
    {"AQF064", true, GlowKind::Panel, kPanelGlow},
    {"AQF065", true, GlowKind::Panel, kPanelGlow},
    {"AQF066", true, GlowKind::Panel, kPanelGlow},
    // Computer consoles (flats): their small screens.
    {"CONS1_*", true, GlowKind::Screen, kScreenGlow},
    // Fire and falls (textures).
    {"FIREBLU*", false, GlowKind::Whole, kHotLiquidGlow},
    {"FIRELAV*", false, GlowKind::Whole, kHotLiquidGlow},
    {"FIREMAG*", false, GlowKind::Whole, kHotLiquidGlow},
    {"FIREWAL*", false, GlowKind::Whole, kHotLiquidGlow},
    {"SFALL*", false, GlowKind::Whole, kHotLiquidGlow},
    {"BFALL*", false, GlowKind::Whole, kDullLiquidGlow},
    {"WFALL*", false, GlowKind::Whole, kDullLiquidGlow},
    // Coloured light panels (Freedoom), before the LITE* lamps.
    {"AQLITE*", false, GlowKind::Panel, kPanelGlow},
    {"LITEGRN1", false, GlowKind::Panel, kPanelGlow},
    {"LITERED1", false, GlowKind::Panel, kPanelGlow},
    {"LITERED2", false, GlowKind::Panel, kPanelGlow},
    {"LITEYEL*", false, GlowKind::Panel, kPanelGlow},
    // Lamps, signs and lit switches (textures): only their brightest texels.
    {"LITE*", false, GlowKind::Bright, kLampGlow},
    {"TEKLITE*", false, GlowKind::Bright, kLampGlow},
    {"BSTONE3", false, GlowKind::Bright, kLampGlow},
    {"BRICKLIT", false, GlowKind::Bright, kLampGlow},
    {"EXITSIGN", false, GlowKind::Bright, kLampGlow},
    {"EXITSTON", false, GlowKind::Bright, kLampGlow},
    {"EXITSGN2", false, GlowKind::Bright, kLampGlow},
    {"SW1*", false, GlowKind::Bright, kLampGlow},
    {"SW2*", false, GlowKind::Bright, kLampGlow},
    // Computer panels and screens (textures).
    {"COMP2", false, GlowKind::Screen, kScreenGlow},
    {"COMPSTA*", false, GlowKind::Screen, kScreenGlow},
    {"COMPUTE*", false, GlowKind::Screen, kScreenGlow},
    {"COMPTALL", false, GlowKind::Screen, kScreenGlow},
    {"COMPTILE", false, GlowKind::Screen, kScreenGlow},
    {"COMPBLUE", false, GlowKind::Screen, kScreenGlow},
    {"COMPWERD", false, GlowKind::Screen, kScreenGlow},
    {"COMPOHSO", false, GlowKind::Screen, kScreenGlow},
    {"PLANET1", false, GlowKind::Screen, kScreenGlow},
    {"AQCOMP01", false, GlowKind::Screen, kScreenGlow},
};

bool matches(const char* pattern, const std::string& name) {
    const std::string p(pattern);
    if (!p.empty() && p.back() == '*')
        return name.compare(0, p.size() - 1, p, 0, p.size() - 1) == 0;
    return name == p;
}

float smoothstep(float lo, float hi, float x) {
    const float t = std::clamp((x - lo) / (hi - lo), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// Hue in degrees [0, 360) of an RGB colour with max > min.
float hueDegrees(float r, float g, float b, float max, float chroma) {
    float h;
    if (max == r)
        h = std::fmod((g - b) / chroma, 6.0f);
    else if (max == g)
        h = (b - r) / chroma + 2.0f;
    else
        h = (r - g) / chroma + 4.0f;
    h *= 60.0f;
    return h < 0 ? h + 360.0f : h;
}

}  // namespace

Glow glowOf(const std::string& name, bool flat) {
    for (const GlowEntry& e : kGlows)
        if (e.flat == flat && matches(e.pattern, name)) return {e.kind, e.strength};
    return {};
}

float glowWeight(GlowKind kind, std::uint8_t r8, std::uint8_t g8, std::uint8_t b8) {
    const float r = r8 / 255.0f, g = g8 / 255.0f, b = b8 / 255.0f;
    const float value = std::max({r, g, b});
    const float chroma = value - std::min({r, g, b});
    // Lamps are drawn near full brightness and their frames, plates and unlit bulbs well below:
    // by this weight Doom's LITE3-5 are 28-37% lit, its switch plates under 3%.
    const float bright = smoothstep(0.66f, 0.86f, value);
    switch (kind) {
        case GlowKind::None:
            return 0.0f;
        case GlowKind::Whole:
            return 1.0f;
        case GlowKind::Bright:
            return bright;
        case GlowKind::Panel:
            return smoothstep(0.30f, 0.45f, value);  // the black grid is below 0.16
        case GlowKind::Screen: {
            // Screen content is saturated (green text, blue and red displays) or white; the
            // machinery around it is grey, or wood, rust and hazard paint in orange to yellow hues.
            if (chroma > 0.1f) {
                const float hue = hueDegrees(r, g, b, value, chroma);
                if (hue >= 15.0f && hue <= 65.0f) return 0.0f;
            }
            return std::max(smoothstep(0.2f, 0.4f, chroma) * smoothstep(0.25f, 0.45f, value),
                            bright);
        }
    }
    return 0.0f;
}

Texture glowTexture(const Texture& texture, GlowKind kind) {
    Texture out = texture;
    out.name = texture.name + " glow";
    const std::size_t n = std::size_t(texture.width) * std::size_t(texture.height);
    for (std::size_t i = 0; i < n && 4 * i + 3 < out.rgba.size(); ++i) {
        std::uint8_t* t = &out.rgba[4 * i];
        const float w = glowWeight(kind, t[0], t[1], t[2]);
        for (int c = 0; c < 3; ++c) {
            const float linear = shader::srgbToLinear(t[c] / 255.0f) * w;
            t[c] = static_cast<std::uint8_t>(std::lround(shader::linearToSrgb(linear) * 255.0f));
        }
    }
    return out;
}

}  // namespace penumbra::wad
