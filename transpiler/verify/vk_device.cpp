// The harness's set-up phase: the Vulkan instance (with the validation layer when asked for), the
// physical device it picks (lavapipe unless told otherwise), the logical device with every feature
// but robustness, its graphics queue and the transform-feedback entry points. Kept apart from the
// per-call phases because it runs once per context and is what fails on a machine without Vulkan.
#include "transpiler/verify/vk_context_impl.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace stereoshift::harness {
namespace {

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

// `name` among `extensions` (what a vkEnumerate*ExtensionProperties call listed).
bool listed(const std::vector<VkExtensionProperties>& extensions, const char* name) {
  for (auto& e : extensions)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

bool hasInstanceExtension(const char* layer, const char* name) {
  uint32_t n = 0;
  if (vkEnumerateInstanceExtensionProperties(layer, &n, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> ext(n);
  if (vkEnumerateInstanceExtensionProperties(layer, &n, ext.data()) != VK_SUCCESS) return false;
  return listed(ext, name);
}

bool hasDeviceExtension(VkPhysicalDevice pd, const char* name) {
  uint32_t n = 0;
  if (vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> ext(n);
  if (vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, ext.data()) != VK_SUCCESS) return false;
  return listed(ext, name);
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
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* impl = static_cast<VulkanContext::Impl*>(user);
  std::string m = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error: " : "warning: ";
  m += data && data->pMessage ? data->pMessage : "(no message)";
  impl->addMessage(std::move(m));
  return VK_FALSE;
}

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

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

  chooseValidation(options);
  uint32_t requested = std::min<uint32_t>(loaderVersion, VK_API_VERSION_1_3);
  createInstance(requested);
  pickDevice(options);
  apiVersion = std::min(requested, props.apiVersion);
  createDevice();
}

void VulkanContext::Impl::chooseValidation(const ContextOptions& options) {
  Validation v = options.validation;
  if (v == Validation::FromEnvironment) {
    const char* env = std::getenv("STEREOSHIFT_VK_VALIDATION");
    std::string s = env ? env : "";
    v = (s.empty() || s == "0" || s == "off") ? Validation::Off
        : (s == "auto")                       ? Validation::IfAvailable
                                              : Validation::Required;
  }
  if (v != Validation::Off) {
    bool have = hasLayer(kValidationLayer) &&
                (hasInstanceExtension(nullptr, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) ||
                 hasInstanceExtension(kValidationLayer, VK_EXT_DEBUG_UTILS_EXTENSION_NAME));
    if (!have && v == Validation::Required)
      fail("validation requested but VK_LAYER_KHRONOS_validation (with VK_EXT_debug_utils) is not installed "
           "(Debian package vulkan-validationlayers)");
    validation = have;
  }
}

void VulkanContext::Impl::createInstance(uint32_t requested) {
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
    layers.push_back(kValidationLayer);
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
    bufferDeviceAddress = f12.bufferDeviceAddress;
    multiview = f11.multiview;
    multiviewGeometry = f11.multiviewGeometryShader;
    multiviewTessellation = f11.multiviewTessellationShader;
  } else {
    multiview = mv.multiview;
    multiviewGeometry = mv.multiviewGeometryShader;
    multiviewTessellation = mv.multiviewTessellationShader;
  }

  pickQueueFamily();
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
  loadTransformFeedbackEntryPoints();
}

void VulkanContext::Impl::pickQueueFamily() {
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
}

void VulkanContext::Impl::loadTransformFeedbackEntryPoints() {
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

}  // namespace stereoshift::harness
