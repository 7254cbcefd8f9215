// Moved instances to the GPU without a new scene upload: the records a move changes (the
// instances, the top level's node records for the binary walk, its threaded nodes for the
// stackless walk, the objects' boxes) copied over the GpuScene's buffers from a staging buffer.
// The one upload of moved instances: Renderer (final frames) and InteractiveRenderer (the viewer)
// both record it after render/instance_arrays.h moveInstances.
#pragma once

#include "gpu/buffer.h"
#include "render/gpu_scene.h"
#include "render/scene_arrays.h"

namespace penumbra {

// Staging bytes recordInstanceUpload needs for these arrays (0 without instances).
VkDeviceSize instanceUploadBytes(const SceneArrays& arrays);

// Writes the records a move changes into `staging` (host-visible) from byte `offset` on, and
// records their copies into `scene`, which was made from these arrays before the move. The caller
// orders the copies after earlier reads of those buffers and before the next pass (a barrier).
void recordInstanceUpload(VkCommandBuffer cmd, const SceneArrays& arrays, const GpuScene& scene,
                          const gpu::Buffer& staging, VkDeviceSize offset);

}  // namespace penumbra
