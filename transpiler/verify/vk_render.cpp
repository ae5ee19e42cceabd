// The harness's render() call: a colour (RGBA8) and depth (D32) target of one or more layers, the
// render pass they are drawn in (multiview when the request has several views), one pipeline per
// draw recorded in order, GPU timestamps around the render pass, and the read-back of the pixels
// (and the depth when asked for). The render pass is public (createColourDepthRenderPass) for the
// benchmarks that record their own frames.
#include "transpiler/verify/vk_context_impl.h"

#include <cstring>

namespace stereoshift::harness {

// See vk_harness.h: the render pass of render(), also for callers that record their own frames.
VkResult createColourDepthRenderPass(VkDevice device, VkFormat colourFormat, VkFormat depthFormat, uint32_t viewMask,
                                     bool keepDepth, VkRenderPass* renderPass) {
  VkAttachmentDescription att[2]{};
  att[0].format = colourFormat;
  att[0].samples = VK_SAMPLE_COUNT_1_BIT;
  att[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  att[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  att[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  att[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  att[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  att[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  att[1] = att[0];
  att[1].format = depthFormat;
  att[1].storeOp = keepDepth ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
  att[1].finalLayout = keepDepth ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription sub{};
  sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  sub.colorAttachmentCount = 1;
  sub.pColorAttachments = &colorRef;
  sub.pDepthStencilAttachment = &depthRef;
  const VkPipelineStageFlags attachmentStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  const VkAccessFlags attachmentAccess = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                                         VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                         VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
  VkSubpassDependency deps[2]{};
  deps[0] = {VK_SUBPASS_EXTERNAL, 0, attachmentStages, attachmentStages, 0, attachmentAccess, 0};
  deps[1] = {0,
             VK_SUBPASS_EXTERNAL,
             attachmentStages,
             VK_PIPELINE_STAGE_TRANSFER_BIT,
             VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
             VK_ACCESS_TRANSFER_READ_BIT,
             0};
  VkRenderPassMultiviewCreateInfo mvci{VK_STRUCTURE_TYPE_RENDER_PASS_MULTIVIEW_CREATE_INFO};
  mvci.subpassCount = 1;
  mvci.pViewMasks = &viewMask;
  mvci.correlationMaskCount = 1;
  mvci.pCorrelationMasks = &viewMask;  // the views (eyes) see nearly the same: the hint multiview is for
  VkRenderPassCreateInfo rpci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  if (viewMask) rpci.pNext = &mvci;
  rpci.attachmentCount = 2;
  rpci.pAttachments = att;
  rpci.subpassCount = 1;
  rpci.pSubpasses = &sub;
  rpci.dependencyCount = 2;
  rpci.pDependencies = deps;
  return vkCreateRenderPass(device, &rpci, nullptr, renderPass);
}

namespace {

constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM, kDepthFormat = VK_FORMAT_D32_SFLOAT;

// The attachments of one render() call, its render pass and framebuffer.
struct RenderTarget {
  Image color, depth;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  uint32_t layers = 1;
};

void checkRenderRequest(const RenderRequest& req, const VulkanContext::Impl& impl, bool useMultiview) {
  if (req.width == 0 || req.height == 0) fail("render: width and height must be non-zero");
  if (req.width > impl.props.limits.maxFramebufferWidth || req.height > impl.props.limits.maxFramebufferHeight)
    fail("render: target larger than maxFramebufferWidth/Height");
  if (req.viewCount == 0) fail("render: viewCount must be >= 1");
  if (useMultiview && !impl.multiview) fail("render: multiview is not supported by the device");
  if (useMultiview && req.viewCount > impl.maxMultiviewViewCount)
    fail("render: viewCount exceeds maxMultiviewViewCount " + std::to_string(impl.maxMultiviewViewCount));
  if (req.draws.empty()) fail("render: no draws");
}

RenderTarget renderTarget(VulkanContext::Impl& impl, Scope& scope, const RenderRequest& req, bool useMultiview) {
  const VkDevice dev = impl.device;
  RenderTarget target;
  target.layers = req.viewCount;
  target.color = impl.image2D(scope, kColorFormat, req.width, req.height, target.layers,
                              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              VK_IMAGE_ASPECT_COLOR_BIT, "colour target");
  target.depth = impl.image2D(scope, kDepthFormat, req.width, req.height, target.layers,
                              VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              VK_IMAGE_ASPECT_DEPTH_BIT, "depth target");

  const uint32_t viewMask = (target.layers >= 32) ? ~0u : ((1u << target.layers) - 1u);
  VkRenderPass rp = VK_NULL_HANDLE;
  VKH_CHECK(createColourDepthRenderPass(dev, kColorFormat, kDepthFormat, useMultiview ? viewMask : 0, req.readDepth, &rp));
  scope.defer([dev, rp] { vkDestroyRenderPass(dev, rp, nullptr); });
  target.renderPass = rp;

  VkImageView views[2] = {target.color.view, target.depth.view};
  VkFramebufferCreateInfo fci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fci.renderPass = rp;
  fci.attachmentCount = 2;
  fci.pAttachments = views;
  fci.width = req.width;
  fci.height = req.height;
  fci.layers = useMultiview ? 1 : target.layers;  // multiview: must be 1
  VkFramebuffer fb = VK_NULL_HANDLE;
  VKH_CHECK(vkCreateFramebuffer(dev, &fci, nullptr, &fb));
  scope.defer([dev, fb] { vkDestroyFramebuffer(dev, fb, nullptr); });
  target.framebuffer = fb;
  return target;
}

// A two-timestamp query pool, reset and its first timestamp written into `cb`.
VkQueryPool startTimer(VkDevice dev, Scope& scope, VkCommandBuffer cb) {
  VkQueryPoolCreateInfo tci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  tci.queryType = VK_QUERY_TYPE_TIMESTAMP;
  tci.queryCount = 2;
  VkQueryPool timer = VK_NULL_HANDLE;
  VKH_CHECK(vkCreateQueryPool(dev, &tci, nullptr, &timer));
  scope.defer([dev, timer] { vkDestroyQueryPool(dev, timer, nullptr); });
  vkCmdResetQueryPool(cb, timer, 0, 2);
  vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timer, 0);
  return timer;
}

// The colour layers (and the depth) copied into the read-back buffers, made visible to the host.
void recordReadback(VkCommandBuffer cb, const RenderTarget& target, const RenderRequest& req, const HostBuffer& colorOut,
                    const HostBuffer& depthOut) {
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, target.layers};
  copy.imageExtent = {req.width, req.height, 1};
  vkCmdCopyImageToBuffer(cb, target.color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, colorOut.buffer, 1, &copy);
  if (req.readDepth) {
    copy.imageSubresource.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
    vkCmdCopyImageToBuffer(cb, target.depth.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, depthOut.buffer, 1, &copy);
  }
  VkMemoryBarrier mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  mb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  mb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &mb, 0, nullptr, 0,
                       nullptr);
}

}  // namespace

void VulkanContext::Impl::render(const RenderRequest& req, RenderResult& out) {
  out.width = req.width;
  out.height = req.height;
  out.viewCount = req.viewCount;
  const bool useMultiview = req.viewCount > 1 && !req.layeredWithoutMultiview;
  checkRenderRequest(req, *this, useMultiview);

  const VkDevice dev = device;
  requireFormat(kColorFormat, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT,
                "colour target");
  requireFormat(kDepthFormat,
                VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | (req.readDepth ? VK_FORMAT_FEATURE_TRANSFER_SRC_BIT : 0),
                "depth target");
  Scope scope(dev);
  VkCommandBuffer cb = beginCommands(scope);
  const RenderTarget target = renderTarget(*this, scope, req, useMultiview);
  const uint32_t layers = target.layers;

  std::vector<BuiltPipeline> pipelines;
  std::vector<PipelineInputs> withAddresses(req.draws.size());
  std::vector<const PipelineInputs*> inputs;
  for (size_t i = 0; i < req.draws.size(); ++i)
    inputs.push_back(&resolveAddresses(scope, req.draws[i].pipeline, &withAddresses[i], "render draw " + std::to_string(i)));
  for (size_t i = 0; i < req.draws.size(); ++i) {
    RasterConfig raster;
    raster.colorAttachment = raster.depthAttachment = true;
    raster.draw = &req.draws[i];
    raster.viewCount = useMultiview ? layers : 1;
    pipelines.push_back(
        buildPipeline(scope, cb, *inputs[i], target.renderPass, raster, "render draw " + std::to_string(i)));
  }

  const VkDeviceSize pixelBytes = VkDeviceSize(req.width) * req.height * 4 * layers;
  HostBuffer colorOut = hostBuffer(scope, pixelBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, nullptr, 0, "colour readback");
  HostBuffer depthOut;
  if (req.readDepth)
    depthOut = hostBuffer(scope, pixelBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, nullptr, 0, "depth readback");

  VkClearValue clears[2];
  std::memcpy(clears[0].color.float32, req.clearColor, sizeof(req.clearColor));
  clears[1].depthStencil = {req.clearDepth, 0};
  VkRenderPassBeginInfo rbi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  rbi.renderPass = target.renderPass;
  rbi.framebuffer = target.framebuffer;
  rbi.renderArea = {{0, 0}, {req.width, req.height}};
  rbi.clearValueCount = 2;
  rbi.pClearValues = clears;
  // GPU timestamps around the render pass: the draws' own time, without the pipeline creation and
  // uploads a render() call also does (benchmarks compare these).
  VkQueryPool timer = timestamps ? startTimer(dev, scope, cb) : VK_NULL_HANDLE;
  vkCmdBeginRenderPass(cb, &rbi, VK_SUBPASS_CONTENTS_INLINE);
  for (size_t i = 0; i < req.draws.size(); ++i) {
    recordBind(cb, pipelines[i], *inputs[i], req.width, req.height);
    recordDraw(cb, pipelines[i], *inputs[i]);
  }
  vkCmdEndRenderPass(cb);
  if (timestamps) vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timer, 1);
  recordReadback(cb, target, req, colorOut, depthOut);
  submitAndWait(scope, cb);

  if (timestamps) {
    uint64_t ticks[2] = {0, 0};
    if (vkGetQueryPoolResults(device, timer, 0, 2, sizeof ticks, ticks, sizeof(uint64_t),
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS && ticks[1] >= ticks[0])
      out.drawMilliseconds = double(ticks[1] - ticks[0]) * props.limits.timestampPeriod * 1e-6;
  }
  const auto* c = static_cast<const uint8_t*>(colorOut.mapped);
  out.pixels.assign(c, c + pixelBytes);
  if (req.readDepth) {
    out.depth.resize(size_t(req.width) * req.height * layers);
    std::memcpy(out.depth.data(), depthOut.mapped, out.depth.size() * 4);
  }
}

}  // namespace stereoshift::harness
