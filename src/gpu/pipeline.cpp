#include "gpu/pipeline.h"

#include "core/error.h"
#include "gpu/check.h"
#include "gpu/shaders.h"

namespace penumbra::gpu {

ComputePipeline::ComputePipeline(const Context& ctx, std::string shaderName,
                                 std::span<const BindingSpec> bindings, std::uint32_t pushConstantBytes,
                                 std::span<const std::uint32_t> specialization)
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

    std::vector<VkSpecializationMapEntry> entries;
    for (std::uint32_t i = 0; i < specialization.size(); ++i)
        entries.push_back({i, i * std::uint32_t(sizeof(std::uint32_t)), sizeof(std::uint32_t)});
    VkSpecializationInfo specInfo{static_cast<std::uint32_t>(entries.size()), entries.data(),
                                  specialization.size_bytes(), specialization.data()};
    VkComputePipelineCreateInfo pipeInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    if (ctx.pipelineStatisticsSupported()) pipeInfo.flags |= VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR;
    pipeInfo.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    pipeInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipeInfo.stage.module = module;
    pipeInfo.stage.pName = "main";
    pipeInfo.stage.pSpecializationInfo = specialization.empty() ? nullptr : &specInfo;
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

namespace {

std::string formatStatistic(const VkPipelineExecutableStatisticKHR& s) {
    switch (s.format) {
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR: return s.value.b32 ? "true" : "false";
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR: return std::to_string(s.value.i64);
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR: return std::to_string(s.value.u64);
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR: return std::to_string(s.value.f64);
        default: return "?";
    }
}

}  // namespace

std::vector<PipelineStatistic> ComputePipeline::namedStatistics() const {
    std::vector<PipelineStatistic> out = statistics();
    for (PipelineStatistic& s : out) s.executable = name() + ": " + s.executable;
    return out;
}

std::vector<PipelineStatistic> ComputePipeline::statistics() const {
    std::vector<PipelineStatistic> out;
    if (!ctx_.pipelineStatisticsSupported()) return out;
    VkDevice device = ctx_.device();
    auto getProperties = reinterpret_cast<PFN_vkGetPipelineExecutablePropertiesKHR>(
        vkGetDeviceProcAddr(device, "vkGetPipelineExecutablePropertiesKHR"));
    auto getStatistics = reinterpret_cast<PFN_vkGetPipelineExecutableStatisticsKHR>(
        vkGetDeviceProcAddr(device, "vkGetPipelineExecutableStatisticsKHR"));
    if (!getProperties || !getStatistics) return out;
    VkPipelineInfoKHR info{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR};
    info.pipeline = pipeline_.get();
    std::uint32_t count = 0;
    PN_VK(getProperties(device, &info, &count, nullptr));
    std::vector<VkPipelineExecutablePropertiesKHR> executables(count, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR});
    PN_VK(getProperties(device, &info, &count, executables.data()));
    for (std::uint32_t e = 0; e < count; ++e) {
        VkPipelineExecutableInfoKHR exec{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR};
        exec.pipeline = pipeline_.get();
        exec.executableIndex = e;
        std::uint32_t n = 0;
        PN_VK(getStatistics(device, &exec, &n, nullptr));
        std::vector<VkPipelineExecutableStatisticKHR> stats(n, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR});
        PN_VK(getStatistics(device, &exec, &n, stats.data()));
        for (const auto& s : stats) out.push_back({executables[e].name, s.name, formatStatistic(s)});
    }
    return out;
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

void ComputePipeline::bindForDispatch(VkCommandBuffer cmd, const void* push) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.get(), 0, 1, &set_, 0, nullptr);
    if (pushBytes_) vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes_, push);
}

void ComputePipeline::dispatch(VkCommandBuffer cmd, std::uint32_t x, std::uint32_t y, std::uint32_t z,
                               const void* push) const {
    bindForDispatch(cmd, push);
    vkCmdDispatch(cmd, x, y, z);
}

void ComputePipeline::dispatchIndirect(VkCommandBuffer cmd, const Buffer& args, VkDeviceSize offset,
                                       const void* push) const {
    bindForDispatch(cmd, push);
    vkCmdDispatchIndirect(cmd, args.get(), offset);
}

}  // namespace penumbra::gpu
