// The harness's capture() call: a pipeline with rasterizer discard in a render pass without
// attachments, its last pre-rasterization stage writing through transform feedback into a buffer
// pre-filled with 0xCD, the stream query counting the primitives written and needed, and the
// bytes the counter buffer says were written, read back.
#include "transpiler/verify/vk_context_impl.h"

#include <cstring>

namespace stereoshift::harness {
namespace {

// The limits of the request against the device's transform-feedback properties.
void checkCaptureRequest(const CaptureRequest& req, const VkPhysicalDeviceTransformFeedbackPropertiesEXT& xfbProps) {
  if (req.xfbStride == 0 || req.xfbStride % 4)
    fail("capture: xfbStride must be a non-zero multiple of 4 (got " + std::to_string(req.xfbStride) + ")");
  if (req.xfbStride > xfbProps.maxTransformFeedbackBufferDataStride)
    fail("capture: xfbStride " + std::to_string(req.xfbStride) + " exceeds maxTransformFeedbackBufferDataStride " +
         std::to_string(xfbProps.maxTransformFeedbackBufferDataStride));
  if (req.expectedVertices == 0) fail("capture: expectedVertices is 0");
  const VkDeviceSize capacity = VkDeviceSize(req.expectedVertices) * req.xfbStride;
  if (capacity > xfbProps.maxTransformFeedbackBufferSize) fail("capture: buffer exceeds maxTransformFeedbackBufferSize");
}

// A render pass without attachments (rasterizer discard) and its 1x1 framebuffer.
VkRenderPass discardRenderPass(VkDevice dev, Scope& scope, VkFramebuffer* framebuffer) {
  VkSubpassDescription sub{};
  sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  VkRenderPassCreateInfo rpci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  rpci.subpassCount = 1;
  rpci.pSubpasses = &sub;
  VkRenderPass rp = VK_NULL_HANDLE;
  VKH_CHECK(vkCreateRenderPass(dev, &rpci, nullptr, &rp));
  scope.defer([dev, rp] { vkDestroyRenderPass(dev, rp, nullptr); });
  VkFramebufferCreateInfo fci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fci.renderPass = rp;
  fci.width = fci.height = fci.layers = 1;
  VkFramebuffer fb = VK_NULL_HANDLE;
  VKH_CHECK(vkCreateFramebuffer(dev, &fci, nullptr, &fb));
  scope.defer([dev, fb] { vkDestroyFramebuffer(dev, fb, nullptr); });
  *framebuffer = fb;
  return rp;
}

}  // namespace

void VulkanContext::Impl::capture(const CaptureRequest& req, CaptureResult& out) {
  out.stride = req.xfbStride;
  checkCaptureRequest(req, xfbProps);
  const VkDeviceSize capacity = VkDeviceSize(req.expectedVertices) * req.xfbStride;

  const VkDevice dev = device;
  Scope scope(dev);
  VkCommandBuffer cb = beginCommands(scope);
  VkFramebuffer fb = VK_NULL_HANDLE;
  VkRenderPass rp = discardRenderPass(dev, scope, &fb);

  RasterConfig raster;
  raster.discard = true;
  PipelineInputs withAddresses;
  const PipelineInputs& in = resolveAddresses(scope, req.pipeline, &withAddresses, "capture");
  BuiltPipeline p = buildPipeline(scope, cb, in, rp, raster, "capture");

  // Capture buffer pre-filled with 0xCD so that unwritten bytes are recognizable; counter buffer.
  HostBuffer xfb = hostBuffer(scope, capacity, VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT, nullptr, 0,
                              "transform feedback buffer");
  std::memset(xfb.mapped, 0xCD, size_t(capacity));
  HostBuffer counter = hostBuffer(scope, 4, VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_COUNTER_BUFFER_BIT_EXT, nullptr, 0,
                                  "transform feedback counter buffer");

  VkQueryPool qp = VK_NULL_HANDLE;
  const bool query = xfbProps.transformFeedbackQueries;
  if (query) {
    VkQueryPoolCreateInfo qci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    qci.queryType = VK_QUERY_TYPE_TRANSFORM_FEEDBACK_STREAM_EXT;
    qci.queryCount = 1;
    VKH_CHECK(vkCreateQueryPool(dev, &qci, nullptr, &qp));
    scope.defer([dev, qp] { vkDestroyQueryPool(dev, qp, nullptr); });
    vkCmdResetQueryPool(cb, qp, 0, 1);
  }

  VkRenderPassBeginInfo rbi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  rbi.renderPass = rp;
  rbi.framebuffer = fb;
  rbi.renderArea = {{0, 0}, {1, 1}};
  vkCmdBeginRenderPass(cb, &rbi, VK_SUBPASS_CONTENTS_INLINE);
  recordBind(cb, p, in, 1, 1);
  VkDeviceSize zero = 0, size = capacity;
  cmdBindXfbBuffers(cb, 0, 1, &xfb.buffer, &zero, &size);
  if (query) cmdBeginQueryIndexed(cb, qp, 0, 0, 0);
  cmdBeginXfb(cb, 0, 0, nullptr, nullptr);  // no counter buffer: start writing at offset 0
  recordDraw(cb, p, in);
  cmdEndXfb(cb, 0, 1, &counter.buffer, &zero);  // the counter receives the bytes written
  if (query) cmdEndQueryIndexed(cb, qp, 0, 0);
  vkCmdEndRenderPass(cb);

  VkMemoryBarrier mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  mb.srcAccessMask = VK_ACCESS_TRANSFORM_FEEDBACK_WRITE_BIT_EXT | VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_WRITE_BIT_EXT;
  mb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &mb, 0,
                       nullptr, 0, nullptr);
  submitAndWait(scope, cb);

  if (query) {
    uint64_t q[2] = {0, 0};
    VKH_CHECK(vkGetQueryPoolResults(dev, qp, 0, 1, sizeof(q), q, sizeof(q),
                                    VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    out.primitivesWritten = q[0];
    out.primitivesNeeded = q[1];
  } else {
    out.primitivesWritten = out.primitivesNeeded = ~uint64_t(0);  // unknown
  }
  uint32_t written = 0;
  std::memcpy(&written, counter.mapped, 4);
  if (written > capacity) written = uint32_t(capacity);
  out.bytes.assign(static_cast<const uint8_t*>(xfb.mapped), static_cast<const uint8_t*>(xfb.mapped) + written);
}

}  // namespace stereoshift::harness
