// The harness's pipeline phase, shared by capture() and render(): the shader stages checked against
// each other and the device, their modules and specialization, the vertex input and its buffers,
// the descriptors (vk_descriptors.cpp), the pipeline layout with push constants, and the fixed
// function state of a graphics pipeline; then the commands that bind and draw it. One function per
// part, called in this order by buildPipeline, so the first problem found is the one reported.
#include "transpiler/verify/vk_context_impl.h"

#include <algorithm>

namespace stereoshift::harness {

uint32_t vertexFormatSize(VkFormat f) {
  switch (f) {
    case VK_FORMAT_R8_UNORM: case VK_FORMAT_R8_SNORM: case VK_FORMAT_R8_UINT: case VK_FORMAT_R8_SINT:
      return 1;
    case VK_FORMAT_R8G8_UNORM: case VK_FORMAT_R8G8_SNORM: case VK_FORMAT_R8G8_UINT:
    case VK_FORMAT_R8G8_SINT: case VK_FORMAT_R16_UNORM: case VK_FORMAT_R16_SNORM:
    case VK_FORMAT_R16_UINT: case VK_FORMAT_R16_SINT: case VK_FORMAT_R16_SFLOAT:
      return 2;
    case VK_FORMAT_R8G8B8A8_UNORM: case VK_FORMAT_R8G8B8A8_SNORM: case VK_FORMAT_R8G8B8A8_UINT:
    case VK_FORMAT_R8G8B8A8_SINT: case VK_FORMAT_B8G8R8A8_UNORM: case VK_FORMAT_R16G16_UNORM:
    case VK_FORMAT_R16G16_SNORM: case VK_FORMAT_R16G16_UINT: case VK_FORMAT_R16G16_SINT:
    case VK_FORMAT_R16G16_SFLOAT: case VK_FORMAT_R32_UINT: case VK_FORMAT_R32_SINT:
    case VK_FORMAT_R32_SFLOAT: case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
    case VK_FORMAT_A2B10G10R10_SNORM_PACK32:
      return 4;
    case VK_FORMAT_R16G16B16A16_UNORM: case VK_FORMAT_R16G16B16A16_SNORM:
    case VK_FORMAT_R16G16B16A16_UINT: case VK_FORMAT_R16G16B16A16_SINT:
    case VK_FORMAT_R16G16B16A16_SFLOAT: case VK_FORMAT_R32G32_UINT: case VK_FORMAT_R32G32_SINT:
    case VK_FORMAT_R32G32_SFLOAT:
      return 8;
    case VK_FORMAT_R32G32B32_UINT: case VK_FORMAT_R32G32B32_SINT: case VK_FORMAT_R32G32B32_SFLOAT:
      return 12;
    case VK_FORMAT_R32G32B32A32_UINT: case VK_FORMAT_R32G32B32A32_SINT:
    case VK_FORMAT_R32G32B32A32_SFLOAT:
      return 16;
    default:
      return 0;
  }
}

const char* stageName(VkShaderStageFlagBits s) {
  switch (s) {
    case VK_SHADER_STAGE_VERTEX_BIT: return "vertex";
    case VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT: return "tessellation control";
    case VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT: return "tessellation evaluation";
    case VK_SHADER_STAGE_GEOMETRY_BIT: return "geometry";
    case VK_SHADER_STAGE_FRAGMENT_BIT: return "fragment";
    default: return "unsupported";
  }
}

VulkanContext::Impl::BuiltPipeline VulkanContext::Impl::buildPipeline(Scope& scope, VkCommandBuffer uploads,
                                                                      const PipelineInputs& in,
                                                                      VkRenderPass renderPass,
                                                                      const RasterConfig& raster,
                                                                      const std::string& label) {
  BuiltPipeline out;
  const StageMap stages = checkStages(in, raster, label);
  Specialization spec;
  specialize(in, &spec, label);
  const std::vector<VkPipelineShaderStageCreateInfo> stageInfos = shaderStages(scope, stages, spec);
  const VertexInput input = vertexInput(scope, in, &out, label);
  const std::vector<VkDescriptorSetLayout> setLayouts = descriptorSets(scope, uploads, in, &out, label);
  out.layout = pipelineLayout(scope, in, setLayouts, label);
  out.pipeline = graphicsPipeline(scope, in, raster, renderPass, stageInfos, input, out.layout, label);
  return out;
}

VulkanContext::Impl::StageMap VulkanContext::Impl::checkStages(const PipelineInputs& in, const RasterConfig& raster,
                                                               const std::string& label) const {
  auto err = [&](const std::string& m) { failIn(label, m); };
  StageMap stages;
  for (const ShaderStage& s : in.stages) {
    if (std::string(stageName(s.stage)) == "unsupported")
      err("unsupported shader stage flag " + std::to_string(int(s.stage)));
    if (raster.discard && s.stage == VK_SHADER_STAGE_FRAGMENT_BIT) continue;  // capture ignores fragment
    if (!stages.emplace(s.stage, &s).second) err(std::string("two ") + stageName(s.stage) + " shaders");
    if (s.spirv.size() < 5 || s.spirv[0] != 0x07230203u)
      err(std::string(stageName(s.stage)) + " shader: not a SPIR-V module (missing or bad magic number)");
    if (s.entry.empty()) err(std::string(stageName(s.stage)) + " shader: empty entry point name");
  }
  if (!stages.count(VK_SHADER_STAGE_VERTEX_BIT)) err("a vertex shader is required");
  const bool tesc = stages.count(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT);
  const bool tese = stages.count(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT);
  const bool geom = stages.count(VK_SHADER_STAGE_GEOMETRY_BIT);
  if (tesc != tese) err("tessellation needs both a control and an evaluation shader");
  if ((tesc || tese) && !tessellationShader) err("the device does not support tessellation shaders");
  if (geom && !geometryShader) err("the device does not support geometry shaders");
  const bool patches = in.topology == VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
  if (patches != tesc) err("VK_PRIMITIVE_TOPOLOGY_PATCH_LIST is required exactly when tessellation shaders are given");
  if (patches && (in.patchControlPoints == 0 || in.patchControlPoints > props.limits.maxTessellationPatchSize))
    err("patchControlPoints must be in [1, " + std::to_string(props.limits.maxTessellationPatchSize) + "]");
  if (raster.viewCount > 1 && ((tesc && !multiviewTessellation) || (geom && !multiviewGeometry)))
    err("the device does not support multiview with tessellation/geometry shaders");
  return stages;
}

void VulkanContext::Impl::specialize(const PipelineInputs& in, Specialization* spec, const std::string& label) const {
  std::set<uint32_t> ids;
  for (const SpecConstant& c : in.specConstants) {
    if (!ids.insert(c.constantID).second)
      failIn(label, "specialization constant " + std::to_string(c.constantID) + " given twice");
    spec->entries.push_back({c.constantID, uint32_t(spec->data.size() * 4), 4});
    spec->data.push_back(c.bits);
  }
  spec->info = {uint32_t(spec->entries.size()), spec->entries.data(), spec->data.size() * 4, spec->data.data()};
}

std::vector<VkPipelineShaderStageCreateInfo> VulkanContext::Impl::shaderStages(Scope& scope, const StageMap& stages,
                                                                               const Specialization& spec) {
  const VkDevice dev = device;
  std::vector<VkPipelineShaderStageCreateInfo> stageInfos;
  for (auto& [flag, s] : stages) {
    VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    smci.codeSize = s->spirv.size() * 4;
    smci.pCode = s->spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    VKH_CHECK(vkCreateShaderModule(dev, &smci, nullptr, &module));
    scope.defer([dev, module] { vkDestroyShaderModule(dev, module, nullptr); });
    VkPipelineShaderStageCreateInfo si{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    si.stage = flag;
    si.module = module;
    si.pName = s->entry.c_str();
    si.pSpecializationInfo = spec.entries.empty() ? nullptr : &spec.info;
    stageInfos.push_back(si);
  }
  return stageInfos;
}

VulkanContext::Impl::VertexInput VulkanContext::Impl::vertexInput(Scope& scope, const PipelineInputs& in,
                                                                   BuiltPipeline* out, const std::string& label) {
  const bool indexed = !in.indices.empty();
  if (!indexed && in.vertexCount == 0) failIn(label, "vertexCount is 0 and no indices are given: nothing to draw");
  if (in.instanceCount == 0) failIn(label, "instanceCount is 0: nothing to draw");
  uint32_t maxVertex = indexed ? *std::max_element(in.indices.begin(), in.indices.end()) : in.vertexCount - 1;

  VertexInput input;
  std::set<uint32_t> locations;
  out->vertexBuffer =
      vertexBinding(scope, in.vertices, 0, VK_VERTEX_INPUT_RATE_VERTEX, maxVertex, "vertex", &input, &locations, label);
  if (in.instances)
    out->instanceBuffer = vertexBinding(scope, *in.instances, 1, VK_VERTEX_INPUT_RATE_INSTANCE, in.instanceCount - 1,
                                        "instance", &input, &locations, label);
  if (indexed)
    out->indexBuffer = hostBuffer(scope, in.indices.size() * 4, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, in.indices.data(),
                                  in.indices.size() * 4, "index buffer")
                           .buffer;
  return input;
}

VkBuffer VulkanContext::Impl::vertexBinding(Scope& scope, const VertexBuffer& vb, uint32_t binding,
                                            VkVertexInputRate rate, uint32_t lastElement, const char* what,
                                            VertexInput* input, std::set<uint32_t>* locations,
                                            const std::string& label) {
  auto err = [&](const std::string& m) { failIn(label, m); };
  if (vb.attributes.empty()) {
    if (!vb.bytes.empty()) err(std::string(what) + " buffer has bytes but no attributes");
    return VK_NULL_HANDLE;
  }
  if (vb.stride > props.limits.maxVertexInputBindingStride) err(std::string(what) + " stride too large");
  size_t needed = 0;
  for (const VertexAttribute& a : vb.attributes) {
    if (!locations->insert(a.location).second)
      err("vertex attribute location " + std::to_string(a.location) + " given twice");
    VkFormatProperties fp;
    vkGetPhysicalDeviceFormatProperties(phys, a.format, &fp);
    if (!(fp.bufferFeatures & VK_FORMAT_FEATURE_VERTEX_BUFFER_BIT))
      err("vertex format " + std::to_string(int(a.format)) + " (location " + std::to_string(a.location) +
          ") is not supported as a vertex attribute");
    uint32_t size = vertexFormatSize(a.format);
    if (size && vb.stride && a.offset + size > vb.stride)
      err("attribute at location " + std::to_string(a.location) + " extends past the stride");
    needed = std::max(needed, size_t(lastElement) * vb.stride + a.offset + std::max(size, 1u));
    input->attributes.push_back({a.location, binding, a.format, a.offset});
  }
  if (vb.bytes.size() < needed)
    err(std::string(what) + " buffer too small: " + std::to_string(vb.bytes.size()) + " bytes, the draw reads " +
        std::to_string(needed));
  input->bindings.push_back({binding, vb.stride, rate});
  return hostBuffer(scope, vb.bytes.size(), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, vb.bytes.data(), vb.bytes.size(), what)
      .buffer;
}

VkPipelineLayout VulkanContext::Impl::pipelineLayout(Scope& scope, const PipelineInputs& in,
                                                     const std::vector<VkDescriptorSetLayout>& setLayouts,
                                                     const std::string& label) {
  if (in.pushConstants.size() % 4) failIn(label, "push constant size must be a multiple of 4");
  if (in.pushConstants.size() > props.limits.maxPushConstantsSize)
    failIn(label, "push constants exceed maxPushConstantsSize (" + std::to_string(props.limits.maxPushConstantsSize) + ")");
  VkPushConstantRange pcr{VK_SHADER_STAGE_ALL_GRAPHICS, 0, uint32_t(in.pushConstants.size())};
  VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  plci.setLayoutCount = uint32_t(setLayouts.size());
  plci.pSetLayouts = setLayouts.data();
  plci.pushConstantRangeCount = in.pushConstants.empty() ? 0 : 1;
  plci.pPushConstantRanges = &pcr;
  const VkDevice dev = device;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VKH_CHECK(vkCreatePipelineLayout(dev, &plci, nullptr, &layout));
  scope.defer([dev, layout] { vkDestroyPipelineLayout(dev, layout, nullptr); });
  return layout;
}

struct FixedFunctionState::CreateInfos {
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  VkPipelineRasterizationStateCreateInfo rasterization{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  VkPipelineDepthStencilStateCreateInfo depthStencil{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  VkPipelineColorBlendAttachmentState blendAttachment{};
  VkPipelineColorBlendStateCreateInfo colorBlend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  VkDynamicState dynamicStates[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
};

FixedFunctionState::FixedFunctionState(const Draw* draw, bool discard, bool colourAttachment)
    : infos_(std::make_unique<CreateInfos>()) {
  CreateInfos& s = *infos_;
  s.viewport.viewportCount = 1;
  s.viewport.scissorCount = 1;
  s.rasterization.rasterizerDiscardEnable = discard ? VK_TRUE : VK_FALSE;
  s.rasterization.polygonMode = VK_POLYGON_MODE_FILL;
  s.rasterization.cullMode = VK_CULL_MODE_NONE;
  s.rasterization.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  s.rasterization.lineWidth = 1.f;
  s.multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  if (draw) {
    s.depthStencil.depthTestEnable = draw->depthTest;
    s.depthStencil.depthWriteEnable = draw->depthTest && draw->depthWrite;
    s.depthStencil.depthCompareOp = draw->depthCompare;
    s.blendAttachment.colorWriteMask = draw->colorWrite ? (VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                                           VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT)
                                                        : 0;
    if (draw->alphaBlend) {
      s.blendAttachment.blendEnable = VK_TRUE;
      s.blendAttachment.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
      s.blendAttachment.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
      s.blendAttachment.colorBlendOp = VK_BLEND_OP_ADD;
      s.blendAttachment.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
      s.blendAttachment.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
      s.blendAttachment.alphaBlendOp = VK_BLEND_OP_ADD;
    }
  }
  s.colorBlend.attachmentCount = colourAttachment ? 1 : 0;
  s.colorBlend.pAttachments = &s.blendAttachment;
  s.dynamic.dynamicStateCount = 2;
  s.dynamic.pDynamicStates = s.dynamicStates;
}

FixedFunctionState::~FixedFunctionState() = default;

void FixedFunctionState::applyTo(VkGraphicsPipelineCreateInfo* gci) const {
  gci->pViewportState = &infos_->viewport;
  gci->pRasterizationState = &infos_->rasterization;
  gci->pMultisampleState = &infos_->multisample;
  gci->pDepthStencilState = &infos_->depthStencil;
  gci->pColorBlendState = &infos_->colorBlend;
  gci->pDynamicState = &infos_->dynamic;
}

VkPipeline VulkanContext::Impl::graphicsPipeline(Scope& scope, const PipelineInputs& in, const RasterConfig& raster,
                                                 VkRenderPass renderPass,
                                                 const std::vector<VkPipelineShaderStageCreateInfo>& stages,
                                                 const VertexInput& input, VkPipelineLayout layout,
                                                 const std::string& label) {
  VkPipelineVertexInputStateCreateInfo vis{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vis.vertexBindingDescriptionCount = uint32_t(input.bindings.size());
  vis.pVertexBindingDescriptions = input.bindings.data();
  vis.vertexAttributeDescriptionCount = uint32_t(input.attributes.size());
  vis.pVertexAttributeDescriptions = input.attributes.data();
  VkPipelineInputAssemblyStateCreateInfo ias{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  ias.topology = in.topology;
  VkPipelineTessellationStateCreateInfo ts{VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO};
  ts.patchControlPoints = in.patchControlPoints;
  const FixedFunctionState state(raster.draw, raster.discard, raster.colorAttachment);

  VkGraphicsPipelineCreateInfo gci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  gci.stageCount = uint32_t(stages.size());
  gci.pStages = stages.data();
  gci.pVertexInputState = &vis;
  gci.pInputAssemblyState = &ias;
  gci.pTessellationState = in.topology == VK_PRIMITIVE_TOPOLOGY_PATCH_LIST ? &ts : nullptr;
  state.applyTo(&gci);
  if (!raster.depthAttachment) gci.pDepthStencilState = nullptr;
  gci.layout = layout;
  gci.renderPass = renderPass;
  gci.subpass = 0;
  const VkDevice dev = device;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkResult r = vkCreateGraphicsPipelines(dev, VK_NULL_HANDLE, 1, &gci, nullptr, &pipeline);
  if (r != VK_SUCCESS)
    failIn(label, std::string("vkCreateGraphicsPipelines failed: ") + resultName(r) +
                      " (invalid SPIR-V, an interface mismatch between stages, or a missing device feature)");
  scope.defer([dev, pipeline] { vkDestroyPipeline(dev, pipeline, nullptr); });
  return pipeline;
}

void VulkanContext::Impl::recordBind(VkCommandBuffer cb, const BuiltPipeline& p, const PipelineInputs& in,
                                     uint32_t width, uint32_t height) {
  vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, p.pipeline);
  VkViewport vp{0.f, 0.f, float(width), float(height), 0.f, 1.f};
  VkRect2D sc{{0, 0}, {width, height}};
  vkCmdSetViewport(cb, 0, 1, &vp);
  vkCmdSetScissor(cb, 0, 1, &sc);
  if (!p.sets.empty())
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, p.layout, 0, uint32_t(p.sets.size()), p.sets.data(),
                            0, nullptr);
  if (!in.pushConstants.empty())
    vkCmdPushConstants(cb, p.layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, uint32_t(in.pushConstants.size()),
                       in.pushConstants.data());
  VkDeviceSize zero = 0;
  if (p.vertexBuffer) vkCmdBindVertexBuffers(cb, 0, 1, &p.vertexBuffer, &zero);
  if (p.instanceBuffer) vkCmdBindVertexBuffers(cb, 1, 1, &p.instanceBuffer, &zero);
  if (p.indexBuffer) vkCmdBindIndexBuffer(cb, p.indexBuffer, 0, VK_INDEX_TYPE_UINT32);
}

void VulkanContext::Impl::recordDraw(VkCommandBuffer cb, const BuiltPipeline& p, const PipelineInputs& in) {
  if (p.indexBuffer) {
    vkCmdDrawIndexed(cb, uint32_t(in.indices.size()), in.instanceCount, 0, 0, 0);
  } else {
    vkCmdDraw(cb, in.vertexCount, in.instanceCount, 0, 0);
  }
}

}  // namespace stereoshift::harness
