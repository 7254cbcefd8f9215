// Geometry helpers shared by the OBJ and glTF importers.
#pragma once

#include "core/aabb.h"
#include "scene/scene.h"

namespace penumbra {

// Replaces mesh.normals with smooth vertex normals that keep creases: the faces around a
// position are averaged (weighted by their corner angles) only where their normals differ by
// less than `creaseDegrees`; vertices are split where they differ more. Vertices with equal
// positions are smoothed together even when they were split for UVs. A cube gets one normal per
// face (24 vertices); a finely tessellated sphere keeps shared vertices.
void generateCreaseNormals(Mesh& mesh, float creaseDegrees = 60.0f);

// A camera on +Z of the box's centre that fits its bounding sphere in `fovYDegrees`.
Camera cameraFittingBounds(const Aabb& bounds, float fovYDegrees = 40.0f);

}  // namespace penumbra
