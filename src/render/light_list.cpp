#include "render/light_list.h"

#include "shared/color.h"
#include "shared/constants.h"

namespace penumbra {
namespace {


LightBounds triangleBounds(const EmissiveTriangle& t) {
    LightBounds b;
    for (Vec3 p : t.p) b.bounds.grow(p);
    const Vec3 n = cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
    b.phi = t.radiance * 0.5f * length(n);  // radiance x area
    b.axis = normalize(n);                  // the front face (counter-clockwise winding) emits
    b.cosThetaO = 1.0f;
    b.cosThetaE = 0.0f;                     // Lambertian: up to pi/2 from the normal
    return b;
}

LightBounds sphereBounds(const shader::SphereLight& l) {
    const float lum = luminance(l.radiance);
    // Seen from any direction, a sphere is a disk of area pi r^2.
    const float intensity = lum * kPiF * l.radius * l.radius;
    LightBounds b = l.cosOuter > -1.0f
                        ? spotLightBounds(l.center, l.spotDirection, intensity, l.cosInner, l.cosOuter)
                        : pointLightBounds(l.center, intensity);
    b.bounds.grow(l.center - Vec3{l.radius});
    b.bounds.grow(l.center + Vec3{l.radius});
    return b;
}

bool isInfinite(const shader::PunctualLight& l) { return l.type == PN_LIGHT_DIRECTIONAL; }

}  // namespace

LightBounds punctualBounds(const shader::PunctualLight& l) {
    const float intensity = luminance(l.intensity);
    if (l.type == PN_LIGHT_SPOT) return spotLightBounds(l.position, l.direction, intensity, l.cosInner, l.cosOuter);
    return pointLightBounds(l.position, intensity);
}

float meanLuminance(const Texture& t) {
    const std::size_t n = std::size_t(t.width) * std::size_t(t.height);
    if (n == 0 || t.rgba.size() < 4 * n) return 0.0f;
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        Vec3 c;
        for (int k = 0; k < 3; ++k) {
            const float v = float(t.rgba[4 * i + std::size_t(k)]) / 255.0f;
            c[k] = t.srgb ? shader::srgbToLinear(v) : v;
        }
        sum += luminance(c);
    }
    return float(sum / double(n));
}

float meanLuminanceOverFrames(const std::vector<Texture>& textures, std::size_t index) {
    const TextureAnimation& a = textures[index].animation;
    if (a.frames <= 1 || std::size_t(a.frame) > index || index - std::size_t(a.frame) + std::size_t(a.frames) > textures.size())
        return meanLuminance(textures[index]);
    double sum = 0;
    for (std::size_t k = index - std::size_t(a.frame); k < index - std::size_t(a.frame) + std::size_t(a.frames); ++k)
        sum += meanLuminance(textures[k]);
    return float(sum / a.frames);
}

LightList buildLightList(const LightListInput& in) {
    LightList out;
    // Top level: what cannot be bounded in space (the environment, directional lights) or moves
    // every frame (its bounds are rewritten per frame, never a tree's).
    if (in.environment) out.refs.push_back({PN_LIGHTREF_ENVIRONMENT, 0, 0, 0});
    for (std::uint32_t i = 0; i < in.punctual.size(); ++i)
        if (isInfinite(in.punctual[i]) || (i < in.punctualMoves.size() && in.punctualMoves[i]))
            out.refs.push_back({PN_LIGHTREF_PUNCTUAL, i, 0, 0});
    out.topCount = static_cast<std::uint32_t>(out.refs.size());
    for (const shader::LightRef& r : out.refs)
        out.nodes.push_back(r.type == PN_LIGHTREF_PUNCTUAL && !isInfinite(in.punctual[r.index])
                                ? toLightNode(punctualBounds(in.punctual[r.index]), PN_LIGHT_NODE_LEAF)
                                : shader::LightNode{});

    // The tree over everything with a place in space.
    std::vector<LightBounds> bounds;
    auto add = [&](std::uint32_t type, std::uint32_t index, const LightBounds& b, std::uint32_t primitive) {
        if (!(b.phi > 0) || !std::isfinite(b.phi) || b.bounds.empty()) return;
        if (primitive != PN_NO_HIT) out.primitiveLights.push_back({primitive, std::uint32_t(out.refs.size())});
        out.refs.push_back({type, index, 0, 0});
        bounds.push_back(b);
    };
    for (const EmissiveTriangle& t : in.triangles) add(PN_LIGHTREF_TRIANGLE, t.slot, triangleBounds(t), t.slot);
    for (std::uint32_t i = 0; i < in.spheres.size(); ++i)
        add(PN_LIGHTREF_SPHERE, i, sphereBounds(in.spheres[i]), in.spheres[i].primitive);
    for (std::uint32_t i = 0; i < in.punctual.size(); ++i) {
        const bool top = isInfinite(in.punctual[i]) || (i < in.punctualMoves.size() && in.punctualMoves[i]);
        if (!top) add(PN_LIGHTREF_PUNCTUAL, i, punctualBounds(in.punctual[i]), PN_NO_HIT);
    }
    LightTree tree = buildLightTree(bounds, out.topCount, 0);
    for (std::size_t i = 0; i < tree.trails.size(); ++i) {
        shader::LightRef& r = out.refs[out.topCount + i];
        r.trailLo = std::uint32_t(tree.trails[i]);
        r.trailHi = std::uint32_t(tree.trails[i] >> 32);
    }
    out.tree = compactLightTree(tree);
    return out;
}

std::optional<std::uint32_t> topEntryOfPunctual(std::span<const shader::LightRef> refs, std::uint32_t topCount,
                                                std::uint32_t index) {
    for (std::uint32_t k = 0; k < topCount && k < refs.size(); ++k)
        if (refs[k].type == PN_LIGHTREF_PUNCTUAL && refs[k].index == index) return k;
    return std::nullopt;
}

}  // namespace penumbra
