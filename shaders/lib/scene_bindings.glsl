// The scene's buffers, as every tracing kernel sees them. Include after shared/types.h.
#ifndef PN_SCENE_BINDINGS_GLSL
#define PN_SCENE_BINDINGS_GLSL

#include "shared/accel_layouts.h"

layout(std430, set = 0, binding = PN_BINDING_NODES) readonly buffer NodeBuffer { BvhPair nodes[]; };
layout(std430, set = 0, binding = PN_BINDING_TRI_VERTS) readonly buffer TriVertBuffer { TriVerts triVerts[]; };
layout(std430, set = 0, binding = PN_BINDING_TRI_ATTRIBS) readonly buffer TriAttribBuffer { TriAttribs triAttribs[]; };
layout(std430, set = 0, binding = PN_BINDING_TRI_UVS) readonly buffer TriUvBuffer { TriUvs triUvs[]; };
layout(std430, set = 0, binding = PN_BINDING_MATERIALS) readonly buffer MaterialBuffer { Material materials[]; };
layout(std430, set = 0, binding = PN_BINDING_LIGHTS) readonly buffer LightBuffer { LightRef lights[]; };
layout(std430, set = 0, binding = PN_BINDING_LIGHT_NODES) readonly buffer LightNodeBuffer { LightNode lightNodes[]; };
layout(std430, set = 0, binding = PN_BINDING_LIGHT_TREE) readonly buffer LightTreeBuffer { LightTreeNode lightTree[]; };
layout(std140, set = 0, binding = PN_BINDING_FRAME) uniform FrameBuffer { FrameUniforms frame; };
layout(std430, set = 0, binding = PN_BINDING_TEXTURES) readonly buffer TextureBuffer { TextureInfo textures[]; };
layout(std430, set = 0, binding = PN_BINDING_TEXELS) readonly buffer TexelBuffer { uint texels[]; };
layout(std430, set = 0, binding = PN_BINDING_PUNCTUAL) readonly buffer PunctualBuffer { PunctualLight punctualLights[]; };
layout(std430, set = 0, binding = PN_BINDING_SPHERE_LIGHTS) readonly buffer SphereLightBuffer { SphereLight sphereLights[]; };
layout(std430, set = 0, binding = PN_BINDING_INSTANCES) readonly buffer InstanceBuffer { Instance instances[]; };
layout(std430, set = 0, binding = PN_BINDING_STACKLESS_NODES) readonly buffer StacklessBuffer { StacklessNode stacklessNodes[]; };
layout(std430, set = 0, binding = PN_BINDING_OBJECT_BOXES) readonly buffer ObjectBoxBuffer { ObjectBox objectBoxes[]; };
layout(std430, set = 0, binding = PN_BINDING_OBJECT_PRIMS) readonly buffer ObjectPrimBuffer { uint objectPrims[]; };
layout(push_constant) uniform PushBlock { PassPush push; };

// What this pipeline was specialised for (PN_FEATURE_*); branches on it vanish at pipeline
// creation. PN_HAS must stay a macro: a function argument would not be a constant.
layout(constant_id = 0) const uint pnFeatures = PN_FEATURE_ALL;
#define PN_HAS(feature) ((pnFeatures & (feature)) != 0u)
// The walk this pipeline was made for (PN_ACCEL_*; render/walks.h), a choice apart from the
// capability bits above (issue 38): specialised, the other walks' code vanishes; PN_WALK_ANY (the
// default) keeps them all and reads frame.accel for each ray.
layout(constant_id = 1) const uint pnWalk = PN_WALK_ANY;
#define PN_WALK_IS(walk) (pnWalk == PN_WALK_ANY ? frame.accel == (walk) : pnWalk == (walk))
// Where bounce 0's paths come from (PN_CAMERA_*): only the wavefront's first extend and shade
// make them in place.
layout(constant_id = 2) const uint pnCamera = PN_CAMERA_FROM_QUEUE;
// What the host promises or asks for (PN_OPTION_*); none by default, which is always correct.
layout(constant_id = 3) const uint pnOptions = PN_OPTION_NONE;
#define PN_OPTION(option) ((pnOptions & (option)) != 0u)

#endif
