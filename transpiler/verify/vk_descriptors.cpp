// The harness's descriptor phase of pipeline construction: the reflection-free layout of the
// resources a caller lists (buildDescriptorLayout, public for tests), the set layouts and the pool
// made from it, and one write per slot — uniform and storage buffers, texel buffers, images and
// samplers — with every resource behind them created and uploaded.
#include "transpiler/verify/vk_context_impl.h"

#include <algorithm>

namespace stereoshift::harness {

bool buildDescriptorLayout(const PipelineInputs& in, std::vector<std::vector<DescriptorSlot>>* sets,
                           std::string* error) {
  std::map<uint32_t, std::map<uint32_t, DescriptorSlot>> bySet;
  auto add = [&](uint32_t set, uint32_t binding, VkDescriptorType type, uint32_t index, const char* what,
                 uint32_t count) {
    auto& slots = bySet[set];
    if (slots.count(binding)) {
      if (error)
        *error = std::string("duplicate descriptor (set ") + std::to_string(set) + ", binding " +
                 std::to_string(binding) + ") given by " + what + " " + std::to_string(index);
      return false;
    }
    slots[binding] = DescriptorSlot{binding, type, index, std::max(count, 1u)};
    return true;
  };
  for (uint32_t i = 0; i < in.uniformBuffers.size(); ++i)
    if (!add(in.uniformBuffers[i].set, in.uniformBuffers[i].binding,
             in.uniformBuffers[i].storage ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, i,
             "uniform buffer", in.uniformBuffers[i].arrayCount))
      return false;
  for (uint32_t i = 0; i < in.textures.size(); ++i)
    if (!add(in.textures[i].set, in.textures[i].binding, in.textures[i].type, i, "texture",
             in.textures[i].arrayCount))
      return false;
  sets->clear();
  if (bySet.empty()) return true;
  sets->resize(bySet.rbegin()->first + 1);
  for (auto& [set, slots] : bySet)
    for (auto& [binding, slot] : slots) (*sets)[set].push_back(slot);
  return true;
}

namespace {

bool isBufferDescriptor(VkDescriptorType type) {
  return type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}
bool isTexelBufferDescriptor(VkDescriptorType type) {
  return type == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER || type == VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
}

// How many descriptors of each type the sets hold: the pool's sizes, and the room the writes'
// infos need (reserved up front so that their addresses stay valid).
struct DescriptorCounts {
  std::map<VkDescriptorType, uint32_t> byType;
  uint32_t buffers = 0, images = 0, texelBuffers = 0;
};

// The writes of every slot, and the resources they point at (created in `scope`).
class DescriptorWriter {
 public:
  DescriptorWriter(VulkanContext::Impl& impl, Scope& scope, VkCommandBuffer uploads, const DescriptorCounts& counts,
                   const std::string& label)
      : impl_(impl), scope_(scope), uploads_(uploads), label_(label) {
    bufferInfos_.reserve(counts.buffers);
    imageInfos_.reserve(counts.images);
    texelViews_.reserve(counts.texelBuffers);
  }

  void write(const PipelineInputs& in, VkDescriptorSet set, uint32_t setIndex, const DescriptorSlot& s) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = s.binding;
    w.descriptorCount = s.count;
    w.descriptorType = s.type;
    std::string where = "(set " + std::to_string(setIndex) + ", binding " + std::to_string(s.binding) + ")";
    if (isBufferDescriptor(s.type)) {
      w.pBufferInfo = buffers(in.uniformBuffers[s.resourceIndex], s, where);
    } else if (isTexelBufferDescriptor(s.type)) {
      w.pTexelBufferView = texelBuffers(in.textures[s.resourceIndex], s, where);
    } else {
      w.pImageInfo = images(in.textures[s.resourceIndex], s, where);
    }
    writes_.push_back(w);
  }

  void flush() {
    if (!writes_.empty()) vkUpdateDescriptorSets(impl_.device, uint32_t(writes_.size()), writes_.data(), 0, nullptr);
  }

 private:
  // One buffer per element of a uniform or storage buffer (array).
  const VkDescriptorBufferInfo* buffers(const UniformBuffer& u, const DescriptorSlot& s, const std::string& where) {
    if (u.bytes.empty()) failIn(label_, "uniform buffer " + where + " is empty");
    if (u.bytes.size() % s.count)
      failIn(label_, "uniform buffer array " + where + ": bytes do not split into equal elements");
    const size_t elementSize = u.bytes.size() / s.count;
    if (!u.storage && elementSize > impl_.props.limits.maxUniformBufferRange)
      failIn(label_, "uniform buffer " + where + " exceeds maxUniformBufferRange");
    size_t first = bufferInfos_.size();
    for (uint32_t e = 0; e < s.count; ++e) {
      HostBuffer hb = impl_.hostBuffer(scope_, elementSize,
                                       u.storage ? VK_BUFFER_USAGE_STORAGE_BUFFER_BIT : VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                       u.bytes.data() + e * elementSize, elementSize, "uniform buffer");
      bufferInfos_.push_back({hb.buffer, 0, elementSize});
    }
    return &bufferInfos_[first];
  }

  // One buffer and view per element of a uniform or storage texel buffer (array).
  const VkBufferView* texelBuffers(const SampledTexture& t, const DescriptorSlot& s, const std::string& where) {
    const bool storageTexels = s.type == VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
    if (t.width == 0) failIn(label_, "texel buffer " + where + " has zero texels");
    if (t.rgba.size() != size_t(t.width) * 4 * s.count)
      failIn(label_, "texel buffer " + where + ": rgba must hold width*4 values per element");
    VkFormatProperties fp;
    vkGetPhysicalDeviceFormatProperties(impl_.phys, t.format, &fp);
    VkFormatFeatureFlags need = storageTexels ? VK_FORMAT_FEATURE_STORAGE_TEXEL_BUFFER_BIT
                                              : VK_FORMAT_FEATURE_UNIFORM_TEXEL_BUFFER_BIT;
    if (!(fp.bufferFeatures & need)) failIn(label_, "texel buffer " + where + ": format not supported for texel buffers");
    const VkDevice dev = impl_.device;
    size_t first = texelViews_.size();
    for (uint32_t e = 0; e < s.count; ++e) {
      HostBuffer hb = impl_.hostBuffer(scope_, size_t(t.width) * 16,
                                       storageTexels ? VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT
                                                     : VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                                       t.rgba.data() + size_t(e) * t.width * 4, size_t(t.width) * 16, "texel buffer");
      VkBufferViewCreateInfo bvci{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
      bvci.buffer = hb.buffer;
      bvci.format = t.format;
      bvci.range = VK_WHOLE_SIZE;
      VkBufferView view = VK_NULL_HANDLE;
      VKH_CHECK(vkCreateBufferView(dev, &bvci, nullptr, &view));
      scope_.defer([dev, view] { vkDestroyBufferView(dev, view, nullptr); });
      texelViews_.push_back(view);
    }
    return &texelViews_[first];
  }

  // Images (sampled, storage, combined with a sampler) and samplers, one per element.
  const VkDescriptorImageInfo* images(const SampledTexture& t, const DescriptorSlot& s, const std::string& where) {
    size_t first = imageInfos_.size();
    for (uint32_t e = 0; e < s.count; ++e) {
      VkDescriptorImageInfo info{};
      if (s.type == VK_DESCRIPTOR_TYPE_SAMPLER || s.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER)
        info.sampler = sharedSampler();
      if (s.type != VK_DESCRIPTOR_TYPE_SAMPLER) {
        info.imageView = impl_.textureImage(scope_, uploads_, t, e, where).view;
        info.imageLayout = s.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE ? VK_IMAGE_LAYOUT_GENERAL
                                                                      : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
      }
      imageInfos_.push_back(info);
    }
    return &imageInfos_[first];
  }

  // One nearest clamp-to-edge sampler serves every descriptor.
  VkSampler sharedSampler() {
    if (sampler_) return sampler_;
    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = sci.minFilter = VK_FILTER_NEAREST;
    sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sci.maxLod = 0.f;
    sci.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    const VkDevice dev = impl_.device;
    VKH_CHECK(vkCreateSampler(dev, &sci, nullptr, &sampler_));
    VkSampler made = sampler_;
    scope_.defer([dev, made] { vkDestroySampler(dev, made, nullptr); });
    return sampler_;
  }

  VulkanContext::Impl& impl_;
  Scope& scope_;
  VkCommandBuffer uploads_;
  const std::string& label_;
  std::vector<VkDescriptorBufferInfo> bufferInfos_;
  std::vector<VkDescriptorImageInfo> imageInfos_;
  std::vector<VkBufferView> texelViews_;
  std::vector<VkWriteDescriptorSet> writes_;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

// One set layout per descriptor set of `layoutSets`; `counts` receives what the sets hold.
std::vector<VkDescriptorSetLayout> createSetLayouts(VkDevice dev, Scope& scope,
                                                    const std::vector<std::vector<DescriptorSlot>>& layoutSets,
                                                    DescriptorCounts* counts) {
  std::vector<VkDescriptorSetLayout> setLayouts;
  for (auto& slots : layoutSets) {
    std::vector<VkDescriptorSetLayoutBinding> b;
    for (const DescriptorSlot& s : slots) {
      b.push_back({s.binding, s.type, s.count, VK_SHADER_STAGE_ALL_GRAPHICS, nullptr});
      counts->byType[s.type] += s.count;
      (isBufferDescriptor(s.type) ? counts->buffers : isTexelBufferDescriptor(s.type) ? counts->texelBuffers
                                                                                        : counts->images) += s.count;
    }
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = uint32_t(b.size());
    lci.pBindings = b.data();
    VkDescriptorSetLayout l = VK_NULL_HANDLE;
    VKH_CHECK(vkCreateDescriptorSetLayout(dev, &lci, nullptr, &l));
    scope.defer([dev, l] { vkDestroyDescriptorSetLayout(dev, l, nullptr); });
    setLayouts.push_back(l);
  }
  return setLayouts;
}

// A pool that holds exactly the sets, and the sets allocated from it.
std::vector<VkDescriptorSet> allocateSets(VkDevice dev, Scope& scope, const std::vector<VkDescriptorSetLayout>& setLayouts,
                                          const DescriptorCounts& counts) {
  std::vector<VkDescriptorSet> sets;
  if (setLayouts.empty()) return sets;
  std::vector<VkDescriptorPoolSize> sizes;
  for (auto [type, count] : counts.byType) sizes.push_back({type, count});
  VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pci.maxSets = uint32_t(setLayouts.size());
  pci.poolSizeCount = uint32_t(sizes.size());
  pci.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VKH_CHECK(vkCreateDescriptorPool(dev, &pci, nullptr, &pool));
  scope.defer([dev, pool] { vkDestroyDescriptorPool(dev, pool, nullptr); });
  VkDescriptorSetAllocateInfo dai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  dai.descriptorPool = pool;
  dai.descriptorSetCount = uint32_t(setLayouts.size());
  dai.pSetLayouts = setLayouts.data();
  sets.resize(setLayouts.size());
  VKH_CHECK(vkAllocateDescriptorSets(dev, &dai, sets.data()));
  return sets;
}

}  // namespace

std::vector<VkDescriptorSetLayout> VulkanContext::Impl::descriptorSets(Scope& scope, VkCommandBuffer uploads,
                                                                       const PipelineInputs& in, BuiltPipeline* out,
                                                                       const std::string& label) {
  std::vector<std::vector<DescriptorSlot>> layoutSets;
  std::string layoutError;
  if (!buildDescriptorLayout(in, &layoutSets, &layoutError)) failIn(label, layoutError);

  DescriptorCounts counts;
  std::vector<VkDescriptorSetLayout> setLayouts = createSetLayouts(device, scope, layoutSets, &counts);
  if (setLayouts.size() > props.limits.maxBoundDescriptorSets)
    failIn(label, "descriptor set index exceeds maxBoundDescriptorSets");
  out->sets = allocateSets(device, scope, setLayouts, counts);

  DescriptorWriter writer(*this, scope, uploads, counts, label);
  for (uint32_t set = 0; set < layoutSets.size(); ++set)
    for (const DescriptorSlot& s : layoutSets[set]) writer.write(in, out->sets[set], set, s);
  writer.flush();
  return setLayouts;
}

}  // namespace stereoshift::harness
