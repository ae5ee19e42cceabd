// stereoshift test harness: headless Vulkan execution of SPIR-V shaders.
//
// Two ways to run a shader set:
//   * capture(): a graphics pipeline with rasterizer discard whose last pre-rasterization stage
//     writes its outputs through VK_EXT_transform_feedback; returns the captured bytes and the
//     number of primitives written (VK_QUERY_TYPE_TRANSFORM_FEEDBACK_STREAM_EXT).
//   * render(): a list of draws into an offscreen RGBA8 colour target (+ D32 depth), read back.
//
// Everything is explicit and reflection-free: the caller lists vertex attributes, uniform buffers,
// textures, push constants and specialization constants. No window system is used. The device is
// the CPU implementation (lavapipe) unless STEREOSHIFT_VK_DEVICE=<index> picks another one.
//
// Coordinate conventions are Vulkan's: NDC y points down, depth range [0, 1], viewport covers the
// whole target, pixel (x, y) of a RenderResult is row y from the top.
//
// A VulkanContext is not thread-safe: use one per thread.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace stereoshift::harness {

// ---------------------------------------------------------------------------------------------
// Pipeline inputs shared by capture() and render()
// ---------------------------------------------------------------------------------------------

// One shader stage. `spirv` is a complete SPIR-V module (words, host endianness).
struct ShaderStage {
  VkShaderStageFlagBits stage = VK_SHADER_STAGE_VERTEX_BIT;
  std::vector<uint32_t> spirv;
  std::string entry = "main";
};

struct VertexAttribute {
  uint32_t location = 0;
  VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
  uint32_t offset = 0;  // byte offset inside one element of the binding
};

// Raw vertex data of one binding: element i starts at byte i * stride.
struct VertexBuffer {
  std::vector<uint8_t> bytes;
  uint32_t stride = 0;
  std::vector<VertexAttribute> attributes;
  bool empty() const { return attributes.empty(); }
};

// A uniform buffer (std140 bytes as the shader declares them), visible to all graphics stages.
struct UniformBuffer {
  uint32_t set = 0;
  uint32_t binding = 0;
  std::vector<uint8_t> bytes;
  bool storage = false;  // bind as a storage buffer, e.g. an HLSL StructuredBuffer or a GLSL buffer block
  // A descriptor array (`uniform Lights { ... } lights[4]`): `bytes` holds arrayCount elements of
  // equal size back to back; each element is its own buffer.
  uint32_t arrayCount = 1;
};

// An image descriptor. By default a combined image sampler over a 2D VK_FORMAT_R32G32B32A32_SFLOAT
// image, one mip level, nearest filtering, clamp-to-edge, unnormalized coordinates off. `rgba`
// holds width*height*depth*layers*4 32-bit values (floats, or the raw bits of an integer format),
// row-major, row 0 first (texture coordinate v = 0), then slice after slice and layer after layer.
// The other kinds a shader declares:
//   * viewType: 1D, 2D, 3D (depth slices), cube (layers = 6) and the array views (layers);
//   * type: COMBINED_IMAGE_SAMPLER, SAMPLED_IMAGE (a texture without sampler), SAMPLER (a sampler
//     alone: no image, `rgba` unused), STORAGE_IMAGE (layout GENERAL), UNIFORM_TEXEL_BUFFER and
//     STORAGE_TEXEL_BUFFER (a buffer view of `width` texels, `rgba` its texels);
//   * format: any colour format; only the 32-bit four-channel formats take `rgba` as their texels,
//     every other format is cleared to the first texel's value;
//   * arrayCount: a descriptor array (`sampler2D shadowMaps[4]`), `rgba` holding each element's
//     texels one after the other.
struct SampledTexture {
  uint32_t set = 0;
  uint32_t binding = 0;
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> rgba;
  VkImageViewType viewType = VK_IMAGE_VIEW_TYPE_2D;
  uint32_t depth = 1;
  uint32_t layers = 1;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
  uint32_t arrayCount = 1;
  size_t texelsPerElement() const { return size_t(width) * height * depth * layers; }
};

// A specialization constant: the 32 raw bits (float bits, int, uint or VkBool32). Applied to every
// stage of the pipeline; stages that do not declare the constant ID ignore it.
struct SpecConstant {
  uint32_t constantID = 0;
  uint32_t bits = 0;
};

// Memory a shader reaches through a buffer device address (GL_EXT_buffer_reference,
// vk::RawBufferLoad) rather than a descriptor: PipelineInputs::addressBuffers[i] is created with
// VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT, and wherever the push constants, a uniform buffer or
// an address buffer holds addressPlaceholder(i) (8 bytes at an 8-byte-aligned offset) the harness
// writes that buffer's address before the draw. No generated value has these high bits.
constexpr uint64_t kAddressPlaceholderTag = 0x5AD0DDA000000000ull;
constexpr uint64_t addressPlaceholder(uint32_t index) { return kAddressPlaceholderTag | index; }

struct PipelineInputs {
  // Vertex stage required; tessellation control + evaluation optional (both or neither);
  // geometry optional; fragment optional (render() only; ignored by capture()).
  std::vector<ShaderStage> stages;

  VertexBuffer vertices;                  // binding 0, VK_VERTEX_INPUT_RATE_VERTEX (may be empty)
  std::optional<VertexBuffer> instances;  // binding 1, VK_VERTEX_INPUT_RATE_INSTANCE

  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  uint32_t patchControlPoints = 0;  // required (>= 1) with VK_PRIMITIVE_TOPOLOGY_PATCH_LIST

  uint32_t vertexCount = 0;  // vertices to draw; ignored when `indices` is non-empty
  uint32_t instanceCount = 1;
  std::vector<uint32_t> indices;  // optional: vkCmdDrawIndexed with all these uint32 indices

  std::vector<UniformBuffer> uniformBuffers;
  std::vector<SampledTexture> textures;
  std::vector<uint8_t> pushConstants;  // offset 0, all graphics stages; size multiple of 4
  std::vector<SpecConstant> specConstants;
  std::vector<std::vector<uint8_t>> addressBuffers;  // see addressPlaceholder
};

// ---------------------------------------------------------------------------------------------
// Transform-feedback capture
// ---------------------------------------------------------------------------------------------

// The SPIR-V of the last pre-rasterization stage must already carry ExecutionMode Xfb and
// XfbBuffer 0 / XfbStride / Offset decorations on the captured outputs.
struct CaptureRequest {
  PipelineInputs pipeline;
  uint32_t xfbStride = 0;         // bytes per captured vertex, == the shader's XfbStride
  uint32_t expectedVertices = 0;  // capacity of the capture buffer, in vertices
};

struct CaptureResult {
  std::string error;           // empty on success
  std::vector<uint8_t> bytes;  // the bytes written to xfb buffer 0 (counter buffer value)
  uint32_t stride = 0;
  uint64_t primitivesWritten = 0;  // from VK_QUERY_TYPE_TRANSFORM_FEEDBACK_STREAM_EXT, stream 0
  uint64_t primitivesNeeded = 0;   // > primitivesWritten when the buffer was too small

  bool ok() const { return error.empty(); }
  uint32_t vertexCount() const { return stride ? uint32_t(bytes.size() / stride) : 0; }
  // Component `index` (in 4-byte units) of captured vertex `vertex`, as float / uint32 bits.
  float f32(uint32_t vertex, uint32_t index) const { return read<float>(vertex, index); }
  uint32_t u32(uint32_t vertex, uint32_t index) const { return read<uint32_t>(vertex, index); }

 private:
  template <class T>
  T read(uint32_t vertex, uint32_t index) const {
    T v{};
    size_t at = size_t(vertex) * stride + size_t(index) * 4;
    if (at + 4 <= bytes.size()) std::memcpy(&v, bytes.data() + at, 4);
    return v;
  }
};

// ---------------------------------------------------------------------------------------------
// Offscreen rendering
// ---------------------------------------------------------------------------------------------

struct Draw {
  PipelineInputs pipeline;
  bool depthTest = true;  // compare against the D32 depth buffer
  bool depthWrite = true;
  VkCompareOp depthCompare = VK_COMPARE_OP_LESS;
  bool colorWrite = true;   // false: depth-only draw (e.g. a depth pre-pass)
  bool alphaBlend = false;  // src*a + dst*(1-a) on colour, alpha kept as src + dst*(1-a)
};

struct RenderRequest {
  uint32_t width = 0;
  uint32_t height = 0;
  float clearColor[4] = {0.f, 0.f, 0.f, 1.f};
  float clearDepth = 1.f;
  // > 1: multiview (VK_KHR_multiview, core 1.1) into a layered target, view mask (1<<n)-1;
  // shaders see gl_ViewIndex. Pixels and depth come back layer after layer.
  uint32_t viewCount = 1;
  // With viewCount > 1: a plain layered target of viewCount layers instead (no view mask), where the
  // vertex stage picks the layer with gl_Layer (instanced single-pass stereo).
  bool layeredWithoutMultiview = false;
  bool readDepth = false;  // also return the depth buffer
  std::vector<Draw> draws;  // recorded in order inside one render pass
};

struct RenderResult {
  std::string error;            // empty on success
  uint32_t width = 0, height = 0, viewCount = 0;
  std::vector<uint8_t> pixels;  // width*height*4 RGBA8 per view, rows top to bottom
  std::vector<float> depth;     // width*height per view when readDepth
  // GPU time of the render pass (timestamps before and after it): the draws alone, not the pipeline
  // creation and uploads of the call; -1 where the queue writes no timestamps.
  double drawMilliseconds = -1;

  bool ok() const { return error.empty(); }
  const uint8_t* pixel(uint32_t x, uint32_t y, uint32_t view = 0) const {
    return pixels.data() + ((size_t(view) * height + y) * width + x) * 4;
  }
  float depthAt(uint32_t x, uint32_t y, uint32_t view = 0) const {
    return depth[(size_t(view) * height + y) * width + x];
  }
};

// ---------------------------------------------------------------------------------------------
// Descriptor layout (reflection-free: built from the listed resources; exposed for tests)
// ---------------------------------------------------------------------------------------------

struct DescriptorSlot {
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  uint32_t resourceIndex = 0;  // index into uniformBuffers or textures
  uint32_t count = 1;          // descriptor array size
};

// sets->at(s) lists the bindings of descriptor set s, sorted by binding; sets between 0 and the
// highest used set that have no resource are empty. Fails on a duplicate (set, binding).
bool buildDescriptorLayout(const PipelineInputs& inputs,
                           std::vector<std::vector<DescriptorSlot>>* sets, std::string* error);

// The render pass render() draws in, for callers that record their own frames (benchmarks): one
// subpass, a colour attachment (cleared, stored, left in TRANSFER_SRC for the read-back) and a depth
// attachment (cleared; stored and left in TRANSFER_SRC with keepDepth); viewMask != 0 makes it a
// multiview render pass with that view (and correlation) mask.
VkResult createColourDepthRenderPass(VkDevice device, VkFormat colourFormat, VkFormat depthFormat, uint32_t viewMask,
                                     bool keepDepth, VkRenderPass* renderPass);

// The fixed-function state of the harness's graphics pipelines, for callers that build their own
// (benchmarks) too: one viewport and scissor, both dynamic; filled polygons, no culling,
// counter-clockwise front faces; one sample; depth test and colour writes / blending as `draw` says
// (none at all without a draw). `discard`: the rasterizer discards (capture); `colourAttachment`:
// the render pass has one colour attachment.
class FixedFunctionState {
 public:
  explicit FixedFunctionState(const Draw* draw, bool discard = false, bool colourAttachment = true);
  ~FixedFunctionState();
  FixedFunctionState(const FixedFunctionState&) = delete;
  FixedFunctionState& operator=(const FixedFunctionState&) = delete;
  // Points `gci`'s viewport, rasterization, multisample, depth-stencil, colour-blend and dynamic
  // state here (valid while this object lives).
  void applyTo(VkGraphicsPipelineCreateInfo* gci) const;

 private:
  struct CreateInfos;
  std::unique_ptr<CreateInfos> infos_;
};

// How the harness describes a 2D attachment image (one mip level, `layers` layers, optimal tiling,
// exclusive, layout undefined) and views an image, for callers that create their own (benchmarks).
VkImageCreateInfo imageInfo2D(VkFormat format, uint32_t width, uint32_t height, uint32_t layers, VkImageUsageFlags usage);
VkResult createImageView(VkDevice device, VkImage image, VkImageViewType type, VkFormat format,
                         const VkImageSubresourceRange& range, VkImageView* view);

// ---------------------------------------------------------------------------------------------
// The context
// ---------------------------------------------------------------------------------------------

enum class Validation {
  FromEnvironment,  // STEREOSHIFT_VK_VALIDATION: unset/0 = Off, "auto" = IfAvailable, else Required
  Off,
  IfAvailable,  // VK_LAYER_KHRONOS_validation when installed
  Required,     // create() fails when the layer is missing
};

struct ContextOptions {
  Validation validation = Validation::FromEnvironment;
  int deviceIndex = -1;  // -1: STEREOSHIFT_VK_DEVICE if set, else the CPU device (lavapipe),
                         // else the first device with transform feedback
  // Also receives every validation message, including those emitted while the context is being
  // destroyed (e.g. objects still alive at vkDestroyDevice). Must outlive the context.
  std::function<void(const std::string&)> messageSink;
};

class VulkanContext {
 public:
  // nullptr and *error set when Vulkan 1.1, a suitable device, or VK_EXT_transform_feedback
  // (transformFeedback feature) is unavailable.
  static std::unique_ptr<VulkanContext> create(std::string* error, const ContextOptions& options = {});

  // True when the loader exists and reports at least one physical device. Tests call this to
  // GTEST_SKIP on machines without any Vulkan implementation; everything else is a failure.
  static bool anyDeviceAvailable(std::string* why = nullptr);

  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  CaptureResult capture(const CaptureRequest& request);
  RenderResult render(const RenderRequest& request);

  std::string deviceName() const;
  const VkPhysicalDeviceProperties& properties() const;  // limits such as maxPushConstantsSize
  const VkPhysicalDeviceFeatures& features() const;      // the core features enabled on the device
  VkPhysicalDeviceType deviceType() const;
  uint32_t apiVersion() const;  // the version used (min of loader and device)
  bool validationEnabled() const;
  bool multiviewSupported() const;
  // Messages of severity warning or error from the validation layer since the last clear.
  std::vector<std::string> validationMessages() const;
  void clearValidationMessages();

  VkInstance instance() const;
  VkPhysicalDevice physicalDevice() const;
  VkDevice device() const;
  // The graphics queue render() and capture() submit to, for callers that record their own commands.
  VkQueue queue() const;
  uint32_t queueFamilyIndex() const;

  struct Impl;

 private:
  explicit VulkanContext(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// ---------------------------------------------------------------------------------------------
// Utilities
// ---------------------------------------------------------------------------------------------

// Loads a .spv file; empty vector and *error set on failure (missing, size not a multiple of 4,
// bad magic number).
std::vector<uint32_t> loadSpirv(const std::string& path, std::string* error = nullptr);

template <class T>
std::vector<uint8_t> toBytes(const T* data, size_t count) {
  std::vector<uint8_t> out(sizeof(T) * count);
  if (count) std::memcpy(out.data(), data, out.size());
  return out;
}
template <class T>
std::vector<uint8_t> toBytes(const std::vector<T>& v) {
  return toBytes(v.data(), v.size());
}

inline uint32_t floatBits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

// PNG (8-bit RGBA, non-interlaced, zlib stream of stored deflate blocks).
std::vector<uint8_t> encodePng(int width, int height, const uint8_t* rgba);
bool writePng(const std::string& path, int width, int height, const uint8_t* rgba);
// A red/cyan anaglyph of two RGBA8 images of `pixels` pixels: red from the left eye, green and
// blue from the right, opaque.
std::vector<uint8_t> anaglyph(const std::vector<uint8_t>& left, const std::vector<uint8_t>& right, size_t pixels);

}  // namespace stereoshift::harness
