#include "render/passes/trace_outputs.h"

#include "render/scene_pipeline.h"

namespace penumbra {

std::unique_ptr<gpu::ComputePipeline> makeTracePipeline(const gpu::Context& ctx, const std::string& shader,
                                                        const GpuScene& scene, const gpu::Buffer& frameUniforms,
                                                        const TraceOutputs& outputs,
                                                        const std::vector<std::uint32_t>& moreBindings,
                                                        KernelSpec spec, std::uint32_t camera) {
    std::vector<std::uint32_t> bindings = {PN_BINDING_ACCUM, PN_BINDING_COUNTERS, PN_BINDING_ACTIVE_MASK,
                                           PN_BINDING_PIXEL_ESTIMATES};
    bindings.insert(bindings.end(), moreBindings.begin(), moreBindings.end());
    auto pipeline = makeScenePipeline(ctx, shader, scene, frameUniforms, bindings, spec, camera);
    pipeline->bind(PN_BINDING_ACCUM, *outputs.accumulation);
    pipeline->bind(PN_BINDING_COUNTERS, *outputs.counters);
    pipeline->bind(PN_BINDING_ACTIVE_MASK, *outputs.activeMask);
    pipeline->bind(PN_BINDING_PIXEL_ESTIMATES, *outputs.pixelEstimates);
    return pipeline;
}

}  // namespace penumbra
