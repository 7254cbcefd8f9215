// Texture lookups from the texel buffer: bilinear or nearest filtering, wrap modes, sRGB decoding
// and animation done by hand, which works on every Vulkan 1.2 device with no descriptor-indexing
// features.
#ifndef PN_TEXTURES_GLSL
#define PN_TEXTURES_GLSL

#include "shared/animation.h"
#include "shared/color.h"
#include "shared/view_limits.h"

int wrapTexel(int i, int size, uint mode) {
    if (mode == PN_WRAP_CLAMP) return clamp(i, 0, size - 1);
    if (mode == PN_WRAP_MIRROR) {
        int period = 2 * size;
        int m = ((i % period) + period) % period;
        return m < size ? m : period - 1 - m;
    }
    return ((i % size) + size) % size;
}

// Colour texels are decoded to linear before filtering, as sRGB texture hardware does.
vec4 texelAt(TextureInfo info, int x, int y) {
    vec4 c = unpackUnorm4x8(texels[info.firstTexel + uint(y) * info.width + uint(x)]);
    if ((info.flags & PN_TEXTURE_SRGB) != 0u) c.rgb = vec3(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b));
    return c;
}

// The texture a lookup of texture `index` (described by `info`) shows at frame.time: itself, or
// for a frame of an animation the cycle's frame on show, this texture's offset in the cycle kept
// (as Doom animates every frame of a cycle).
uint animatedTexture(uint index, TextureInfo info) {
    if (info.frameCount <= 1u) return index;
    uint step = animationTick(frame.time, info.secondsPerFrame) % info.frameCount;
    return index - info.frame + (step + info.frame) % info.frameCount;
}

// Linear RGBA at uv (v = 0 is the top row, as glTF and our Texture store it); `wrap` is the
// material's sampler word (PN_WRAP_* per axis, PN_SAMPLER_NEAREST).
vec4 sampleTexture(uint index, vec2 uv, uint wrap) {
    TextureInfo info = textures[index];
    if (info.frameCount > 1u) info = textures[animatedTexture(index, info)];
    int w = int(info.width), h = int(info.height);
    uint wrapU = wrap & 0xffu, wrapV = (wrap >> 8) & 0xffu;
    if ((wrap & PN_SAMPLER_NEAREST) != 0u) {
        vec2 q = floor(uv * vec2(w, h));
        if (any(isnan(q)) || any(isinf(q))) q = vec2(0.0);
        ivec2 i = ivec2(clamp(q, vec2(-1e8), vec2(1e8)));
        return texelAt(info, wrapTexel(i.x, w, wrapU), wrapTexel(i.y, h, wrapV));
    }
    vec2 p = uv * vec2(w, h) - 0.5;
    if (any(isnan(p)) || any(isinf(p))) p = vec2(0.0);
    vec2 base = floor(p);
    vec2 f = p - base;
    // Keep the integer range sane for huge uv values before wrapping.
    ivec2 i0 = ivec2(clamp(base, vec2(-1e8), vec2(1e8)));
    int x0 = wrapTexel(i0.x, w, wrapU), x1 = wrapTexel(i0.x + 1, w, wrapU);
    int y0 = wrapTexel(i0.y, h, wrapV), y1 = wrapTexel(i0.y + 1, h, wrapV);
    return mix(mix(texelAt(info, x0, y0), texelAt(info, x1, y0), f.x),
               mix(texelAt(info, x0, y1), texelAt(info, x1, y1), f.x), f.y);
}

// A triangle's texture coordinates at barycentrics (u, v): all zero for one without any.
vec2 interpolateUv(TriVerts tv, float u, float v) {
    TriUvs t = triUvs[tv.uvIndex];
    return (1.0 - u - v) * t.uv0 + u * t.uv1 + v * t.uv2;
}

// Base colour (rgb) and coverage (a) of a material at uv.
vec4 materialBaseColor(Material m, vec2 uv) {
    if (!PN_HAS(PN_FEATURE_TEXTURES) || m.albedoTexture == PN_NO_TEXTURE) return vec4(m.albedo, 1.0);
    vec4 t = sampleTexture(m.albedoTexture, uv, m.albedoWrap);
    if (frame.textureSaturation != 1.0) {  // shared/view_limits.h
        float lum = luminance(t.rgb);
        t.rgb = vec3(saturateChannel(t.r, lum, frame.textureSaturation), saturateChannel(t.g, lum, frame.textureSaturation),
                     saturateChannel(t.b, lum, frame.textureSaturation));
    }
    return vec4(m.albedo * t.rgb, t.a);
}

// For alpha-tested triangles: is the point (u, v) of triangle `tri` (whose TriVerts the caller
// has already read, as tv) a hole?
bool isAlphaHole(uint tri, TriVerts tv, float u, float v) {
    Material m = materials[triAttribs[tri].materialId];
    if ((m.flags & PN_MATERIAL_ALPHA_TESTED) == 0u || m.albedoTexture == PN_NO_TEXTURE) return false;
    return sampleTexture(m.albedoTexture, interpolateUv(tv, u, v), m.albedoWrap).a < m.alphaCutoff;
}

#endif
