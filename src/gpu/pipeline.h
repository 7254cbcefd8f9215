// A compute pipeline from an embedded shader, with one descriptor set of buffers.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/handle.h"

namespace penumbra::gpu {

struct BindingSpec {
    std::uint32_t binding;
    VkDescriptorType type;  // VK_DESCRIPTOR_TYPE_STORAGE_BUFFER or _UNIFORM_BUFFER
};

// One statistic the driver reports for a compiled pipeline (VK_KHR_pipeline_executable_properties):
// registers, spills, shared memory... Names and meanings are the driver's.
struct PipelineStatistic {
    std::string executable;  // the driver's name for the compiled stage
    std::string name;
    std::string value;       // formatted number
};

class ComputePipeline {
public:
    // specialization: the values of specialization constants 0, 1, 2, ... (uint32 each); empty
    // keeps the shader's defaults.
    ComputePipeline(const Context& ctx, std::string shaderName, std::span<const BindingSpec> bindings,
                    std::uint32_t pushConstantBytes, std::span<const std::uint32_t> specialization = {});

    // What the driver says about the compiled pipeline; empty when it cannot say
    // (Context::pipelineStatisticsSupported).
    std::vector<PipelineStatistic> statistics() const;
    // The same, each executable's name prefixed by the pipeline's ("wave_shade: CS").
    std::vector<PipelineStatistic> namedStatistics() const;

    // Points `binding` at `buffer`. Call between submissions, not while a dispatch is in flight.
    void bind(std::uint32_t binding, const Buffer& buffer);

    // Binds the pipeline and its set, pushes `push` (pushConstantBytes of it) and dispatches.
    void dispatch(VkCommandBuffer cmd, std::uint32_t x, std::uint32_t y, std::uint32_t z, const void* push) const;
    // The same, with the group counts read on the GPU from a VkDispatchIndirectCommand in `args`
    // (which needs VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT) at `offset`.
    void dispatchIndirect(VkCommandBuffer cmd, const Buffer& args, VkDeviceSize offset, const void* push) const;

    const std::string& name() const { return name_; }

private:
    void bindForDispatch(VkCommandBuffer cmd, const void* push) const;

    const Context& ctx_;
    std::string name_;
    std::vector<BindingSpec> bindings_;
    std::uint32_t pushBytes_;
    DescriptorSetLayout setLayout_;
    PipelineLayout layout_;
    Pipeline pipeline_;
    DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace penumbra::gpu
