// The Surface at a hit on a sprite slot (lib/sprite.glsl). Included by surface.glsl after the
// Surface struct.
#ifndef PN_SPRITE_SURFACE_GLSL
#define PN_SPRITE_SURFACE_GLSL

Surface spriteSurfaceAt(TriVerts tv, TriAttribs ta, float t, float u, float v, vec3 o, vec3 d) {
    vec3 n, r;
    spriteCard(tv, o, n, r);  // a hit means the card exists
    Surface s;
    s.position = o + t * d;
    s.frontFace = true;  // the card always faces the ray's origin
    s.geometricNormal = n;
    s.shadingNormal = n;
    s.material = ta.materialId;
    s.lightIndex = ta.lightIndex;
    s.area = ta.area;
    s.uv = vec2(u, v);
    return s;
}

#endif
