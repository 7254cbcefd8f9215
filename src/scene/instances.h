// Instances (Scene::prototypes and Scene::instances): counting them, and baking them into world
// meshes where a consumer needs every triangle in world space (emitters, exports, the oracle of
// the instancing tests).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/transform.h"
#include "scene/scene.h"

namespace penumbra {

// The mesh moved by `transform`: positions and normals (by the inverse transpose); a mirroring
// transform also reverses the winding, so front faces stay in front.
Mesh transformedMesh(Mesh mesh, const Affine& transform);

std::size_t prototypeTriangleCount(const Prototype& prototype);
// Triangles the instances place in all (each instance counts its prototype's).
std::size_t instancedTriangleCount(const Scene& scene);
// Whether the prototype has a material that light sampling aims at (an emitter that is not
// lightSampled, like glowing eyes, is found by rays alone and needs no world-space light entry,
// so it may stay an instance and move).
bool prototypeIsEmissive(const Scene& scene, const Prototype& prototype);

// Appends world copies of instance i's meshes to scene.meshes (the instance itself stays).
void appendBakedInstance(Scene& scene, std::size_t instance);
// Every instance becomes world meshes; prototypes and instances are then empty.
void bakeAllInstances(Scene& scene);
// Instances of prototypes with an emissive material become world meshes, so their light data
// (world-space emitters in the light BVH) stays as for any mesh; returns how many were baked.
// keptFrom (optional): each remaining instance's number before, so callers can keep naming
// instances by the scene's own numbers.
std::size_t bakeEmissiveInstances(Scene& scene, std::vector<std::uint32_t>* keptFrom = nullptr);

// Moves every non-emissive world mesh into one prototype placed once by the identity (a
// measurement aid: the same picture through the two-level traversal; PENUMBRA_FORCE_INSTANCES=1).
void instanceWorldMeshes(Scene& scene);

}  // namespace penumbra
