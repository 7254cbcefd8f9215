// PN_INLINE: how a function written once for C++ and GLSL is declared (inline in C++, so headers
// can define it; nothing in GLSL). Included by the shared headers of functions.
#ifndef PN_INLINE
#ifdef __cplusplus
#define PN_INLINE inline
#else
#define PN_INLINE
#endif
#endif
