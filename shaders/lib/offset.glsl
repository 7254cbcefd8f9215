// Moves a ray origin off the surface it starts on, by an amount that scales with the position's
// floating-point magnitude (Waechter and Binder, Ray Tracing Gems ch. 6), so secondary rays do
// not hit their own surface at any scene scale.
#ifndef PN_OFFSET_GLSL
#define PN_OFFSET_GLSL

vec3 offsetRayOrigin(vec3 p, vec3 n) {
    const float nearOrigin = 1.0 / 32.0;
    const float floatStep = 1.0 / 65536.0;
    const float intStep = 256.0;
    ivec3 ulps = ivec3(intStep * n);
    vec3 moved = vec3(intBitsToFloat(floatBitsToInt(p.x) + (p.x < 0.0 ? -ulps.x : ulps.x)),
                      intBitsToFloat(floatBitsToInt(p.y) + (p.y < 0.0 ? -ulps.y : ulps.y)),
                      intBitsToFloat(floatBitsToInt(p.z) + (p.z < 0.0 ? -ulps.z : ulps.z)));
    return vec3(abs(p.x) < nearOrigin ? p.x + floatStep * n.x : moved.x,
                abs(p.y) < nearOrigin ? p.y + floatStep * n.y : moved.y,
                abs(p.z) < nearOrigin ? p.z + floatStep * n.z : moved.z);
}

#endif
