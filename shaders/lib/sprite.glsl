// Sprites (PN_TRI_SPRITE slots, see shared/types.h): upright cards that turn about their vertical
// axis to face each ray's origin, so every ray sees the thing's picture square on, as Doom draws
// its sprites. The view (1 or 8 of them, side by side in the material's base-colour texture) is
// picked by the camera's direction from the thing relative to the way it faces, with Doom's rule
// (R_ProjectSprite). A ray from a point beside the axis sees the card turned toward it, so the
// thing shades and shadows itself like a solid of revolution. Include after textures.glsl.
#ifndef PN_SPRITE_GLSL
#define PN_SPRITE_GLSL

#include "lib/sampling.glsl"

// The card seen from o: its normal (horizontal, toward o) and the right of a viewer at o along
// it. False when o is on the axis, where no card faces it.
bool spriteCard(TriVerts s, vec3 o, out vec3 normal, out vec3 right) {
    vec2 toOrigin = o.xz - s.v0.xz;
    float len = length(toOrigin);
    normal = vec3(0.0, 0.0, 1.0);
    right = vec3(1.0, 0.0, 0.0);
    if (!(len > 1e-6)) return false;
    vec2 n = toOrigin / len;
    normal = vec3(n.x, 0.0, n.y);
    right = vec3(n.y, 0.0, -n.x);  // cross(-normal, +y)
    return true;
}

// The view the camera sees: floor((a - facing) / 45 degrees + 4.5) mod 8, where a is the direction
// from the camera to the thing; both angles counter-clockwise from +x toward -z (Doom's x and y).
uint spriteView(TriVerts s) {
    if (s.e2.z < 1.5) return 0u;
    vec3 d = s.v0 - frame.cameraPosition;
    if (d.x == 0.0 && d.z == 0.0) return 0u;
    float k = floor((atan(-d.z, d.x) - s.e2.y) / (0.25 * PN_PI) + 4.5);
    return uint(mod(k, 8.0)) % 8u;
}

// A hit on sprite slot i: the card facing o, within its extent, where its view is opaque. u, v:
// where in the material's texture (views side by side, each a cell of the card's extent).
bool hitSprite(uint i, TriVerts s, vec3 o, vec3 d, float tMax, out float t, out float u, out float v) {
    t = 0.0;
    u = 0.0;
    v = 0.0;
    vec3 n, r;
    if (!spriteCard(s, o, n, r)) return false;
    float denom = dot(d, n);
    if (!(denom < 0.0)) return false;  // leaving the card, or along it
    t = dot(s.v0 - o, n) / denom;
    if (!(t > 0.0 && t < tMax)) return false;
    vec3 p = o + t * d - s.v0;
    float x = dot(p, r), y = p.y;
    if (!(x >= s.e1.x && x <= s.e1.y && y >= s.e1.z && y <= s.e2.x)) return false;
    u = (float(spriteView(s)) + (x - s.e1.x) / (s.e1.y - s.e1.x)) / max(s.e2.z, 1.0);
    v = (s.e2.x - y) / (s.e2.x - s.e1.z);
    Material m = materials[triAttribs[i].materialId];
    return m.albedoTexture == PN_NO_TEXTURE || sampleTexture(m.albedoTexture, vec2(u, v), m.albedoWrap).a >= m.alphaCutoff;
}

#endif
