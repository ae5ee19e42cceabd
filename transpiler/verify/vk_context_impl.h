// The inside of VulkanContext (vk_harness.h), shared by the files that implement it, one phase each:
//   vk_device.cpp     instance, validation layer and device set-up (create(), the device queries)
//   vk_resources.cpp  memory, host-visible buffers, images and textures, one-shot command buffers
//   vk_descriptors.cpp the descriptor layout of a pipeline's resources, its sets and their writes
//   vk_pipeline.cpp   graphics pipeline construction: stages, vertex input, layout, fixed function
//   vk_capture.cpp    capture(): a transform-feedback draw and its read-back
//   vk_render.cpp     render(): the colour/depth render pass, the draws and the read-back
//   vk_harness.cpp    the public surface: errors turned into results, accessors, loadSpirv
// Not a public header: tests and callers use vk_harness.h only.
#pragma once

#include "transpiler/verify/vk_harness.h"

#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace stereoshift::harness {

// ------------------------------------------------------------------------------------------------
// Errors: internal code throws HarnessError; capture()/render()/create() turn it into a string.
// ------------------------------------------------------------------------------------------------

struct HarnessError : std::runtime_error {
  HarnessError(const std::string& msg, bool lost = false) : std::runtime_error(msg), deviceLost(lost) {}
  bool deviceLost;
};

[[noreturn]] inline void fail(const std::string& msg) { throw HarnessError(msg); }

const char* resultName(VkResult r);
// Throws a HarnessError naming the call, the result and where it was made (file:line).
void checkResult(VkResult r, const char* expr, const char* file, int line);

#define VKH_CHECK(expr) checkResult((expr), #expr, __FILE_NAME__, __LINE__)

// Runs deferred destroy calls in reverse order of registration, then frees device memory, after
// waiting for the device to be idle. Registered right after each successful vkCreate*, so every
// exit path (success or HarnessError) releases everything.
class Scope {
 public:
  explicit Scope(VkDevice device) : device_(device) {}
  ~Scope() {
    if (device_ != VK_NULL_HANDLE && (!objects_.empty() || !memory_.empty())) vkDeviceWaitIdle(device_);
    for (auto it = objects_.rbegin(); it != objects_.rend(); ++it) (*it)();
    for (VkDeviceMemory m : memory_) vkFreeMemory(device_, m, nullptr);
  }
  Scope(const Scope&) = delete;
  Scope& operator=(const Scope&) = delete;

  template <class F>
  void defer(F&& f) {
    objects_.emplace_back(std::forward<F>(f));
  }
  void deferFree(VkDeviceMemory m) { memory_.push_back(m); }

 private:
  VkDevice device_;
  std::vector<std::function<void()>> objects_;
  std::vector<VkDeviceMemory> memory_;
};

struct HostBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  void* mapped = nullptr;
  VkDeviceSize size = 0;
};

struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
};

// Bytes per element of the vertex formats the tests are likely to use; 0 = unknown (no size check).
uint32_t vertexFormatSize(VkFormat f);
const char* stageName(VkShaderStageFlagBits s);

// ------------------------------------------------------------------------------------------------
// The context's state and the phases of a call
// ------------------------------------------------------------------------------------------------

struct VulkanContext::Impl {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  PFN_vkDestroyDebugUtilsMessengerEXT destroyMessenger = nullptr;
  VkPhysicalDevice phys = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  bool timestamps = false;  // the graphics queue writes timestamps (render()'s drawMilliseconds)
  VkCommandPool commandPool = VK_NULL_HANDLE;

  VkPhysicalDeviceProperties props{};
  VkPhysicalDeviceFeatures enabledFeatures{};
  VkPhysicalDeviceMemoryProperties memory{};
  VkPhysicalDeviceTransformFeedbackPropertiesEXT xfbProps{};
  uint32_t apiVersion = 0;
  bool validation = false;
  bool geometryShader = false, tessellationShader = false;
  bool multiview = false, multiviewGeometry = false, multiviewTessellation = false;
  bool bufferDeviceAddress = false;  // Vulkan 1.2's feature, enabled when supported (address buffers)
  uint32_t maxMultiviewViewCount = 0;
  bool lost = false;

  PFN_vkCmdBindTransformFeedbackBuffersEXT cmdBindXfbBuffers = nullptr;
  PFN_vkCmdBeginTransformFeedbackEXT cmdBeginXfb = nullptr;
  PFN_vkCmdEndTransformFeedbackEXT cmdEndXfb = nullptr;
  PFN_vkCmdBeginQueryIndexedEXT cmdBeginQueryIndexed = nullptr;
  PFN_vkCmdEndQueryIndexedEXT cmdEndQueryIndexed = nullptr;

  mutable std::mutex messageMutex;
  std::vector<std::string> messages;

  ~Impl() {
    if (device) {
      vkDeviceWaitIdle(device);
      if (commandPool) vkDestroyCommandPool(device, commandPool, nullptr);
      vkDestroyDevice(device, nullptr);
    }
    if (messenger && destroyMessenger) destroyMessenger(instance, messenger, nullptr);
    if (instance) vkDestroyInstance(instance, nullptr);
  }

  // Set-up (vk_device.cpp) -----------------------------------------------------------------------
  void init(const ContextOptions& options);
  // The validation layer when `options` (or the environment) asks for it; sets `validation`.
  void chooseValidation(const ContextOptions& options);
  void createInstance(uint32_t requestedVersion);
  void pickDevice(const ContextOptions& options);
  void createDevice();
  // The graphics queue family; sets queueFamily and timestamps.
  void pickQueueFamily();
  void loadTransformFeedbackEntryPoints();

  // Resources (vk_resources.cpp) -----------------------------------------------------------------
  uint32_t memoryType(uint32_t typeBits, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred,
                      const char* what) const;
  // Memory for `req` (freed by `scope`): a type with `required` and, where one has it, `preferred`.
  // `allocateFlags`: VkMemoryAllocateFlagsInfo (device addresses).
  VkDeviceMemory allocateMemory(Scope& scope, const VkMemoryRequirements& req, VkMemoryPropertyFlags required,
                                VkMemoryPropertyFlags preferred, const char* what, VkMemoryAllocateFlags allocateFlags = 0);
  // A host-visible buffer of at least `size` bytes, mapped, zeroed and then filled from `init`.
  HostBuffer hostBuffer(Scope& scope, VkDeviceSize size, VkBufferUsageFlags usage, const void* init,
                        size_t initSize, const char* what, VkMemoryAllocateFlags allocateFlags = 0);
  // `in` with its address buffers created (alive as long as `scope`) and every placeholder replaced
  // by the address it names (see addressPlaceholder); `in` itself when it has none.
  const PipelineInputs& resolveAddresses(Scope& scope, const PipelineInputs& in, PipelineInputs* resolved,
                                         const std::string& label);
  // An image as `ici` describes it, in device-local memory, with a view of all its layers.
  Image deviceImage(Scope& scope, const VkImageCreateInfo& ici, VkImageViewType viewType, VkImageAspectFlags aspect,
                    const char* what);
  Image image2D(Scope& scope, VkFormat format, uint32_t w, uint32_t h, uint32_t layers, VkImageUsageFlags usage,
                VkImageAspectFlags aspect, const char* what);
  void requireFormat(VkFormat format, VkFormatFeatureFlags optimalFeatures, const char* what) const;
  // One element of a SampledTexture that has an image: created, filled through `uploads` and left
  // in the layout its descriptor type reads it in.
  Image textureImage(Scope& scope, VkCommandBuffer uploads, const SampledTexture& t, uint32_t element,
                     const std::string& where);
  VkCommandBuffer beginCommands(Scope& scope);
  void submitAndWait(Scope& scope, VkCommandBuffer cb);

  // Pipelines (vk_pipeline.cpp, vk_descriptors.cpp) ----------------------------------------------
  struct RasterConfig {
    bool discard = false;
    bool colorAttachment = false;
    bool depthAttachment = false;
    const Draw* draw = nullptr;  // depth/blend options when rendering
    uint32_t viewCount = 1;
  };
  struct BuiltPipeline {
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> sets;
    VkBuffer vertexBuffer = VK_NULL_HANDLE, instanceBuffer = VK_NULL_HANDLE, indexBuffer = VK_NULL_HANDLE;
  };
  // The shader stages by kind, checked against each other and the device (fragment dropped when
  // the rasterizer discards).
  using StageMap = std::map<VkShaderStageFlagBits, const ShaderStage*>;
  // Specialization constants shared by every stage; stays alive until the pipeline is created.
  struct Specialization {
    std::vector<VkSpecializationMapEntry> entries;
    std::vector<uint32_t> data;
    VkSpecializationInfo info{};
  };
  struct VertexInput {
    std::vector<VkVertexInputBindingDescription> bindings;
    std::vector<VkVertexInputAttributeDescription> attributes;
  };

  BuiltPipeline buildPipeline(Scope& scope, VkCommandBuffer uploads, const PipelineInputs& in,
                              VkRenderPass renderPass, const RasterConfig& raster, const std::string& label);
  StageMap checkStages(const PipelineInputs& in, const RasterConfig& raster, const std::string& label) const;
  void specialize(const PipelineInputs& in, Specialization* spec, const std::string& label) const;
  std::vector<VkPipelineShaderStageCreateInfo> shaderStages(Scope& scope, const StageMap& stages,
                                                            const Specialization& spec);
  // Vertex (binding 0), instance (binding 1) and index buffers, uploaded; their bindings and attributes.
  VertexInput vertexInput(Scope& scope, const PipelineInputs& in, BuiltPipeline* out, const std::string& label);
  VkBuffer vertexBinding(Scope& scope, const VertexBuffer& vb, uint32_t binding, VkVertexInputRate rate,
                         uint32_t lastElement, const char* what, VertexInput* input, std::set<uint32_t>* locations,
                         const std::string& label);
  // Descriptor set layouts, the sets (out->sets) and every resource they point at, uploaded.
  std::vector<VkDescriptorSetLayout> descriptorSets(Scope& scope, VkCommandBuffer uploads, const PipelineInputs& in,
                                                    BuiltPipeline* out, const std::string& label);
  VkPipelineLayout pipelineLayout(Scope& scope, const PipelineInputs& in,
                                  const std::vector<VkDescriptorSetLayout>& setLayouts, const std::string& label);
  VkPipeline graphicsPipeline(Scope& scope, const PipelineInputs& in, const RasterConfig& raster,
                              VkRenderPass renderPass, const std::vector<VkPipelineShaderStageCreateInfo>& stages,
                              const VertexInput& input, VkPipelineLayout layout, const std::string& label);
  // Binds the pipeline and its state; then recordDraw issues the draw. Split because transform
  // feedback must begin after the pipeline is bound and no pipeline may be bound while it is active.
  void recordBind(VkCommandBuffer cb, const BuiltPipeline& p, const PipelineInputs& in, uint32_t width,
                  uint32_t height);
  void recordDraw(VkCommandBuffer cb, const BuiltPipeline& p, const PipelineInputs& in);

  // The calls (vk_capture.cpp, vk_render.cpp) ----------------------------------------------------
  void capture(const CaptureRequest& req, CaptureResult& out);
  void render(const RenderRequest& req, RenderResult& out);

  std::function<void(const std::string&)> messageSink;

  void addMessage(std::string m) {
    std::lock_guard<std::mutex> lock(messageMutex);
    if (messageSink) messageSink(m);
    messages.push_back(std::move(m));
  }
};

// A failure inside buildPipeline's phases: "<label>: <message>".
[[noreturn]] inline void failIn(const std::string& label, const std::string& message) { fail(label + ": " + message); }

}  // namespace stereoshift::harness
