// The harness's public surface (see vk_harness.h): what turns the internal HarnessError of any phase
// into a result's error string, the context's accessors, and loading SPIR-V files. The phases
// themselves live beside this file (vk_context_impl.h lists them).
#include "transpiler/verify/vk_context_impl.h"

#include <fstream>
#include <sstream>

namespace stereoshift::harness {

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

void checkResult(VkResult r, const char* expr, const char* file, int line) {
  if (r == VK_SUCCESS) return;
  std::ostringstream s;
  s << expr << " failed: " << resultName(r) << " (" << int(r) << ") at " << file << ":" << line;
  throw HarnessError(s.str(), r == VK_ERROR_DEVICE_LOST);
}

VulkanContext::VulkanContext(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
VulkanContext::~VulkanContext() = default;

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
