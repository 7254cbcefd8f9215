#include "gpu/pipeline.h"

#include "core/error.h"
#include "gpu/check.h"
#include "gpu/shaders.h"

namespace penumbra::gpu {

ComputePipeline::ComputePipeline(const Context& ctx, std::string shaderName,
                                 std::span<const BindingSpec> bindings, std::uint32_t pushConstantBytes)
    : ctx_(ctx), name_(std::move(shaderName)), bindings_(bindings.begin(), bindings.end()),
      pushBytes_(pushConstantBytes) {
    VkDevice device = ctx.device();
    std::span<const std::uint32_t> code = shaderCode(name_);

    std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
    std::uint32_t storageCount = 0, uniformCount = 0;
    for (const BindingSpec& b : bindings_) {
        layoutBindings.push_back({b.binding, b.type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
        (b.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER ? uniformCount : storageCount)++;
    }
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.bindingCount = static_cast<std::uint32_t>(layoutBindings.size());
    setInfo.pBindings = layoutBindings.data();
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    PN_VK(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &setLayout));
    setLayout_ = DescriptorSetLayout(device, setLayout);

    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes_};
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout;
    layoutInfo.pushConstantRangeCount = pushBytes_ ? 1 : 0;
    layoutInfo.pPushConstantRanges = &range;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    PN_VK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout));
    layout_ = PipelineLayout(device, layout);

    VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    moduleInfo.codeSize = code.size_bytes();
    moduleInfo.pCode = code.data();
    VkShaderModule module = VK_NULL_HANDLE;
    PN_VK(vkCreateShaderModule(device, &moduleInfo, nullptr, &module));
    ShaderModule moduleOwner(device, module);

    VkComputePipelineCreateInfo pipeInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pipeInfo.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    pipeInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipeInfo.stage.module = module;
    pipeInfo.stage.pName = "main";
    pipeInfo.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    PN_VK(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &pipeInfo, nullptr, &pipeline));
    pipeline_ = Pipeline(device, pipeline);

    std::vector<VkDescriptorPoolSize> sizes;
    if (storageCount) sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, storageCount});
    if (uniformCount) sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uniformCount});
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
    poolInfo.pPoolSizes = sizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    PN_VK(vkCreateDescriptorPool(device, &poolInfo, nullptr, &pool));
    pool_ = DescriptorPool(device, pool);

    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = pool;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &setLayout;
    PN_VK(vkAllocateDescriptorSets(device, &alloc, &set_));
}

void ComputePipeline::bind(std::uint32_t binding, const Buffer& buffer) {
    const BindingSpec* spec = nullptr;
    for (const BindingSpec& b : bindings_)
        if (b.binding == binding) spec = &b;
    PN_CHECK(spec != nullptr);
    VkDescriptorBufferInfo info{buffer.get(), 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set_;
    write.dstBinding = binding;
    write.descriptorCount = 1;
    write.descriptorType = spec->type;
    write.pBufferInfo = &info;
    vkUpdateDescriptorSets(ctx_.device(), 1, &write, 0, nullptr);
}

void ComputePipeline::dispatch(VkCommandBuffer cmd, std::uint32_t x, std::uint32_t y, std::uint32_t z,
                               const void* push) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.get(), 0, 1, &set_, 0, nullptr);
    if (pushBytes_) vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes_, push);
    vkCmdDispatch(cmd, x, y, z);
}

}  // namespace penumbra::gpu
