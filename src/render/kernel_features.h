// What the tracing kernels are specialised for (shaders/shared/features.h): the capabilities a scene
// has (constant 0) apart from the promises and modes the host adds (constant 3). The walk
// (constant 1) comes with the scene's arrays (render/walks.h) and the camera variant (constant 2)
// with the kernel that makes camera paths (render/passes/wavefront_pass.cpp). Pipelines are
// specialised with it, so a Doom level's kernel carries no sphere, glass or environment-map code.
// PENUMBRA_GENERIC_KERNEL=1 keeps every capability and promises nothing (the A/B baseline).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "render/scene_arrays.h"

namespace penumbra {

// Scenes with at least this many lights get the shadow-ray roulette (PN_FEATURE_SHADOW_ROULETTE).
// It pays where one light sample among many often carries little: on the H200 (session 33) the
// Doom maps' frames (294 and 676 lights) were 7-17% faster with it, while the scenes of 2-4 lights
// traced 1-3% fewer rays and were up to 2% slower, paying for the test on every light sample.
constexpr std::size_t kShadowRouletteMinLights = 16;

// Specialization constants 0 and 3 of every scene-tracing kernel.
struct KernelSpec {
    std::uint32_t capabilities = PN_FEATURE_ALL;  // PN_FEATURE_*: what the kernel can meet
    std::uint32_t options = PN_OPTION_NONE;       // PN_OPTION_*: what it is promised or asked to do
    bool has(std::uint32_t capability) const { return (capabilities & capability) != 0; }
    bool hasOption(std::uint32_t option) const { return (options & option) != 0; }
    KernelSpec withOption(std::uint32_t option, bool on) const {
        return {capabilities, on ? options | option : options & ~option};
    }
    bool operator==(const KernelSpec&) const = default;
};

// The scene edits after which a bit may need new kernels (KernelBit::changedBy), as a bit set.
enum SceneEdit : std::uint32_t {
    kEditNone = 0,
    kEditGeometry = 1,     // primitives, instances, sprites
    kEditMaterials = 2,    // one material's parameters (InteractiveRenderer::setMaterial)
    kEditLights = 4,       // the light list, tree and grid
    kEditEnvironment = 8,  // the environment map
};

// One row per bit: its name, which constant it lives in, how the scene shows it (null for options
// that come from settings, not from the scene) and which edits can change that.
struct KernelBit {
    std::uint32_t bit;
    bool option;  // constant 3 (PN_OPTION_*), else constant 0 (PN_FEATURE_*)
    const char* name;
    bool (*detect)(const SceneArrays&);
    std::uint32_t changedBy;  // SceneEdit bits
};
std::span<const KernelBit> kernelBits();

// What `arrays` needs, with the settings' modes: --cull-backfaces and the frame statistics.
KernelSpec kernelSpec(const SceneArrays& arrays, bool cullBackfaces = false, bool frameStatistics = false);

// `inUse` with the bits that `edits` can change detected again on `arrays`; the kernels must be
// remade when the result differs (a wall edited to glass needs kernels with glass in them).
KernelSpec kernelSpecAfter(KernelSpec inUse, const SceneArrays& arrays, std::uint32_t edits);

// "spheres,textures+cull-backfaces" (options after a '+'), "all" for every capability, for reports.
std::string kernelSpecNames(KernelSpec spec);

}  // namespace penumbra
