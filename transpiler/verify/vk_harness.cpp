// Headless Vulkan execution harness: see vk_harness.h.
#include "transpiler/verify/vk_harness.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace stereoshift::harness {
namespace {

// ------------------------------------------------------------------------------------------------
// Errors: internal code throws HarnessError; capture()/render()/create() turn it into a string.
// ------------------------------------------------------------------------------------------------

struct HarnessError : std::runtime_error {
  HarnessError(const std::string& msg, bool lost = false) : std::runtime_error(msg), deviceLost(lost) {}
  bool deviceLost;
};

[[noreturn]] void fail(const std::string& msg) { throw HarnessError(msg); }

const char* resultName(VkResult r) {
  switch (r) {
#define CASE(x) \
  case x:       \
    return #x;
    CASE(VK_SUCCESS)
    CASE(VK_NOT_READY)
    CASE(VK_TIMEOUT)
    CASE(VK_EVENT_SET)
    CASE(VK_EVENT_RESET)
    CASE(VK_INCOMPLETE)
    CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    CASE(VK_ERROR_INITIALIZATION_FAILED)
    CASE(VK_ERROR_DEVICE_LOST)
    CASE(VK_ERROR_MEMORY_MAP_FAILED)
    CASE(VK_ERROR_LAYER_NOT_PRESENT)
    CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    CASE(VK_ERROR_TOO_MANY_OBJECTS)
    CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    CASE(VK_ERROR_FRAGMENTED_POOL)
    CASE(VK_ERROR_UNKNOWN)
    CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    CASE(VK_ERROR_FRAGMENTATION)
    CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    CASE(VK_PIPELINE_COMPILE_REQUIRED)
    CASE(VK_ERROR_INVALID_SHADER_NV)
#undef CASE
    default:
      return "VkResult(unknown)";
  }
}

void checkResult(VkResult r, const char* expr, int line) {
  if (r == VK_SUCCESS) return;
  std::ostringstream s;
  s << expr << " failed: " << resultName(r) << " (" << int(r) << ") at vk_harness.cpp:" << line;
  throw HarnessError(s.str(), r == VK_ERROR_DEVICE_LOST);
}

#define VKH_CHECK(expr) checkResult((expr), #expr, __LINE__)

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

std::string versionString(uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
         std::to_string(VK_API_VERSION_PATCH(v));
}

bool hasLayer(const char* name) {
  uint32_t n = 0;
  if (vkEnumerateInstanceLayerProperties(&n, nullptr) != VK_SUCCESS) return false;
  std::vector<VkLayerProperties> layers(n);
  if (vkEnumerateInstanceLayerProperties(&n, layers.data()) != VK_SUCCESS) return false;
  for (auto& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

bool hasInstanceExtension(const char* layer, const char* name) {
  uint32_t n = 0;
  if (vkEnumerateInstanceExtensionProperties(layer, &n, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> ext(n);
  if (vkEnumerateInstanceExtensionProperties(layer, &n, ext.data()) != VK_SUCCESS) return false;
  for (auto& e : ext)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

bool hasDeviceExtension(VkPhysicalDevice pd, const char* name) {
  uint32_t n = 0;
  if (vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> ext(n);
  if (vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, ext.data()) != VK_SUCCESS) return false;
  for (auto& e : ext)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

const char* deviceTypeName(VkPhysicalDeviceType t) {
  switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
    default: return "other";
  }
}

VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT type,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);

}  // namespace

// ------------------------------------------------------------------------------------------------
// Descriptor layout
// ------------------------------------------------------------------------------------------------

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

// ------------------------------------------------------------------------------------------------
// Context implementation
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

  void init(const ContextOptions& options);
  void pickDevice(const ContextOptions& options);
  void createDevice();

  // Per-call helpers ---------------------------------------------------------------------------
  uint32_t memoryType(uint32_t typeBits, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred,
                      const char* what) const;
  HostBuffer hostBuffer(Scope& scope, VkDeviceSize size, VkBufferUsageFlags usage, const void* init,
                        size_t initSize, const char* what);
  Image image2D(Scope& scope, VkFormat format, uint32_t w, uint32_t h, uint32_t layers, VkImageUsageFlags usage,
                VkImageAspectFlags aspect, const char* what);
  void requireFormat(VkFormat format, VkFormatFeatureFlags optimalFeatures, const char* what) const;
  // One element of a SampledTexture that has an image: created, filled through `uploads` and left
  // in the layout its descriptor type reads it in.
  Image textureImage(Scope& scope, VkCommandBuffer uploads, const SampledTexture& t, uint32_t element,
                     const std::string& where);
  VkCommandBuffer beginCommands(Scope& scope);
  void submitAndWait(Scope& scope, VkCommandBuffer cb);

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
  BuiltPipeline buildPipeline(Scope& scope, VkCommandBuffer uploads, const PipelineInputs& in,
                              VkRenderPass renderPass, const RasterConfig& raster, const std::string& label);
  // Binds the pipeline and its state; then recordDraw issues the draw. Split because transform
  // feedback must begin after the pipeline is bound and no pipeline may be bound while it is active.
  void recordBind(VkCommandBuffer cb, const BuiltPipeline& p, const PipelineInputs& in, uint32_t width,
                  uint32_t height);
  void recordDraw(VkCommandBuffer cb, const BuiltPipeline& p, const PipelineInputs& in);

  void capture(const CaptureRequest& req, CaptureResult& out);
  void render(const RenderRequest& req, RenderResult& out);

  std::function<void(const std::string&)> messageSink;

  void addMessage(std::string m) {
    std::lock_guard<std::mutex> lock(messageMutex);
    if (messageSink) messageSink(m);
    messages.push_back(std::move(m));
  }
};

namespace {
VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* impl = static_cast<VulkanContext::Impl*>(user);
  std::string m = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error: " : "warning: ";
  m += data && data->pMessage ? data->pMessage : "(no message)";
  impl->addMessage(std::move(m));
  return VK_FALSE;
}
}  // namespace

void VulkanContext::Impl::init(const ContextOptions& options) {
  messageSink = options.messageSink;
  // Loader version (vkEnumerateInstanceVersion is absent from 1.0 loaders).
  uint32_t loaderVersion = VK_API_VERSION_1_0;
  auto enumerateVersion =
      reinterpret_cast<PFN_vkEnumerateInstanceVersion>(vkGetInstanceProcAddr(nullptr, "vkEnumerateInstanceVersion"));
  if (enumerateVersion) VKH_CHECK(enumerateVersion(&loaderVersion));
  if (loaderVersion < VK_API_VERSION_1_1)
    fail("the Vulkan loader supports only " + versionString(loaderVersion) + "; Vulkan 1.1 is required");

  // Validation.
  Validation v = options.validation;
  if (v == Validation::FromEnvironment) {
    const char* env = std::getenv("STEREOSHIFT_VK_VALIDATION");
    std::string s = env ? env : "";
    v = (s.empty() || s == "0" || s == "off") ? Validation::Off
        : (s == "auto")                       ? Validation::IfAvailable
                                              : Validation::Required;
  }
  const char* kLayer = "VK_LAYER_KHRONOS_validation";
  if (v != Validation::Off) {
    bool have = hasLayer(kLayer) && (hasInstanceExtension(nullptr, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) ||
                                     hasInstanceExtension(kLayer, VK_EXT_DEBUG_UTILS_EXTENSION_NAME));
    if (!have && v == Validation::Required)
      fail("validation requested but VK_LAYER_KHRONOS_validation (with VK_EXT_debug_utils) is not installed "
           "(Debian package vulkan-validationlayers)");
    validation = have;
  }

  uint32_t requested = std::min<uint32_t>(loaderVersion, VK_API_VERSION_1_3);
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "stereoshift-harness";
  app.pEngineName = "stereoshift";
  app.apiVersion = VK_MAKE_API_VERSION(0, VK_API_VERSION_MAJOR(requested), VK_API_VERSION_MINOR(requested), 0);

  VkDebugUtilsMessengerCreateInfoEXT dbg{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  dbg.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  dbg.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT;
  dbg.pfnUserCallback = debugCallback;
  dbg.pUserData = this;

  std::vector<const char*> layers, extensions;
  if (validation) {
    layers.push_back(kLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  ici.pApplicationInfo = &app;
  ici.enabledLayerCount = uint32_t(layers.size());
  ici.ppEnabledLayerNames = layers.data();
  ici.enabledExtensionCount = uint32_t(extensions.size());
  ici.ppEnabledExtensionNames = extensions.data();
  if (validation) ici.pNext = &dbg;
  VKH_CHECK(vkCreateInstance(&ici, nullptr, &instance));

  if (validation) {
    auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (!createMessenger || !destroyMessenger) fail("vkCreateDebugUtilsMessengerEXT is not available");
    VKH_CHECK(createMessenger(instance, &dbg, nullptr, &messenger));
  }

  pickDevice(options);
  apiVersion = std::min(requested, props.apiVersion);
  createDevice();
}

void VulkanContext::Impl::pickDevice(const ContextOptions& options) {
  uint32_t n = 0;
  VKH_CHECK(vkEnumeratePhysicalDevices(instance, &n, nullptr));
  if (n == 0) fail("no Vulkan physical device (is mesa-vulkan-drivers / lavapipe installed?)");
  std::vector<VkPhysicalDevice> devices(n);
  VKH_CHECK(vkEnumeratePhysicalDevices(instance, &n, devices.data()));
  devices.resize(n);

  std::vector<VkPhysicalDeviceProperties> all(n);
  std::string listing;
  for (uint32_t i = 0; i < n; ++i) {
    vkGetPhysicalDeviceProperties(devices[i], &all[i]);
    listing += "\n  [" + std::to_string(i) + "] " + all[i].deviceName + " (" + deviceTypeName(all[i].deviceType) +
               ", Vulkan " + versionString(all[i].apiVersion) + ")";
  }

  int index = options.deviceIndex;
  if (index < 0) {
    if (const char* env = std::getenv("STEREOSHIFT_VK_DEVICE"); env && *env) {
      char* end = nullptr;
      long v = std::strtol(env, &end, 10);
      if (*end != '\0' || v < 0) fail(std::string("STEREOSHIFT_VK_DEVICE='") + env + "' is not a device index;" + listing);
      index = int(v);
    }
  }
  if (index >= 0) {
    if (uint32_t(index) >= n) fail("device index " + std::to_string(index) + " out of range; devices:" + listing);
  } else {
    for (uint32_t i = 0; i < n && index < 0; ++i)
      if (all[i].deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) index = int(i);
    for (uint32_t i = 0; i < n && index < 0; ++i)
      if (hasDeviceExtension(devices[i], VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME)) index = int(i);
    if (index < 0) fail("no CPU Vulkan device (lavapipe) and no device with VK_EXT_transform_feedback;" + listing);
  }
  phys = devices[uint32_t(index)];
  props = all[uint32_t(index)];
  if (props.apiVersion < VK_API_VERSION_1_1)
    fail(std::string("device '") + props.deviceName + "' supports only Vulkan " + versionString(props.apiVersion) +
         "; 1.1 is required");
  if (!hasDeviceExtension(phys, VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME))
    fail(std::string("device '") + props.deviceName + "' lacks VK_EXT_transform_feedback");
  vkGetPhysicalDeviceMemoryProperties(phys, &memory);
}

void VulkanContext::Impl::createDevice() {
  // Query: core features, transform feedback, multiview + draw parameters (1.1), 1.2 features.
  const bool v12 = apiVersion >= VK_API_VERSION_1_2;
  VkPhysicalDeviceTransformFeedbackFeaturesEXT xfb{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT};
  VkPhysicalDeviceMultiviewFeatures mv{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MULTIVIEW_FEATURES};
  VkPhysicalDeviceShaderDrawParametersFeatures dp{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_DRAW_PARAMETERS_FEATURES};
  VkPhysicalDeviceVulkan11Features f11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
  VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  features.pNext = &xfb;
  if (v12) {
    xfb.pNext = &f11;
    f11.pNext = &f12;
  } else {
    xfb.pNext = &mv;
    mv.pNext = &dp;
  }
  vkGetPhysicalDeviceFeatures2(phys, &features);
  if (!xfb.transformFeedback)
    fail(std::string("device '") + props.deviceName + "' does not support the transformFeedback feature");

  VkPhysicalDeviceMultiviewProperties mvProps{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MULTIVIEW_PROPERTIES};
  xfbProps = VkPhysicalDeviceTransformFeedbackPropertiesEXT{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_PROPERTIES_EXT};
  xfbProps.pNext = &mvProps;
  VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  p2.pNext = &xfbProps;
  vkGetPhysicalDeviceProperties2(phys, &p2);
  xfbProps.pNext = nullptr;
  maxMultiviewViewCount = mvProps.maxMultiviewViewCount;

  // Enable everything supported except robustness (which would hide out-of-bounds accesses).
  features.features.robustBufferAccess = VK_FALSE;
  geometryShader = features.features.geometryShader;
  enabledFeatures = features.features;
  tessellationShader = features.features.tessellationShader;
  if (v12) {
    multiview = f11.multiview;
    multiviewGeometry = f11.multiviewGeometryShader;
    multiviewTessellation = f11.multiviewTessellationShader;
  } else {
    multiview = mv.multiview;
    multiviewGeometry = mv.multiviewGeometryShader;
    multiviewTessellation = mv.multiviewTessellationShader;
  }

  uint32_t nq = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(phys, &nq, nullptr);
  std::vector<VkQueueFamilyProperties> families(nq);
  vkGetPhysicalDeviceQueueFamilyProperties(phys, &nq, families.data());
  bool found = false;
  for (uint32_t i = 0; i < nq && !found; ++i)
    if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
      queueFamily = i;
      found = true;
      timestamps = families[i].timestampValidBits > 0 && props.limits.timestampPeriod > 0;
    }
  if (!found) fail(std::string("device '") + props.deviceName + "' has no graphics queue");

  float priority = 1.f;
  VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  qci.queueFamilyIndex = queueFamily;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  const char* ext[] = {VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME};
  VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  dci.pNext = &features;
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  dci.enabledExtensionCount = 1;
  dci.ppEnabledExtensionNames = ext;
  VKH_CHECK(vkCreateDevice(phys, &dci, nullptr, &device));
  vkGetDeviceQueue(device, queueFamily, 0, &queue);

  VkCommandPoolCreateInfo cpci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  cpci.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  cpci.queueFamilyIndex = queueFamily;
  VKH_CHECK(vkCreateCommandPool(device, &cpci, nullptr, &commandPool));

  auto load = [&](const char* name) {
    PFN_vkVoidFunction f = vkGetDeviceProcAddr(device, name);
    if (!f) fail(std::string(name) + " is not exported by the driver");
    return f;
  };
  cmdBindXfbBuffers = reinterpret_cast<PFN_vkCmdBindTransformFeedbackBuffersEXT>(
      load("vkCmdBindTransformFeedbackBuffersEXT"));
  cmdBeginXfb = reinterpret_cast<PFN_vkCmdBeginTransformFeedbackEXT>(load("vkCmdBeginTransformFeedbackEXT"));
  cmdEndXfb = reinterpret_cast<PFN_vkCmdEndTransformFeedbackEXT>(load("vkCmdEndTransformFeedbackEXT"));
  cmdBeginQueryIndexed = reinterpret_cast<PFN_vkCmdBeginQueryIndexedEXT>(load("vkCmdBeginQueryIndexedEXT"));
  cmdEndQueryIndexed = reinterpret_cast<PFN_vkCmdEndQueryIndexedEXT>(load("vkCmdEndQueryIndexedEXT"));
}

// ------------------------------------------------------------------------------------------------
// Resource helpers
// ------------------------------------------------------------------------------------------------

uint32_t VulkanContext::Impl::memoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                                         VkMemoryPropertyFlags preferred, const char* what) const {
  for (int pass = 0; pass < 2; ++pass) {
    VkMemoryPropertyFlags want = pass == 0 ? (required | preferred) : required;
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
      if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & want) == want) return i;
  }
  fail(std::string("no memory type for ") + what);
}

HostBuffer VulkanContext::Impl::hostBuffer(Scope& scope, VkDeviceSize size, VkBufferUsageFlags usage,
                                           const void* init, size_t initSize, const char* what) {
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
  VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  mai.allocationSize = req.size;
  mai.memoryTypeIndex = memoryType(req.memoryTypeBits,
                                   VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, 0, what);
  VkDeviceMemory mem = VK_NULL_HANDLE;
  VKH_CHECK(vkAllocateMemory(device, &mai, nullptr, &mem));
  scope.deferFree(mem);
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

Image VulkanContext::Impl::image2D(Scope& scope, VkFormat format, uint32_t w, uint32_t h, uint32_t layers,
                                   VkImageUsageFlags usage, VkImageAspectFlags aspect, const char* what) {
  Image img;
  VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  ici.imageType = VK_IMAGE_TYPE_2D;
  ici.format = format;
  ici.extent = {w, h, 1};
  ici.mipLevels = 1;
  ici.arrayLayers = layers;
  ici.samples = VK_SAMPLE_COUNT_1_BIT;
  ici.tiling = VK_IMAGE_TILING_OPTIMAL;
  ici.usage = usage;
  ici.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VKH_CHECK(vkCreateImage(device, &ici, nullptr, &img.image));
  VkDevice dev = device;
  VkImage im = img.image;
  scope.defer([dev, im] { vkDestroyImage(dev, im, nullptr); });

  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device, img.image, &req);
  VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  mai.allocationSize = req.size;
  mai.memoryTypeIndex = memoryType(req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, what);
  VkDeviceMemory mem = VK_NULL_HANDLE;
  VKH_CHECK(vkAllocateMemory(device, &mai, nullptr, &mem));
  scope.deferFree(mem);
  VKH_CHECK(vkBindImageMemory(device, img.image, mem, 0));

  VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  vci.image = img.image;
  vci.viewType = layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
  vci.format = format;
  vci.subresourceRange = {aspect, 0, 1, 0, layers};
  VKH_CHECK(vkCreateImageView(device, &vci, nullptr, &img.view));
  VkImageView view = img.view;
  scope.defer([dev, view] { vkDestroyImageView(dev, view, nullptr); });
  return img;
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
  Image img;
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
  VKH_CHECK(vkCreateImage(device, &ici, nullptr, &img.image));
  VkDevice dev = device;
  VkImage im = img.image;
  scope.defer([dev, im] { vkDestroyImage(dev, im, nullptr); });
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device, img.image, &req);
  VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  mai.allocationSize = req.size;
  mai.memoryTypeIndex = memoryType(req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, what.c_str());
  VkDeviceMemory mem = VK_NULL_HANDLE;
  VKH_CHECK(vkAllocateMemory(device, &mai, nullptr, &mem));
  scope.deferFree(mem);
  VKH_CHECK(vkBindImageMemory(device, img.image, mem, 0));

  VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  vci.image = img.image;
  vci.viewType = t.viewType;
  vci.format = t.format;
  vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, t.layers};
  VKH_CHECK(vkCreateImageView(device, &vci, nullptr, &img.view));
  VkImageView view = img.view;
  scope.defer([dev, view] { vkDestroyImageView(dev, view, nullptr); });

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

// ------------------------------------------------------------------------------------------------
// Pipeline construction shared by capture() and render()
// ------------------------------------------------------------------------------------------------

VulkanContext::Impl::BuiltPipeline VulkanContext::Impl::buildPipeline(Scope& scope, VkCommandBuffer uploads,
                                                                      const PipelineInputs& in,
                                                                      VkRenderPass renderPass,
                                                                      const RasterConfig& raster,
                                                                      const std::string& label) {
  const VkDevice dev = device;
  BuiltPipeline out;
  auto err = [&](const std::string& m) { fail(label + ": " + m); };

  // --- stages ---------------------------------------------------------------------------------
  std::map<VkShaderStageFlagBits, const ShaderStage*> stages;
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

  // --- specialization (all stages) ------------------------------------------------------------
  std::vector<VkSpecializationMapEntry> specEntries;
  std::vector<uint32_t> specData;
  {
    std::set<uint32_t> ids;
    for (const SpecConstant& c : in.specConstants) {
      if (!ids.insert(c.constantID).second) err("specialization constant " + std::to_string(c.constantID) + " given twice");
      specEntries.push_back({c.constantID, uint32_t(specData.size() * 4), 4});
      specData.push_back(c.bits);
    }
  }
  VkSpecializationInfo specInfo{uint32_t(specEntries.size()), specEntries.data(), specData.size() * 4, specData.data()};

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
    si.pSpecializationInfo = specEntries.empty() ? nullptr : &specInfo;
    stageInfos.push_back(si);
  }

  // --- vertex input -----------------------------------------------------------------------------
  const bool indexed = !in.indices.empty();
  if (!indexed && in.vertexCount == 0) err("vertexCount is 0 and no indices are given: nothing to draw");
  if (in.instanceCount == 0) err("instanceCount is 0: nothing to draw");
  uint32_t maxVertex = indexed ? *std::max_element(in.indices.begin(), in.indices.end()) : in.vertexCount - 1;

  std::vector<VkVertexInputBindingDescription> bindings;
  std::vector<VkVertexInputAttributeDescription> attributes;
  std::set<uint32_t> locations;
  auto addBinding = [&](const VertexBuffer& vb, uint32_t binding, VkVertexInputRate rate, uint32_t lastElement,
                        const char* what) -> VkBuffer {
    if (vb.attributes.empty()) {
      if (!vb.bytes.empty()) err(std::string(what) + " buffer has bytes but no attributes");
      return VK_NULL_HANDLE;
    }
    if (vb.stride > props.limits.maxVertexInputBindingStride) err(std::string(what) + " stride too large");
    size_t needed = 0;
    for (const VertexAttribute& a : vb.attributes) {
      if (!locations.insert(a.location).second)
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
      attributes.push_back({a.location, binding, a.format, a.offset});
    }
    if (vb.bytes.size() < needed)
      err(std::string(what) + " buffer too small: " + std::to_string(vb.bytes.size()) + " bytes, the draw reads " +
          std::to_string(needed));
    bindings.push_back({binding, vb.stride, rate});
    return hostBuffer(scope, vb.bytes.size(), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, vb.bytes.data(), vb.bytes.size(),
                      what)
        .buffer;
  };
  out.vertexBuffer = addBinding(in.vertices, 0, VK_VERTEX_INPUT_RATE_VERTEX, maxVertex, "vertex");
  if (in.instances)
    out.instanceBuffer =
        addBinding(*in.instances, 1, VK_VERTEX_INPUT_RATE_INSTANCE, in.instanceCount - 1, "instance");
  if (indexed)
    out.indexBuffer = hostBuffer(scope, in.indices.size() * 4, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, in.indices.data(),
                                 in.indices.size() * 4, "index buffer")
                          .buffer;

  // --- descriptors -------------------------------------------------------------------------------
  std::vector<std::vector<DescriptorSlot>> layoutSets;
  std::string layoutError;
  if (!buildDescriptorLayout(in, &layoutSets, &layoutError)) err(layoutError);

  std::vector<VkDescriptorSetLayout> setLayouts;
  std::map<VkDescriptorType, uint32_t> descriptorCounts;
  uint32_t bufferDescriptors = 0, imageDescriptors = 0, texelBufferDescriptors = 0;
  for (auto& slots : layoutSets) {
    std::vector<VkDescriptorSetLayoutBinding> b;
    for (const DescriptorSlot& s : slots) {
      b.push_back({s.binding, s.type, s.count, VK_SHADER_STAGE_ALL_GRAPHICS, nullptr});
      descriptorCounts[s.type] += s.count;
      bool buffer = s.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || s.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      bool texel = s.type == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER || s.type == VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
      (buffer ? bufferDescriptors : texel ? texelBufferDescriptors : imageDescriptors) += s.count;
    }
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = uint32_t(b.size());
    lci.pBindings = b.data();
    VkDescriptorSetLayout l = VK_NULL_HANDLE;
    VKH_CHECK(vkCreateDescriptorSetLayout(dev, &lci, nullptr, &l));
    scope.defer([dev, l] { vkDestroyDescriptorSetLayout(dev, l, nullptr); });
    setLayouts.push_back(l);
  }
  if (setLayouts.size() > props.limits.maxBoundDescriptorSets)
    err("descriptor set index exceeds maxBoundDescriptorSets");

  if (!setLayouts.empty()) {
    std::vector<VkDescriptorPoolSize> sizes;
    for (auto [type, count] : descriptorCounts) sizes.push_back({type, count});
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
    out.sets.resize(setLayouts.size());
    VKH_CHECK(vkAllocateDescriptorSets(dev, &dai, out.sets.data()));
  }

  // Resources + writes. Infos are stored in pre-sized vectors so their addresses stay valid.
  std::vector<VkDescriptorBufferInfo> bufferInfos;
  std::vector<VkDescriptorImageInfo> imageInfos;
  std::vector<VkBufferView> texelViews;
  bufferInfos.reserve(bufferDescriptors);
  imageInfos.reserve(imageDescriptors);
  texelViews.reserve(texelBufferDescriptors);
  std::vector<VkWriteDescriptorSet> writes;
  VkSampler sampler = VK_NULL_HANDLE;  // one nearest clamp-to-edge sampler serves every descriptor
  auto sharedSampler = [&] {
    if (sampler) return sampler;
    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = sci.minFilter = VK_FILTER_NEAREST;
    sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sci.maxLod = 0.f;
    sci.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    VKH_CHECK(vkCreateSampler(dev, &sci, nullptr, &sampler));
    VkSampler made = sampler;
    scope.defer([dev, made] { vkDestroySampler(dev, made, nullptr); });
    return sampler;
  };
  for (uint32_t set = 0; set < layoutSets.size(); ++set) {
    for (const DescriptorSlot& s : layoutSets[set]) {
      VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      w.dstSet = out.sets[set];
      w.dstBinding = s.binding;
      w.descriptorCount = s.count;
      w.descriptorType = s.type;
      std::string where = "(set " + std::to_string(set) + ", binding " + std::to_string(s.binding) + ")";
      if (s.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || s.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER) {
        const UniformBuffer& u = in.uniformBuffers[s.resourceIndex];
        if (u.bytes.empty()) err("uniform buffer " + where + " is empty");
        if (u.bytes.size() % s.count) err("uniform buffer array " + where + ": bytes do not split into equal elements");
        const size_t elementSize = u.bytes.size() / s.count;
        if (!u.storage && elementSize > props.limits.maxUniformBufferRange)
          err("uniform buffer " + where + " exceeds maxUniformBufferRange");
        size_t first = bufferInfos.size();
        for (uint32_t e = 0; e < s.count; ++e) {
          HostBuffer hb = hostBuffer(scope, elementSize,
                                     u.storage ? VK_BUFFER_USAGE_STORAGE_BUFFER_BIT : VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                     u.bytes.data() + e * elementSize, elementSize, "uniform buffer");
          bufferInfos.push_back({hb.buffer, 0, elementSize});
        }
        w.pBufferInfo = &bufferInfos[first];
        writes.push_back(w);
        continue;
      }
      const SampledTexture& t = in.textures[s.resourceIndex];
      if (s.type == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER || s.type == VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER) {
        const bool storageTexels = s.type == VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
        if (t.width == 0) err("texel buffer " + where + " has zero texels");
        if (t.rgba.size() != size_t(t.width) * 4 * s.count)
          err("texel buffer " + where + ": rgba must hold width*4 values per element");
        VkFormatProperties fp;
        vkGetPhysicalDeviceFormatProperties(phys, t.format, &fp);
        VkFormatFeatureFlags need = storageTexels ? VK_FORMAT_FEATURE_STORAGE_TEXEL_BUFFER_BIT
                                                  : VK_FORMAT_FEATURE_UNIFORM_TEXEL_BUFFER_BIT;
        if (!(fp.bufferFeatures & need)) err("texel buffer " + where + ": format not supported for texel buffers");
        size_t first = texelViews.size();
        for (uint32_t e = 0; e < s.count; ++e) {
          HostBuffer hb = hostBuffer(scope, size_t(t.width) * 16,
                                     storageTexels ? VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT
                                                   : VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                                     t.rgba.data() + size_t(e) * t.width * 4, size_t(t.width) * 16, "texel buffer");
          VkBufferViewCreateInfo bvci{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
          bvci.buffer = hb.buffer;
          bvci.format = t.format;
          bvci.range = VK_WHOLE_SIZE;
          VkBufferView view = VK_NULL_HANDLE;
          VKH_CHECK(vkCreateBufferView(dev, &bvci, nullptr, &view));
          scope.defer([dev, view] { vkDestroyBufferView(dev, view, nullptr); });
          texelViews.push_back(view);
        }
        w.pTexelBufferView = &texelViews[first];
        writes.push_back(w);
        continue;
      }
      size_t first = imageInfos.size();
      for (uint32_t e = 0; e < s.count; ++e) {
        VkDescriptorImageInfo info{};
        if (s.type == VK_DESCRIPTOR_TYPE_SAMPLER || s.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER)
          info.sampler = sharedSampler();
        if (s.type != VK_DESCRIPTOR_TYPE_SAMPLER) {
          info.imageView = textureImage(scope, uploads, t, e, where).view;
          info.imageLayout = s.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE ? VK_IMAGE_LAYOUT_GENERAL
                                                                        : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        }
        imageInfos.push_back(info);
      }
      w.pImageInfo = &imageInfos[first];
      writes.push_back(w);
    }
  }
  if (!writes.empty()) vkUpdateDescriptorSets(dev, uint32_t(writes.size()), writes.data(), 0, nullptr);

  // --- layout --------------------------------------------------------------------------------------
  if (in.pushConstants.size() % 4) err("push constant size must be a multiple of 4");
  if (in.pushConstants.size() > props.limits.maxPushConstantsSize)
    err("push constants exceed maxPushConstantsSize (" + std::to_string(props.limits.maxPushConstantsSize) + ")");
  VkPushConstantRange pcr{VK_SHADER_STAGE_ALL_GRAPHICS, 0, uint32_t(in.pushConstants.size())};
  VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  plci.setLayoutCount = uint32_t(setLayouts.size());
  plci.pSetLayouts = setLayouts.data();
  plci.pushConstantRangeCount = in.pushConstants.empty() ? 0 : 1;
  plci.pPushConstantRanges = &pcr;
  VKH_CHECK(vkCreatePipelineLayout(dev, &plci, nullptr, &out.layout));
  VkPipelineLayout layout = out.layout;
  scope.defer([dev, layout] { vkDestroyPipelineLayout(dev, layout, nullptr); });

  // --- fixed function ------------------------------------------------------------------------------
  VkPipelineVertexInputStateCreateInfo vis{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vis.vertexBindingDescriptionCount = uint32_t(bindings.size());
  vis.pVertexBindingDescriptions = bindings.data();
  vis.vertexAttributeDescriptionCount = uint32_t(attributes.size());
  vis.pVertexAttributeDescriptions = attributes.data();
  VkPipelineInputAssemblyStateCreateInfo ias{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  ias.topology = in.topology;
  VkPipelineTessellationStateCreateInfo ts{VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO};
  ts.patchControlPoints = in.patchControlPoints;
  VkPipelineViewportStateCreateInfo vps{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  vps.viewportCount = 1;
  vps.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  rs.rasterizerDiscardEnable = raster.discard ? VK_TRUE : VK_FALSE;
  rs.polygonMode = VK_POLYGON_MODE_FILL;
  rs.cullMode = VK_CULL_MODE_NONE;
  rs.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  rs.lineWidth = 1.f;
  VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  VkPipelineColorBlendAttachmentState cba{};
  if (raster.draw) {
    ds.depthTestEnable = raster.draw->depthTest;
    ds.depthWriteEnable = raster.draw->depthTest && raster.draw->depthWrite;
    ds.depthCompareOp = raster.draw->depthCompare;
    cba.colorWriteMask = raster.draw->colorWrite ? (VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                                    VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT)
                                                 : 0;
    if (raster.draw->alphaBlend) {
      cba.blendEnable = VK_TRUE;
      cba.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
      cba.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
      cba.colorBlendOp = VK_BLEND_OP_ADD;
      cba.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
      cba.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
      cba.alphaBlendOp = VK_BLEND_OP_ADD;
    }
  }
  VkPipelineColorBlendStateCreateInfo cbs{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  cbs.attachmentCount = raster.colorAttachment ? 1 : 0;
  cbs.pAttachments = &cba;
  VkDynamicState dyn[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dys{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dys.dynamicStateCount = 2;
  dys.pDynamicStates = dyn;

  VkGraphicsPipelineCreateInfo gci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  gci.stageCount = uint32_t(stageInfos.size());
  gci.pStages = stageInfos.data();
  gci.pVertexInputState = &vis;
  gci.pInputAssemblyState = &ias;
  gci.pTessellationState = patches ? &ts : nullptr;
  gci.pViewportState = &vps;
  gci.pRasterizationState = &rs;
  gci.pMultisampleState = &ms;
  gci.pDepthStencilState = raster.depthAttachment ? &ds : nullptr;
  gci.pColorBlendState = &cbs;
  gci.pDynamicState = &dys;
  gci.layout = out.layout;
  gci.renderPass = renderPass;
  gci.subpass = 0;
  VkResult r = vkCreateGraphicsPipelines(dev, VK_NULL_HANDLE, 1, &gci, nullptr, &out.pipeline);
  if (r != VK_SUCCESS)
    err(std::string("vkCreateGraphicsPipelines failed: ") + resultName(r) +
        " (invalid SPIR-V, an interface mismatch between stages, or a missing device feature)");
  VkPipeline pipeline = out.pipeline;
  scope.defer([dev, pipeline] { vkDestroyPipeline(dev, pipeline, nullptr); });
  return out;
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

// ------------------------------------------------------------------------------------------------
// capture()
// ------------------------------------------------------------------------------------------------

void VulkanContext::Impl::capture(const CaptureRequest& req, CaptureResult& out) {
  out.stride = req.xfbStride;
  if (req.xfbStride == 0 || req.xfbStride % 4)
    fail("capture: xfbStride must be a non-zero multiple of 4 (got " + std::to_string(req.xfbStride) + ")");
  if (req.xfbStride > xfbProps.maxTransformFeedbackBufferDataStride)
    fail("capture: xfbStride " + std::to_string(req.xfbStride) + " exceeds maxTransformFeedbackBufferDataStride " +
         std::to_string(xfbProps.maxTransformFeedbackBufferDataStride));
  if (req.expectedVertices == 0) fail("capture: expectedVertices is 0");
  const VkDeviceSize capacity = VkDeviceSize(req.expectedVertices) * req.xfbStride;
  if (capacity > xfbProps.maxTransformFeedbackBufferSize) fail("capture: buffer exceeds maxTransformFeedbackBufferSize");

  const VkDevice dev = device;
  Scope scope(dev);
  VkCommandBuffer cb = beginCommands(scope);

  // Render pass without attachments (rasterizer discard).
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

  RasterConfig raster;
  raster.discard = true;
  BuiltPipeline p = buildPipeline(scope, cb, req.pipeline, rp, raster, "capture");

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
  recordBind(cb, p, req.pipeline, 1, 1);
  VkDeviceSize zero = 0, size = capacity;
  cmdBindXfbBuffers(cb, 0, 1, &xfb.buffer, &zero, &size);
  if (query) cmdBeginQueryIndexed(cb, qp, 0, 0, 0);
  cmdBeginXfb(cb, 0, 0, nullptr, nullptr);  // no counter buffer: start writing at offset 0
  recordDraw(cb, p, req.pipeline);
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

// ------------------------------------------------------------------------------------------------
// render()
// ------------------------------------------------------------------------------------------------

void VulkanContext::Impl::render(const RenderRequest& req, RenderResult& out) {
  out.width = req.width;
  out.height = req.height;
  out.viewCount = req.viewCount;
  if (req.width == 0 || req.height == 0) fail("render: width and height must be non-zero");
  if (req.width > props.limits.maxFramebufferWidth || req.height > props.limits.maxFramebufferHeight)
    fail("render: target larger than maxFramebufferWidth/Height");
  if (req.viewCount == 0) fail("render: viewCount must be >= 1");
  const bool useMultiview = req.viewCount > 1 && !req.layeredWithoutMultiview;
  if (useMultiview && !multiview) fail("render: multiview is not supported by the device");
  if (useMultiview && req.viewCount > maxMultiviewViewCount)
    fail("render: viewCount exceeds maxMultiviewViewCount " + std::to_string(maxMultiviewViewCount));
  if (req.draws.empty()) fail("render: no draws");

  const VkDevice dev = device;
  const VkFormat colorFormat = VK_FORMAT_R8G8B8A8_UNORM, depthFormat = VK_FORMAT_D32_SFLOAT;
  requireFormat(colorFormat, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT,
                "colour target");
  requireFormat(depthFormat,
                VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | (req.readDepth ? VK_FORMAT_FEATURE_TRANSFER_SRC_BIT : 0),
                "depth target");
  Scope scope(dev);
  VkCommandBuffer cb = beginCommands(scope);

  const uint32_t layers = req.viewCount;
  Image color = image2D(scope, colorFormat, req.width, req.height, layers,
                        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT,
                        "colour target");
  Image depth = image2D(scope, depthFormat, req.width, req.height, layers,
                        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                        VK_IMAGE_ASPECT_DEPTH_BIT, "depth target");

  const uint32_t viewMask = (layers >= 32) ? ~0u : ((1u << layers) - 1u);
  VkRenderPass rp = VK_NULL_HANDLE;
  VKH_CHECK(createColourDepthRenderPass(dev, colorFormat, depthFormat, useMultiview ? viewMask : 0, req.readDepth, &rp));
  scope.defer([dev, rp] { vkDestroyRenderPass(dev, rp, nullptr); });

  VkImageView views[2] = {color.view, depth.view};
  VkFramebufferCreateInfo fci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fci.renderPass = rp;
  fci.attachmentCount = 2;
  fci.pAttachments = views;
  fci.width = req.width;
  fci.height = req.height;
  fci.layers = useMultiview ? 1 : layers;  // multiview: must be 1
  VkFramebuffer fb = VK_NULL_HANDLE;
  VKH_CHECK(vkCreateFramebuffer(dev, &fci, nullptr, &fb));
  scope.defer([dev, fb] { vkDestroyFramebuffer(dev, fb, nullptr); });

  std::vector<BuiltPipeline> pipelines;
  for (size_t i = 0; i < req.draws.size(); ++i) {
    RasterConfig raster;
    raster.colorAttachment = raster.depthAttachment = true;
    raster.draw = &req.draws[i];
    raster.viewCount = useMultiview ? layers : 1;
    pipelines.push_back(
        buildPipeline(scope, cb, req.draws[i].pipeline, rp, raster, "render draw " + std::to_string(i)));
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
  rbi.renderPass = rp;
  rbi.framebuffer = fb;
  rbi.renderArea = {{0, 0}, {req.width, req.height}};
  rbi.clearValueCount = 2;
  rbi.pClearValues = clears;
  // GPU timestamps around the render pass: the draws' own time, without the pipeline creation and
  // uploads a render() call also does (benchmarks compare these).
  VkQueryPool timer = VK_NULL_HANDLE;
  if (timestamps) {
    VkQueryPoolCreateInfo tci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    tci.queryType = VK_QUERY_TYPE_TIMESTAMP;
    tci.queryCount = 2;
    VKH_CHECK(vkCreateQueryPool(device, &tci, nullptr, &timer));
    VkDevice dev = device;
    scope.defer([dev, timer] { vkDestroyQueryPool(dev, timer, nullptr); });
    vkCmdResetQueryPool(cb, timer, 0, 2);
    vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timer, 0);
  }
  vkCmdBeginRenderPass(cb, &rbi, VK_SUBPASS_CONTENTS_INLINE);
  for (size_t i = 0; i < req.draws.size(); ++i) {
    recordBind(cb, pipelines[i], req.draws[i].pipeline, req.width, req.height);
    recordDraw(cb, pipelines[i], req.draws[i].pipeline);
  }
  vkCmdEndRenderPass(cb);
  if (timestamps) vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timer, 1);

  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, layers};
  copy.imageExtent = {req.width, req.height, 1};
  vkCmdCopyImageToBuffer(cb, color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, colorOut.buffer, 1, &copy);
  if (req.readDepth) {
    copy.imageSubresource.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
    vkCmdCopyImageToBuffer(cb, depth.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, depthOut.buffer, 1, &copy);
  }
  VkMemoryBarrier mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  mb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  mb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &mb, 0, nullptr, 0,
                       nullptr);
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

// ------------------------------------------------------------------------------------------------
// Public surface
// ------------------------------------------------------------------------------------------------

VulkanContext::VulkanContext(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
VulkanContext::~VulkanContext() = default;

std::unique_ptr<VulkanContext> VulkanContext::create(std::string* error, const ContextOptions& options) {
  auto impl = std::make_unique<Impl>();
  try {
    impl->init(options);
  } catch (const std::exception& e) {
    if (error) *error = std::string("Vulkan context: ") + e.what();
    return nullptr;
  }
  if (error) error->clear();
  return std::unique_ptr<VulkanContext>(new VulkanContext(std::move(impl)));
}

bool VulkanContext::anyDeviceAvailable(std::string* why) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.apiVersion = VK_API_VERSION_1_0;
  VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  ici.pApplicationInfo = &app;
  VkInstance instance = VK_NULL_HANDLE;
  VkResult r = vkCreateInstance(&ici, nullptr, &instance);
  if (r != VK_SUCCESS) {
    if (why) *why = std::string("vkCreateInstance failed: ") + resultName(r) + " (no Vulkan driver installed?)";
    return false;
  }
  uint32_t n = 0;
  r = vkEnumeratePhysicalDevices(instance, &n, nullptr);
  vkDestroyInstance(instance, nullptr);
  if (r != VK_SUCCESS || n == 0) {
    if (why) *why = "no Vulkan physical device (install mesa-vulkan-drivers for lavapipe)";
    return false;
  }
  return true;
}

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

template <class Result, class Fn>
static Result runGuarded(VulkanContext::Impl& impl, Fn&& fn) {
  Result out;
  if (impl.lost) {
    out.error = "the Vulkan device was lost by an earlier call; create a new context";
    return out;
  }
  try {
    fn(out);
  } catch (const HarnessError& e) {
    if (e.deviceLost) impl.lost = true;
    out.error = e.what();
  } catch (const std::exception& e) {
    out.error = std::string("internal error: ") + e.what();
  }
  return out;
}

CaptureResult VulkanContext::capture(const CaptureRequest& request) {
  CaptureResult r = runGuarded<CaptureResult>(*impl_, [&](CaptureResult& out) { impl_->capture(request, out); });
  if (!r.ok()) r.bytes.clear();
  return r;
}

RenderResult VulkanContext::render(const RenderRequest& request) {
  RenderResult r = runGuarded<RenderResult>(*impl_, [&](RenderResult& out) { impl_->render(request, out); });
  if (!r.ok()) {
    r.pixels.clear();
    r.depth.clear();
  }
  return r;
}

std::string VulkanContext::deviceName() const { return impl_->props.deviceName; }
const VkPhysicalDeviceProperties& VulkanContext::properties() const { return impl_->props; }
const VkPhysicalDeviceFeatures& VulkanContext::features() const { return impl_->enabledFeatures; }
VkPhysicalDeviceType VulkanContext::deviceType() const { return impl_->props.deviceType; }
uint32_t VulkanContext::apiVersion() const { return impl_->apiVersion; }
bool VulkanContext::validationEnabled() const { return impl_->validation; }
bool VulkanContext::multiviewSupported() const { return impl_->multiview; }
std::vector<std::string> VulkanContext::validationMessages() const {
  std::lock_guard<std::mutex> lock(impl_->messageMutex);
  return impl_->messages;
}
void VulkanContext::clearValidationMessages() {
  std::lock_guard<std::mutex> lock(impl_->messageMutex);
  impl_->messages.clear();
}
VkInstance VulkanContext::instance() const { return impl_->instance; }
VkPhysicalDevice VulkanContext::physicalDevice() const { return impl_->phys; }
VkDevice VulkanContext::device() const { return impl_->device; }
VkQueue VulkanContext::queue() const { return impl_->queue; }
uint32_t VulkanContext::queueFamilyIndex() const { return impl_->queueFamily; }

std::vector<uint32_t> loadSpirv(const std::string& path, std::string* error) {
  auto setError = [&](const std::string& m) {
    if (error) *error = m;
    return std::vector<uint32_t>{};
  };
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  if (!f) return setError("cannot open SPIR-V file '" + path + "'");
  std::streamoff size = f.tellg();
  if (size <= 0 || size % 4) return setError("'" + path + "': size " + std::to_string(size) + " is not a positive multiple of 4");
  std::vector<uint32_t> words(size_t(size) / 4);
  f.seekg(0);
  if (!f.read(reinterpret_cast<char*>(words.data()), size)) return setError("cannot read '" + path + "'");
  if (words[0] != 0x07230203u) return setError("'" + path + "' is not SPIR-V (bad magic number)");
  if (error) error->clear();
  return words;
}

}  // namespace stereoshift::harness
