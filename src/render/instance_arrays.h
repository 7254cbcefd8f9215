// The two-level part of SceneArrays: one bottom-level BVH per prototype the scene's instances
// use, the instances (the world's own geometry first, as an identity instance) and the top level
// over them, rebuilt on the CPU when an instance moves. Layout at shader::Instance.
#pragma once

#include <cstdint>

#include "bvh/builder.h"
#include "core/transform.h"
#include "render/scene_arrays.h"
#include "scene/scene.h"

namespace penumbra {

// Call once the world level (the flat BVH over the scene's own primitives) is in `out`: appends a
// bottom level per used prototype to out.nodes, out.triVerts and out.triAttribs, the instances,
// and the top level. Does nothing for a scene without instances (the flat BVH is then walked
// alone, exactly as before).
void appendInstanceLevels(const Scene& scene, SceneArrays& out, const bvh::BuildOptions& options);

// Rebuilds the top level from the instances' current transforms (what a moved instance needs),
// and the walks' records of it (render/walks.h refreshTopLevelRecords).
void rebuildTopLevel(SceneArrays& arrays);

// Moves the instances to where `scene` now places them (the scene the arrays were built from, its
// instances moved: an animation, a Doom door) and, if any moved, rebuilds the top level; no bottom
// level is rebuilt. Returns whether any moved. Instances of emissive prototypes were baked into
// the world where they stood (scene/instances.h bakeEmissiveInstances) and do not move here.
bool moveInstances(SceneArrays& arrays, const Scene& scene);

// Moves instance `index` of arrays.instances (0 is the world when it has geometry; see
// shader::Instance::id for the scene's number) and rebuilds the top level.
void setInstanceTransform(SceneArrays& arrays, std::uint32_t index, const Affine& objectToWorld);

}  // namespace penumbra
