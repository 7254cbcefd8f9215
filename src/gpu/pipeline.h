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

class ComputePipeline {
public:
    ComputePipeline(const Context& ctx, std::string shaderName, std::span<const BindingSpec> bindings,
                    std::uint32_t pushConstantBytes);

    // Points `binding` at `buffer`. Call between submissions, not while a dispatch is in flight.
    void bind(std::uint32_t binding, const Buffer& buffer);

    // Binds the pipeline and its set, pushes `push` (pushConstantBytes of it) and dispatches.
    void dispatch(VkCommandBuffer cmd, std::uint32_t x, std::uint32_t y, std::uint32_t z, const void* push) const;

    const std::string& name() const { return name_; }

private:
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
