// The harness's resource phase: device memory, host-visible buffers (vertex, index, uniform,
// staging, read-back), device-local images with their views (attachments and textures, a texture
// filled through a staging copy or a clear), and the one-shot command buffer every call records
// into and waits for. Everything created is registered with the call's Scope, so any error path
// releases it.
#include "transpiler/verify/vk_context_impl.h"

#include <algorithm>
#include <cstring>

namespace stereoshift::harness {

VkResult createImageView(VkDevice device, VkImage image, VkImageViewType type, VkFormat format,
                         const VkImageSubresourceRange& range, VkImageView* view) {
  VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  vci.image = image;
  vci.viewType = type;
  vci.format = format;
  vci.subresourceRange = range;
  return vkCreateImageView(device, &vci, nullptr, view);
}

uint32_t VulkanContext::Impl::memoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                                         VkMemoryPropertyFlags preferred, const char* what) const {
  for (int pass = 0; pass < 2; ++pass) {
    VkMemoryPropertyFlags want = pass == 0 ? (required | preferred) : required;
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
      if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & want) == want) return i;
  }
  fail(std::string("no memory type for ") + what);
}

VkDeviceMemory VulkanContext::Impl::allocateMemory(Scope& scope, const VkMemoryRequirements& req,
                                                   VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred,
                                                   const char* what, VkMemoryAllocateFlags allocateFlags) {
  VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
  flags.flags = allocateFlags;
  if (allocateFlags) mai.pNext = &flags;
  mai.allocationSize = req.size;
  mai.memoryTypeIndex = memoryType(req.memoryTypeBits, required, preferred, what);
  VkDeviceMemory mem = VK_NULL_HANDLE;
  VKH_CHECK(vkAllocateMemory(device, &mai, nullptr, &mem));
  scope.deferFree(mem);
  return mem;
}

namespace {

// Replaces every placeholder in `bytes` by the address it names.
void patchAddresses(std::vector<uint8_t>& bytes, const std::vector<VkDeviceAddress>& addresses, const std::string& label) {
  for (size_t at = 0; at + 8 <= bytes.size(); at += 8) {
    uint64_t value = 0;
    std::memcpy(&value, bytes.data() + at, 8);
    if ((value & 0xFFFFFFFF00000000ull) != kAddressPlaceholderTag) continue;
    const uint64_t index = value & 0xFFFFFFFFull;
    if (index >= addresses.size()) failIn(label, "address placeholder " + std::to_string(index) + " names no address buffer");
    std::memcpy(bytes.data() + at, &addresses[index], 8);
  }
}

}  // namespace

const PipelineInputs& VulkanContext::Impl::resolveAddresses(Scope& scope, const PipelineInputs& in,
                                                            PipelineInputs* resolved, const std::string& label) {
  if (in.addressBuffers.empty()) return in;
  if (!bufferDeviceAddress)
    failIn(label, "the shader reads memory through buffer device addresses and the device lacks bufferDeviceAddress");
  *resolved = in;
  std::vector<VkDeviceAddress> addresses;
  std::vector<HostBuffer> buffers;
  for (const auto& bytes : in.addressBuffers) {
    HostBuffer b = hostBuffer(scope, std::max<VkDeviceSize>(bytes.size(), 16),
                              VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, nullptr, 0,
                              "address buffer", VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT);
    VkBufferDeviceAddressInfo bai{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
    bai.buffer = b.buffer;
    addresses.push_back(vkGetBufferDeviceAddress(device, &bai));
    buffers.push_back(b);
  }
  patchAddresses(resolved->pushConstants, addresses, label);
  for (auto& u : resolved->uniformBuffers) patchAddresses(u.bytes, addresses, label);
  for (size_t i = 0; i < buffers.size(); ++i) {
    std::vector<uint8_t> bytes = in.addressBuffers[i];
    patchAddresses(bytes, addresses, label);
    std::memcpy(buffers[i].mapped, bytes.data(), bytes.size());
  }
  resolved->addressBuffers.clear();
  return *resolved;
}

HostBuffer VulkanContext::Impl::hostBuffer(Scope& scope, VkDeviceSize size, VkBufferUsageFlags usage,
                                           const void* init, size_t initSize, const char* what,
                                           VkMemoryAllocateFlags allocateFlags) {
  HostBuffer b;
  b.size = std::max<VkDeviceSize>(size, 4);
  VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  bci.size = b.size;
  bci.usage = usage;
  bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VKH_CHECK(vkCreateBuffer(device, &bci, nullptr, &b.buffer));
  VkDevice dev = device;
  VkBuffer buf = b.buffer;
  scope.defer([dev, buf] { vkDestroyBuffer(dev, buf, nullptr); });

  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device, b.buffer, &req);
  VkDeviceMemory mem = allocateMemory(scope, req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                      0, what, allocateFlags);
  VKH_CHECK(vkBindBufferMemory(device, b.buffer, mem, 0));
  VKH_CHECK(vkMapMemory(device, mem, 0, VK_WHOLE_SIZE, 0, &b.mapped));
  std::memset(b.mapped, 0, size_t(b.size));
  if (init && initSize) std::memcpy(b.mapped, init, std::min<size_t>(initSize, size_t(b.size)));
  return b;
}

void VulkanContext::Impl::requireFormat(VkFormat format, VkFormatFeatureFlags optimalFeatures, const char* what) const {
  VkFormatProperties fp;
  vkGetPhysicalDeviceFormatProperties(phys, format, &fp);
  if ((fp.optimalTilingFeatures & optimalFeatures) != optimalFeatures)
    fail(std::string(what) + ": format " + std::to_string(int(format)) +
         " lacks the required optimal-tiling features on this device");
}

Image VulkanContext::Impl::deviceImage(Scope& scope, const VkImageCreateInfo& ici, VkImageViewType viewType,
                                       VkImageAspectFlags aspect, const char* what) {
  Image img;
  VKH_CHECK(vkCreateImage(device, &ici, nullptr, &img.image));
  VkDevice dev = device;
  VkImage im = img.image;
  scope.defer([dev, im] { vkDestroyImage(dev, im, nullptr); });

  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device, img.image, &req);
  VkDeviceMemory mem = allocateMemory(scope, req, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, what);
  VKH_CHECK(vkBindImageMemory(device, img.image, mem, 0));

  VKH_CHECK(createImageView(device, img.image, viewType, ici.format, {aspect, 0, 1, 0, ici.arrayLayers}, &img.view));
  VkImageView view = img.view;
  scope.defer([dev, view] { vkDestroyImageView(dev, view, nullptr); });
  return img;
}

VkImageCreateInfo imageInfo2D(VkFormat format, uint32_t width, uint32_t height, uint32_t layers, VkImageUsageFlags usage) {
  VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  ici.imageType = VK_IMAGE_TYPE_2D;
  ici.format = format;
  ici.extent = {width, height, 1};
  ici.mipLevels = 1;
  ici.arrayLayers = layers;
  ici.samples = VK_SAMPLE_COUNT_1_BIT;
  ici.tiling = VK_IMAGE_TILING_OPTIMAL;
  ici.usage = usage;
  ici.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  return ici;
}

Image VulkanContext::Impl::image2D(Scope& scope, VkFormat format, uint32_t w, uint32_t h, uint32_t layers,
                                   VkImageUsageFlags usage, VkImageAspectFlags aspect, const char* what) {
  return deviceImage(scope, imageInfo2D(format, w, h, layers, usage),
                     layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D, aspect, what);
}

Image VulkanContext::Impl::textureImage(Scope& scope, VkCommandBuffer uploads, const SampledTexture& t,
                                       uint32_t element, const std::string& where) {
  const bool storage = t.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  const bool cube = t.viewType == VK_IMAGE_VIEW_TYPE_CUBE || t.viewType == VK_IMAGE_VIEW_TYPE_CUBE_ARRAY;
  const bool volume = t.viewType == VK_IMAGE_VIEW_TYPE_3D;
  const bool line = t.viewType == VK_IMAGE_VIEW_TYPE_1D || t.viewType == VK_IMAGE_VIEW_TYPE_1D_ARRAY;
  const std::string what = "texture " + where;
  if (t.width == 0 || t.height == 0 || t.depth == 0 || t.layers == 0) fail(what + " has zero size");
  if (t.width > props.limits.maxImageDimension2D || t.height > props.limits.maxImageDimension2D)
    fail(what + " exceeds maxImageDimension2D");
  if (cube && (t.width != t.height || t.layers % 6)) fail(what + ": a cube needs square faces and 6 layers per cube");
  if (volume && t.layers != 1) fail(what + ": a 3D image has one layer");
  if (line && t.height != 1) fail(what + ": a 1D image has height 1");
  const size_t texels = t.texelsPerElement();
  if (t.rgba.size() != texels * 4 * t.arrayCount)
    fail(what + ": rgba has " + std::to_string(t.rgba.size()) + " values, expected width*height*depth*layers*4*arrayCount = " +
         std::to_string(texels * 4 * t.arrayCount));
  requireFormat(t.format,
                (storage ? VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT : VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT) |
                    VK_FORMAT_FEATURE_TRANSFER_DST_BIT,
                what.c_str());
  VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  ici.flags = cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
  ici.imageType = volume ? VK_IMAGE_TYPE_3D : line ? VK_IMAGE_TYPE_1D : VK_IMAGE_TYPE_2D;
  ici.format = t.format;
  ici.extent = {t.width, t.height, t.depth};
  ici.mipLevels = 1;
  ici.arrayLayers = t.layers;
  ici.samples = VK_SAMPLE_COUNT_1_BIT;
  ici.tiling = VK_IMAGE_TILING_OPTIMAL;
  ici.usage = (storage ? VK_IMAGE_USAGE_STORAGE_BIT : VK_IMAGE_USAGE_SAMPLED_BIT) | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  ici.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  Image img = deviceImage(scope, ici, t.viewType, VK_IMAGE_ASPECT_COLOR_BIT, what.c_str());

  VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = img.image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, t.layers};
  vkCmdPipelineBarrier(uploads, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                       nullptr, 1, &b);
  const float* texels0 = t.rgba.data() + texels * 4 * element;
  const bool fourChannel32 = t.format == VK_FORMAT_R32G32B32A32_SFLOAT || t.format == VK_FORMAT_R32G32B32A32_SINT ||
                             t.format == VK_FORMAT_R32G32B32A32_UINT;
  if (fourChannel32) {
    HostBuffer staging = hostBuffer(scope, texels * 16, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, texels0, texels * 16,
                                    "texture staging");
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, t.layers};
    copy.imageExtent = {t.width, t.height, t.depth};
    vkCmdCopyBufferToImage(uploads, staging.buffer, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
  } else {  // any other format: one value everywhere, converted by the clear
    VkClearColorValue value;
    std::memcpy(&value, texels0, 16);
    vkCmdClearColorImage(uploads, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &value, 1, &b.subresourceRange);
  }
  b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  b.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | (storage ? VK_ACCESS_SHADER_WRITE_BIT : 0);
  b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  b.newLayout = storage ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  vkCmdPipelineBarrier(uploads, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT, 0, 0, nullptr, 0,
                       nullptr, 1, &b);
  return img;
}

VkCommandBuffer VulkanContext::Impl::beginCommands(Scope& scope) {
  VkCommandBufferAllocateInfo cai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  cai.commandPool = commandPool;
  cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cai.commandBufferCount = 1;
  VkCommandBuffer cb = VK_NULL_HANDLE;
  VKH_CHECK(vkAllocateCommandBuffers(device, &cai, &cb));
  VkDevice dev = device;
  VkCommandPool pool = commandPool;
  scope.defer([dev, pool, cb] { vkFreeCommandBuffers(dev, pool, 1, &cb); });
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VKH_CHECK(vkBeginCommandBuffer(cb, &bi));
  return cb;
}

void VulkanContext::Impl::submitAndWait(Scope& scope, VkCommandBuffer cb) {
  VKH_CHECK(vkEndCommandBuffer(cb));
  VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  VKH_CHECK(vkCreateFence(device, &fci, nullptr, &fence));
  VkDevice dev = device;
  scope.defer([dev, fence] { vkDestroyFence(dev, fence, nullptr); });
  VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  si.commandBufferCount = 1;
  si.pCommandBuffers = &cb;
  VKH_CHECK(vkQueueSubmit(queue, 1, &si, fence));
  VkResult r = vkWaitForFences(device, 1, &fence, VK_TRUE, 60ull * 1000 * 1000 * 1000);
  if (r == VK_TIMEOUT) fail("GPU work did not finish within 60 s");
  VKH_CHECK(r);
}

}  // namespace stereoshift::harness
