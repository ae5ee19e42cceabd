// Single-pass stereo against two passes, side by side in one run (issue 14; docs/accuracy-and-benchmarks.md "Single-pass
// stereo"). One mono vertex shader in a common engine style (a camera block, a per-draw model matrix
// and colour in a push constant) is converted three ways to SPIR-V, and one frame of N small draws
// (default 2000 meshes of 4 triangles) is recorded and submitted in each mode into a 2-layer target:
//   two-pass:  the scene recorded twice, one render pass per layer, eyeSign -1 then +1 in the
//              StereoParams block (one descriptor set per eye; the default --eye-source);
//   multiview: recorded once, render pass view mask 0b11 (--eye-source multiview);
//   instanced: recorded once, every draw with twice the instances, the vertex shader writing gl_Layer
//              (--eye-source instanced).
// Per mode it prints the draw calls recorded, the vertex shader invocations (pipeline statistics
// queries in the render passes), the CPU time of recording the frame's command buffer (steady_clock
// around vkBeginCommandBuffer .. vkEndCommandBuffer) and the GPU time of its render passes (timestamps),
// medians over --reps frames with the modes interleaved (the order rotates every frame; one warm-up
// frame per mode is not counted), then the ratios to two-pass. Every frame's two layers are read back;
// both single-pass modes must equal the two-pass frame bit for bit (so the figures are for the same
// image) and the eyes must differ, else the exit status is 1. Nothing here asserts a speed.
//
// On lavapipe the "GPU" is the CPU: its times say how much vertex and fragment work a mode does on
// this machine, not what a GPU with hardware multiview would do; the invocation counts and draw
// calls are the portable figures.
//
//   build/bench/single_pass_bench [--draws N] [--triangles T] [--reps R] [--size S]
#include "transpiler/stereoshift.h"
#include "transpiler/verify/vk_harness.h"

#include <stereoshift/stereo_runtime.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

using namespace stereoshift;
using namespace stereoshift::harness;
namespace runtime = stereoshift::runtime;

namespace {

const char* kVertexShader = R"(#version 450
layout(location = 0) in vec3 inPosition;
layout(set = 0, binding = 0) uniform Camera { mat4 viewProjection; } camera;
layout(push_constant) uniform PerDraw { mat4 model; vec4 colour; } perDraw;
layout(location = 0) flat out vec4 vColour;
void main() {
  gl_Position = camera.viewProjection * (perDraw.model * vec4(inPosition, 1.0));
  vColour = perDraw.colour;
}
)";

const char* kFragmentShader = R"(#version 450
layout(location = 0) flat in vec4 vColour;
layout(location = 0) out vec4 outColour;
void main() { outColour = vColour; }
)";

constexpr float kSeparation = 0.06f, kConvergence = 3.0f;
constexpr uint32_t kMeshVariants = 8;  // meshes in the shared vertex buffer; draw i uses mesh i % 8
constexpr uint32_t kQueriesPerPass = 2, kMaxPasses = 2;
constexpr VkFormat kColourFormat = VK_FORMAT_R8G8B8A8_UNORM, kDepthFormat = VK_FORMAT_D32_SFLOAT;

void check(VkResult r, const char* what) {
  if (r != VK_SUCCESS) throw std::runtime_error(std::string(what) + " failed (VkResult " + std::to_string(int(r)) + ")");
}

std::vector<uint32_t> words(const std::string& bytes) {
  std::vector<uint32_t> w(bytes.size() / 4);
  std::memcpy(w.data(), bytes.data(), w.size() * 4);
  return w;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// ---- the scene --------------------------------------------------------------------------------

struct PerDraw {  // the shader's push-constant block
  float model[16];
  float colour[4];
};
static_assert(offsetof(PerDraw, colour) == 64 && sizeof(PerDraw) == 80, "PerDraw must match the shader's block");

struct DrawItem {
  PerDraw perDraw;
  uint32_t firstVertex = 0;
};

struct Scene {
  std::vector<float> vertices;  // kMeshVariants meshes of verticesPerMesh xyz vertices, back to back
  uint32_t verticesPerMesh = 0;
  std::vector<DrawItem> draws;
  float viewProjection[16] = {};
};

// Fans of `triangles` triangles (unit radius, each variant turned and with its own rim), placed at
// random in front of the camera, eye depth 2 .. 8 around the convergence 3, about 12 pixels across
// at 256 x 256 whatever their depth. A fixed seed: every run draws the same scene.
Scene makeScene(uint32_t draws, uint32_t triangles) {
  Scene s;
  s.verticesPerMesh = 3 * triangles;
  const float pi = 3.14159265f;
  for (uint32_t m = 0; m < kMeshVariants; ++m)
    for (uint32_t t = 0; t < triangles; ++t) {
      auto rim = [&](uint32_t k, float* out) {
        // At most a third of the circle per triangle: one or two triangles are wedges, not slivers.
        float angle = 2 * pi * float(k) / float(std::max(triangles, 3u)) + 0.4f * float(m);
        float radius = 1.0f - 0.15f * float((k + m) % 3);
        out[0] = radius * std::cos(angle);
        out[1] = radius * std::sin(angle);
        out[2] = 0;
      };
      float v[9] = {0, 0, 0};
      rim(t, v + 3);
      rim(t + 1, v + 6);
      s.vertices.insert(s.vertices.end(), v, v + 9);
    }
  // Left-handed perspective with Vulkan depth [0, 1]: clip w = eye depth z, 90 degrees both ways.
  const float nearZ = 0.5f, farZ = 20.0f;
  s.viewProjection[0] = s.viewProjection[5] = 1;
  s.viewProjection[10] = farZ / (farZ - nearZ);
  s.viewProjection[11] = 1;
  s.viewProjection[14] = -farZ * nearZ / (farZ - nearZ);
  uint32_t state = 12345;
  auto uniform = [&] {  // [0, 1), a 32-bit LCG's top 24 bits
    state = state * 1664525u + 1013904223u;
    return float(state >> 8) / float(1u << 24);
  };
  for (uint32_t i = 0; i < draws; ++i) {
    DrawItem d{};
    const float u = -0.95f + 1.9f * uniform(), v = -0.95f + 1.9f * uniform(), z = 2.0f + 6.0f * uniform();
    const float scale = 0.05f * z;  // 0.05 in NDC at any depth
    float* model = d.perDraw.model;
    model[0] = model[5] = model[10] = scale;
    model[12] = u * z;  // NDC x = x / z with P00 = 1
    model[13] = v * z;
    model[14] = z;
    model[15] = 1;
    for (int c = 0; c < 3; ++c) d.perDraw.colour[c] = 0.2f + 0.8f * uniform();
    d.perDraw.colour[3] = 1;
    d.firstVertex = (i % kMeshVariants) * s.verticesPerMesh;
    s.draws.push_back(d);
  }
  return s;
}

// ---- Vulkan objects on the harness's device ------------------------------------------------------

// Everything this bench creates, destroyed in reverse order of creation before the context goes.
class Device {
 public:
  explicit Device(VulkanContext& context) : device_(context.device()) {
    vkGetPhysicalDeviceMemoryProperties(context.physicalDevice(), &memory_);
  }
  ~Device() {
    vkDeviceWaitIdle(device_);
    for (auto it = undo_.rbegin(); it != undo_.rend(); ++it) (*it)();
  }
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  VkDevice handle() const { return device_; }
  void onDestroy(std::function<void()> f) { undo_.push_back(std::move(f)); }

  struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    void* mapped = nullptr;
  };
  Buffer hostBuffer(VkDeviceSize size, VkBufferUsageFlags usage) {
    Buffer b;
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bci.size = size;
    bci.usage = usage;
    check(vkCreateBuffer(device_, &bci, nullptr, &b.buffer), "vkCreateBuffer");
    VkBuffer buffer = b.buffer;
    onDestroy([this, buffer] { vkDestroyBuffer(device_, buffer, nullptr); });
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, b.buffer, &req);
    VkDeviceMemory mem = allocate(req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, true);
    check(vkBindBufferMemory(device_, b.buffer, mem, 0), "vkBindBufferMemory");
    check(vkMapMemory(device_, mem, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
    return b;
  }

  // A 2-layer attachment with a view of both layers (multiview, instanced) and one of each (two-pass).
  struct LayeredImage {
    VkImage image = VK_NULL_HANDLE;
    VkImageView bothLayers = VK_NULL_HANDLE;
    VkImageView layer[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
  };
  LayeredImage layeredImage(VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect, uint32_t size) {
    LayeredImage img;
    const VkImageCreateInfo ici = imageInfo2D(format, size, size, 2, usage);
    check(vkCreateImage(device_, &ici, nullptr, &img.image), "vkCreateImage");
    VkImage image = img.image;
    onDestroy([this, image] { vkDestroyImage(device_, image, nullptr); });
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device_, img.image, &req);
    check(vkBindImageMemory(device_, img.image, allocate(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, false), 0),
          "vkBindImageMemory");
    auto view = [&](VkImageViewType type, uint32_t first, uint32_t count) {
      VkImageView v = VK_NULL_HANDLE;
      check(createImageView(device_, img.image, type, format, {aspect, 0, 1, first, count}, &v), "vkCreateImageView");
      onDestroy([this, v] { vkDestroyImageView(device_, v, nullptr); });
      return v;
    };
    img.bothLayers = view(VK_IMAGE_VIEW_TYPE_2D_ARRAY, 0, 2);
    img.layer[0] = view(VK_IMAGE_VIEW_TYPE_2D, 0, 1);
    img.layer[1] = view(VK_IMAGE_VIEW_TYPE_2D, 1, 1);
    return img;
  }

  // The harness's render pass (colour kept for the copy to the host, depth dropped);
  // viewMask != 0 makes it a multiview render pass.
  VkRenderPass renderPass(uint32_t viewMask) {
    VkRenderPass rp = VK_NULL_HANDLE;
    check(createColourDepthRenderPass(device_, kColourFormat, kDepthFormat, viewMask, false, &rp), "vkCreateRenderPass");
    onDestroy([this, rp] { vkDestroyRenderPass(device_, rp, nullptr); });
    return rp;
  }

  VkFramebuffer framebuffer(VkRenderPass rp, VkImageView colour, VkImageView depth, uint32_t size, uint32_t layers) {
    VkImageView views[2] = {colour, depth};
    VkFramebufferCreateInfo fci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fci.renderPass = rp;
    fci.attachmentCount = 2;
    fci.pAttachments = views;
    fci.width = fci.height = size;
    fci.layers = layers;
    VkFramebuffer fb = VK_NULL_HANDLE;
    check(vkCreateFramebuffer(device_, &fci, nullptr, &fb), "vkCreateFramebuffer");
    onDestroy([this, fb] { vkDestroyFramebuffer(device_, fb, nullptr); });
    return fb;
  }

  // Opaque, depth-tested, no culling (the harness's fixed-function state); viewport and scissor set
  // per render pass as an engine would.
  VkPipeline pipeline(VkPipelineLayout layout, VkRenderPass rp, const std::vector<uint32_t>& vertex,
                      const std::vector<uint32_t>& fragment) {
    VkPipelineShaderStageCreateInfo stages[2]{};
    const std::vector<uint32_t>* code[2] = {&vertex, &fragment};
    const VkShaderStageFlagBits kinds[2] = {VK_SHADER_STAGE_VERTEX_BIT, VK_SHADER_STAGE_FRAGMENT_BIT};
    for (int i = 0; i < 2; ++i) {
      VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
      smci.codeSize = code[i]->size() * 4;
      smci.pCode = code[i]->data();
      VkShaderModule module = VK_NULL_HANDLE;
      check(vkCreateShaderModule(device_, &smci, nullptr, &module), "vkCreateShaderModule");
      onDestroy([this, module] { vkDestroyShaderModule(device_, module, nullptr); });
      stages[i] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, kinds[i], module, "main", nullptr};
    }
    VkVertexInputBindingDescription binding{0, 12, VK_VERTEX_INPUT_RATE_VERTEX};
    VkVertexInputAttributeDescription attribute{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0};
    VkPipelineVertexInputStateCreateInfo vis{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vis.vertexBindingDescriptionCount = 1;
    vis.pVertexBindingDescriptions = &binding;
    vis.vertexAttributeDescriptionCount = 1;
    vis.pVertexAttributeDescriptions = &attribute;
    VkPipelineInputAssemblyStateCreateInfo ias{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ias.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    const Draw opaque;  // depth-tested (less, written), colour written, no blending
    const FixedFunctionState state(&opaque);
    VkGraphicsPipelineCreateInfo gci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    gci.stageCount = 2;
    gci.pStages = stages;
    gci.pVertexInputState = &vis;
    gci.pInputAssemblyState = &ias;
    state.applyTo(&gci);
    gci.layout = layout;
    gci.renderPass = rp;
    VkPipeline p = VK_NULL_HANDLE;
    check(vkCreateGraphicsPipelines(device_, VK_NULL_HANDLE, 1, &gci, nullptr, &p), "vkCreateGraphicsPipelines");
    onDestroy([this, p] { vkDestroyPipeline(device_, p, nullptr); });
    return p;
  }

 private:
  VkDeviceMemory allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags flags, bool required) {
    uint32_t type = UINT32_MAX;
    for (int pass = 0; pass < 2 && type == UINT32_MAX; ++pass)
      for (uint32_t i = 0; i < memory_.memoryTypeCount && type == UINT32_MAX; ++i)
        if ((req.memoryTypeBits & (1u << i)) &&
            (pass == 1 && !required ? true : (memory_.memoryTypes[i].propertyFlags & flags) == flags))
          type = i;
    if (type == UINT32_MAX) throw std::runtime_error("no suitable memory type");
    VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    mai.allocationSize = req.size;
    mai.memoryTypeIndex = type;
    VkDeviceMemory mem = VK_NULL_HANDLE;
    check(vkAllocateMemory(device_, &mai, nullptr, &mem), "vkAllocateMemory");
    onDestroy([this, mem] { vkFreeMemory(device_, mem, nullptr); });
    return mem;
  }

  VkDevice device_;
  VkPhysicalDeviceMemoryProperties memory_{};
  std::vector<std::function<void()>> undo_;
};

// ---- the three modes ----------------------------------------------------------------------------

struct Converted {
  std::vector<uint32_t> spirv;
  uint32_t eyeSet = 0, eyeBinding = 0;
};

Converted convertVertexShader(EyeSelect select) {
  TranspileOptions options;
  options.target = TargetLanguage::Spirv;
  options.eye.select = select;
  TranspileResult r = transpile(SourceFile{"scene.vert", kVertexShader}, options);
  if (!r.ok) throw std::runtime_error("the vertex shader does not convert:\n" + r.diagnostics.format());
  if (r.report.value("classification", std::string()) != "perspective")
    throw std::runtime_error("the vertex shader is not classified perspective: nothing would be shifted");
  const auto& eye = r.report["passes"]["eye-params"];
  return {words(r.output), eye.value("set", 0u), eye.value("binding", 0u)};
}

struct Mode {
  const char* name = "";
  EyeSelect select = EyeSelect::Parameter;
  runtime::SinglePassSetup setup;       // of every draw (the mono renderer draws 1 instance, first 0)
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  uint32_t framebufferLayers = 1;
  std::vector<VkFramebuffer> passes;    // one render pass each
  std::vector<VkDescriptorSet> sets;    // the descriptor set each render pass binds
  VkCommandBuffer frame = VK_NULL_HANDLE;
  // Results
  uint32_t drawCalls = 0;
  std::vector<double> recordMs, gpuMs;
  uint64_t vertexInvocations = 0, fragmentInvocations = 0;
  size_t unavailableViewQueries = 0;  // per-view statistics queries the driver left unwritten
  std::vector<uint8_t> pixels;  // the last frame's two layers
  size_t framesDiffering = 0;   // against the two-pass frame of the same repetition
  size_t lastDifferingPixels[2] = {0, 0};
};

struct Frame {
  const Scene* scene = nullptr;
  uint32_t size = 0;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkBuffer vertices = VK_NULL_HANDLE;
  // Pipeline statistics (null without pipelineStatisticsQuery), one query inside each render pass:
  // inside a multiview render pass a query takes one index per view and the driver may split the
  // counts among them, so render pass p owns the kQueriesPerPass indices from kQueriesPerPass * p.
  VkQueryPool statistics = VK_NULL_HANDLE;
  VkQueryPool timestamps = VK_NULL_HANDLE;  // null where the queue writes none
};

// The frame's command buffer, from vkBeginCommandBuffer to vkEndCommandBuffer (what is timed):
// one render pass per entry of mode.passes, the scene's draws in each. Returns the draw calls.
uint32_t recordFrame(const Mode& mode, const Frame& f) {
  VkCommandBuffer cb = mode.frame;
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cb, &bi), "vkBeginCommandBuffer");
  if (f.timestamps) {
    vkCmdResetQueryPool(cb, f.timestamps, 0, 2);
    vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, f.timestamps, 0);
  }
  if (f.statistics) vkCmdResetQueryPool(cb, f.statistics, 0, kQueriesPerPass * kMaxPasses);
  VkClearValue clears[2];
  clears[0].color = {{0.0f, 0.0f, 0.0f, 1.0f}};
  clears[1].depthStencil = {1.0f, 0};
  const VkViewport viewport{0, 0, float(f.size), float(f.size), 0, 1};
  const VkRect2D area{{0, 0}, {f.size, f.size}};
  const VkDeviceSize zero = 0;
  uint32_t drawCalls = 0;
  for (size_t pass = 0; pass < mode.passes.size(); ++pass) {
    VkRenderPassBeginInfo rbi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    rbi.renderPass = mode.renderPass;
    rbi.framebuffer = mode.passes[pass];
    rbi.renderArea = area;
    rbi.clearValueCount = 2;
    rbi.pClearValues = clears;
    vkCmdBeginRenderPass(cb, &rbi, VK_SUBPASS_CONTENTS_INLINE);
    if (f.statistics) vkCmdBeginQuery(cb, f.statistics, kQueriesPerPass * uint32_t(pass), 0);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, mode.pipeline);
    vkCmdSetViewport(cb, 0, 1, &viewport);
    vkCmdSetScissor(cb, 0, 1, &area);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, f.layout, 0, 1, &mode.sets[pass], 0, nullptr);
    vkCmdBindVertexBuffers(cb, 0, 1, &f.vertices, &zero);
    for (const DrawItem& d : f.scene->draws) {
      vkCmdPushConstants(cb, f.layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(PerDraw), &d.perDraw);
      vkCmdDraw(cb, f.scene->verticesPerMesh, mode.setup.instanceCount, d.firstVertex, mode.setup.firstInstance);
      ++drawCalls;
    }
    if (f.statistics) vkCmdEndQuery(cb, f.statistics, kQueriesPerPass * uint32_t(pass));
    vkCmdEndRenderPass(cb);
  }
  if (f.timestamps) vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, f.timestamps, 1);
  check(vkEndCommandBuffer(cb), "vkEndCommandBuffer");
  return drawCalls;
}

size_t differingPixels(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b, uint32_t layer, uint32_t size) {
  const size_t pixels = size_t(size) * size, first = pixels * layer;
  size_t n = 0;
  for (size_t p = first; p < first + pixels; ++p) n += std::memcmp(&a[p * 4], &b[p * 4], 4) != 0;
  return n;
}

size_t differingLayers(const std::vector<uint8_t>& image, uint32_t size) {
  const size_t pixels = size_t(size) * size;
  size_t n = 0;
  for (size_t p = 0; p < pixels; ++p) n += std::memcmp(&image[p * 4], &image[(pixels + p) * 4], 4) != 0;
  return n;
}

// One run of the benchmark, phase by phase: the modes and their shaders, the Vulkan objects they
// share (layouts, eye descriptor sets, vertex buffer, 2-layer target, command buffers, queries),
// the interleaved frames, then the table and the image verdict.
class SinglePassBench {
 public:
  SinglePassBench(VulkanContext& context, uint32_t drawCount, uint32_t triangles, int reps, uint32_t size)
      : context_(context), gpu_(context), dev_(gpu_.handle()), scene_(makeScene(drawCount, triangles)),
        drawCount_(drawCount), triangles_(triangles), reps_(reps), size_(size) {}

  int run() {
    chooseModes();
    convertShaders();
    createLayouts();
    writeEyeSets();
    Device::Buffer vertexBuffer = gpu_.hostBuffer(scene_.vertices.size() * 4, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    std::memcpy(vertexBuffer.mapped, scene_.vertices.data(), scene_.vertices.size() * 4);
    frame_.vertices = vertexBuffer.buffer;
    createTargetsAndPipelines();
    createCommandBuffers();
    createQueries();
    measure();
    printTable();
    return verdict();
  }

 private:
  void chooseModes() {
    modes_.resize(3);
    modes_[0].name = "two-pass";
    modes_[0].select = EyeSelect::Parameter;
    modes_[0].setup.instanceCount = 1;  // the mono draw, once per eye
    modes_[0].setup.layerCount = 2;
    modes_[1].name = "multiview";
    modes_[1].select = EyeSelect::ViewIndex;
    modes_[1].setup = runtime::singlePassSetup(runtime::SinglePassMode::Multiview, 1, 0);
    modes_[2].name = "instanced";
    modes_[2].select = EyeSelect::InstanceIndex;
    modes_[2].setup = runtime::singlePassSetup(runtime::SinglePassMode::InstancedLayer, 1, 0);
    if (!context_.multiviewSupported()) {
      std::printf("multiview: not supported by %s, left out\n", context_.deviceName().c_str());
      modes_.erase(modes_.begin() + 1);
    }
  }

  void convertShaders() {
    fragment_ = transpile(SourceFile{"scene.frag", kFragmentShader}, TranspileOptions{});
    if (!fragment_.ok) throw std::runtime_error("the fragment shader does not compile:\n" + fragment_.diagnostics.format());
    for (const Mode& m : modes_) {
      vertex_.push_back(convertVertexShader(m.select));
      if (vertex_.back().eyeSet != 0 || vertex_.back().eyeBinding == 0)
        throw std::runtime_error("the eye block is not in set 0 beside the camera block: set " +
                                 std::to_string(vertex_.back().eyeSet) + ", binding " +
                                 std::to_string(vertex_.back().eyeBinding));
      if (vertex_.back().eyeBinding != vertex_[0].eyeBinding)
        throw std::runtime_error("the modes put the eye block at different bindings");
    }
  }

  // Set 0: the camera at binding 0, StereoParams at the binding the conversion chose; the per-draw
  // push constants.
  void createLayouts() {
    const VkDevice dev = dev_;
    bindings_[0] = {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr};
    bindings_[1] = {vertex_[0].eyeBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = 2;
    lci.pBindings = bindings_;
    check(vkCreateDescriptorSetLayout(dev, &lci, nullptr, &setLayout_), "vkCreateDescriptorSetLayout");
    const VkDescriptorSetLayout setLayout = setLayout_;
    gpu_.onDestroy([dev, setLayout] { vkDestroyDescriptorSetLayout(dev, setLayout, nullptr); });
    VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(PerDraw)};
    VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &setLayout_;
    plci.pushConstantRangeCount = 1;
    plci.pPushConstantRanges = &push;
    frame_.scene = &scene_;
    frame_.size = size_;
    check(vkCreatePipelineLayout(dev, &plci, nullptr, &frame_.layout), "vkCreatePipelineLayout");
    const VkPipelineLayout pipelineLayout = frame_.layout;
    gpu_.onDestroy([dev, pipelineLayout] { vkDestroyPipelineLayout(dev, pipelineLayout, nullptr); });
  }

  // One set per eye for two-pass, one with eyeSign 0 (ignored by the shaders) for both single-pass
  // modes, each pointing at the camera and its StereoParams in one uniform buffer.
  void writeEyeSets() {
    const VkDevice dev = dev_;
    const VkDeviceSize align = std::max<VkDeviceSize>(context_.properties().limits.minUniformBufferOffsetAlignment, 64);
    Device::Buffer uniforms = gpu_.hostBuffer(4 * align, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    auto* uniformBytes = static_cast<uint8_t*>(uniforms.mapped);
    std::memcpy(uniformBytes, scene_.viewProjection, sizeof scene_.viewProjection);
    const runtime::StereoParams eyes[3] = {
        {-1.0f, kSeparation, kConvergence}, {1.0f, kSeparation, kConvergence},
        runtime::singlePassParams(kSeparation, kConvergence)};
    for (int e = 0; e < 3; ++e) std::memcpy(uniformBytes + (e + 1) * align, &eyes[e], sizeof eyes[e]);

    VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 6};
    VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    dpci.maxSets = 3;
    dpci.poolSizeCount = 1;
    dpci.pPoolSizes = &poolSize;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    check(vkCreateDescriptorPool(dev, &dpci, nullptr, &pool), "vkCreateDescriptorPool");
    gpu_.onDestroy([dev, pool] { vkDestroyDescriptorPool(dev, pool, nullptr); });
    VkDescriptorSetLayout setLayouts[3] = {setLayout_, setLayout_, setLayout_};
    VkDescriptorSetAllocateInfo dai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    dai.descriptorPool = pool;
    dai.descriptorSetCount = 3;
    dai.pSetLayouts = setLayouts;
    check(vkAllocateDescriptorSets(dev, &dai, eyeSets_), "vkAllocateDescriptorSets");
    for (int e = 0; e < 3; ++e) {
      VkDescriptorBufferInfo infos[2] = {{uniforms.buffer, 0, sizeof scene_.viewProjection},
                                         {uniforms.buffer, (e + 1) * align, sizeof(runtime::StereoParams)}};
      VkWriteDescriptorSet writes[2]{};
      for (int b = 0; b < 2; ++b) {
        writes[b] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[b].dstSet = eyeSets_[e];
        writes[b].dstBinding = bindings_[b].binding;
        writes[b].descriptorCount = 1;
        writes[b].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        writes[b].pBufferInfo = &infos[b];
      }
      vkUpdateDescriptorSets(dev, 2, writes, 0, nullptr);
    }
  }

  // The 2-layer colour and depth target, and per mode its render pass, pipeline, framebuffers and sets.
  void createTargetsAndPipelines() {
    layers_ = modes_[0].setup.layerCount;
    colour_ = gpu_.layeredImage(kColourFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                VK_IMAGE_ASPECT_COLOR_BIT, size_);
    Device::LayeredImage depth =
        gpu_.layeredImage(kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT, size_);
    const VkRenderPass plainPass = gpu_.renderPass(0);
    for (size_t i = 0; i < modes_.size(); ++i) {
      Mode& m = modes_[i];
      if (std::popcount(m.setup.viewMask) > int(kQueriesPerPass) || (m.select == EyeSelect::Parameter ? 2 : 1) > kMaxPasses)
        throw std::runtime_error("the statistics query pool is too small for this mode");
      if (m.setup.layerCount != layers_) throw std::runtime_error("the modes disagree on the target's layers");
      m.renderPass = m.setup.viewMask ? gpu_.renderPass(m.setup.viewMask) : plainPass;
      m.pipeline = gpu_.pipeline(frame_.layout, m.renderPass, vertex_[i].spirv, fragment_.originalSpirv);
      if (m.select == EyeSelect::Parameter) {
        for (uint32_t eye = 0; eye < 2; ++eye) {
          m.passes.push_back(gpu_.framebuffer(m.renderPass, colour_.layer[eye], depth.layer[eye], size_, 1));
          m.sets.push_back(eyeSets_[eye]);
        }
      } else {
        // Multiview: the view mask picks the layers, the framebuffer has one. Instanced: gl_Layer does.
        m.passes.push_back(gpu_.framebuffer(m.renderPass, colour_.bothLayers, depth.bothLayers, size_,
                                            m.setup.viewMask ? 1 : layers_));
        m.sets.push_back(eyeSets_[2]);
      }
    }
  }

  // One command buffer per mode's frame, and the read-back of both layers, recorded once and
  // submitted after every frame (not timed).
  void createCommandBuffers() {
    const VkDevice dev = dev_;
    VkCommandPoolCreateInfo cpci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    cpci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    cpci.queueFamilyIndex = context_.queueFamilyIndex();
    VkCommandPool commandPool = VK_NULL_HANDLE;
    check(vkCreateCommandPool(dev, &cpci, nullptr, &commandPool), "vkCreateCommandPool");
    gpu_.onDestroy([dev, commandPool] { vkDestroyCommandPool(dev, commandPool, nullptr); });
    std::vector<VkCommandBuffer> commandBuffers(modes_.size() + 1);
    VkCommandBufferAllocateInfo cai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    cai.commandPool = commandPool;
    cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cai.commandBufferCount = uint32_t(commandBuffers.size());
    check(vkAllocateCommandBuffers(dev, &cai, commandBuffers.data()), "vkAllocateCommandBuffers");
    for (size_t i = 0; i < modes_.size(); ++i) modes_[i].frame = commandBuffers[i];

    imageBytes_ = size_t(size_) * size_ * 4 * layers_;
    readback_ = gpu_.hostBuffer(imageBytes_, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    copy_ = commandBuffers.back();
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    check(vkBeginCommandBuffer(copy_, &bi), "vkBeginCommandBuffer");
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, layers_};
    region.imageExtent = {size_, size_, 1};
    vkCmdCopyImageToBuffer(copy_, colour_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer, 1, &region);
    VkMemoryBarrier mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    mb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    mb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(copy_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &mb, 0, nullptr, 0,
                         nullptr);
    check(vkEndCommandBuffer(copy_), "vkEndCommandBuffer");
  }

  // Pipeline statistics (where the device has them), timestamps (where the queue writes them), a fence.
  void createQueries() {
    const VkDevice dev = dev_;
    statistics_ = context_.features().pipelineStatisticsQuery;
    if (statistics_) {
      VkQueryPoolCreateInfo qci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
      qci.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
      qci.queryCount = kQueriesPerPass * kMaxPasses;
      qci.pipelineStatistics = VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT |
                               VK_QUERY_PIPELINE_STATISTIC_FRAGMENT_SHADER_INVOCATIONS_BIT;
      check(vkCreateQueryPool(dev, &qci, nullptr, &frame_.statistics), "vkCreateQueryPool");
      const VkQueryPool q = frame_.statistics;
      gpu_.onDestroy([dev, q] { vkDestroyQueryPool(dev, q, nullptr); });
    }
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(context_.physicalDevice(), &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(context_.physicalDevice(), &familyCount, families.data());
    timestampBits_ = families[context_.queueFamilyIndex()].timestampValidBits;
    tickNs_ = context_.properties().limits.timestampPeriod;
    if (timestampBits_ && tickNs_ > 0) {
      VkQueryPoolCreateInfo qci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
      qci.queryType = VK_QUERY_TYPE_TIMESTAMP;
      qci.queryCount = 2;
      check(vkCreateQueryPool(dev, &qci, nullptr, &frame_.timestamps), "vkCreateQueryPool");
      const VkQueryPool q = frame_.timestamps;
      gpu_.onDestroy([dev, q] { vkDestroyQueryPool(dev, q, nullptr); });
    }
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    check(vkCreateFence(dev, &fci, nullptr, &fence_), "vkCreateFence");
    const VkFence fence = fence_;
    gpu_.onDestroy([dev, fence] { vkDestroyFence(dev, fence, nullptr); });
  }

  // Frame 0 is the warm-up (first recordings grow the driver's command memory); then `reps` frames
  // per mode, the order rotating so that no mode always follows the same one.
  void measure() {
    for (int rep = 0; rep <= reps_; ++rep) {
      for (size_t k = 0; k < modes_.size(); ++k) runFrame(modes_[(size_t(rep) + k) % modes_.size()], rep);
      // This repetition's frames, each against the two-pass one.
      for (size_t i = 1; i < modes_.size(); ++i) {
        size_t l0 = differingPixels(modes_[i].pixels, modes_[0].pixels, 0, size_);
        size_t l1 = differingPixels(modes_[i].pixels, modes_[0].pixels, 1, size_);
        if (l0 || l1) {
          ++modes_[i].framesDiffering;
          modes_[i].lastDifferingPixels[0] = l0;
          modes_[i].lastDifferingPixels[1] = l1;
        }
      }
      eyesDiffer_ = differingLayers(modes_[0].pixels, size_);
    }
  }

  // One frame of `m`: recorded (timed), submitted with the read-back, its queries and pixels read.
  void runFrame(Mode& m, int rep) {
    check(vkResetCommandBuffer(m.frame, 0), "vkResetCommandBuffer");
    const auto start = std::chrono::steady_clock::now();
    m.drawCalls = recordFrame(m, frame_);
    const double recordMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    VkCommandBuffer submitted[2] = {m.frame, copy_};
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 2;
    si.pCommandBuffers = submitted;
    check(vkQueueSubmit(context_.queue(), 1, &si, fence_), "vkQueueSubmit");
    check(vkWaitForFences(dev_, 1, &fence_, VK_TRUE, 120ull * 1000 * 1000 * 1000), "vkWaitForFences");
    check(vkResetFences(dev_, 1, &fence_), "vkResetFences");
    if (frame_.statistics) readStatistics(m);
    const double gpuMs = readGpuMilliseconds();
    if (rep > 0) {
      m.recordMs.push_back(recordMs);
      if (gpuMs >= 0) m.gpuMs.push_back(gpuMs);
    }
    const auto* bytes = static_cast<const uint8_t*>(readback_.mapped);
    m.pixels.assign(bytes, bytes + imageBytes_);
  }

  // The fence has signalled: what is not available now never will be. The queries after a
  // multiview pass's first may stay unavailable (lavapipe puts the whole count in the first).
  void readStatistics(Mode& m) {
    m.vertexInvocations = m.fragmentInvocations = 0;
    const uint32_t views = m.setup.viewMask ? uint32_t(std::popcount(m.setup.viewMask)) : 1;
    for (uint32_t pass = 0; pass < m.passes.size(); ++pass) {
      uint64_t counts[kQueriesPerPass][3] = {};  // per query: vertex, fragment invocations, available
      VkResult r = vkGetQueryPoolResults(dev_, frame_.statistics, kQueriesPerPass * pass, views, sizeof counts, counts,
                                         sizeof counts[0], VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
      if (r != VK_NOT_READY) check(r, "vkGetQueryPoolResults");
      if (!counts[0][2]) throw std::runtime_error(std::string("no statistics from the ") + m.name + " frame");
      for (uint32_t v = 0; v < views; ++v) {
        if (!counts[v][2]) {
          ++m.unavailableViewQueries;
          continue;
        }
        m.vertexInvocations += counts[v][0];
        m.fragmentInvocations += counts[v][1];
      }
    }
  }

  // The GPU time of the last frame's render passes; -1 without timestamps.
  double readGpuMilliseconds() {
    if (!frame_.timestamps) return -1;
    uint64_t ticks[2] = {0, 0};
    check(vkGetQueryPoolResults(dev_, frame_.timestamps, 0, 2, sizeof ticks, ticks, sizeof(uint64_t),
                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
          "vkGetQueryPoolResults");
    const uint64_t mask = timestampBits_ >= 64 ? ~uint64_t(0) : (uint64_t(1) << timestampBits_) - 1;
    return double((ticks[1] - ticks[0]) & mask) * tickNs_ * 1e-6;
  }

  void printTable() const {
    const Mode& base = modes_[0];
    const double baseRecord = median(base.recordMs), baseGpu = base.gpuMs.empty() ? -1 : median(base.gpuMs);
    std::printf("%s: %u draws x %u triangles (%u vertices a draw), %ux%u x 2 layers; median of %d frames per mode, "
                "modes interleaved\n",
                context_.deviceName().c_str(), drawCount_, triangles_, scene_.verticesPerMesh, size_, size_, reps_);
    std::printf("%-10s %6s %10s %10s %10s %9s | %7s %7s %8s %7s\n", "mode", "draws", "VS invoc.", "FS invoc.",
                "record ms", "GPU ms", "draws x", "VS x", "record x", "GPU x");
    for (const Mode& m : modes_) {
      const double record = median(m.recordMs), gpuTime = m.gpuMs.empty() ? -1 : median(m.gpuMs);
      char vs[32] = "n/a", fs[32] = "n/a", vsRatio[16] = "n/a", gpuText[16] = "n/a", gpuRatio[16] = "n/a";
      if (statistics_) {
        std::snprintf(vs, sizeof vs, "%llu", static_cast<unsigned long long>(m.vertexInvocations));
        std::snprintf(fs, sizeof fs, "%llu", static_cast<unsigned long long>(m.fragmentInvocations));
        if (base.vertexInvocations)
          std::snprintf(vsRatio, sizeof vsRatio, "%.2f", double(m.vertexInvocations) / double(base.vertexInvocations));
      }
      if (gpuTime >= 0) {
        std::snprintf(gpuText, sizeof gpuText, "%.3f", gpuTime);
        if (baseGpu > 0) std::snprintf(gpuRatio, sizeof gpuRatio, "%.2f", gpuTime / baseGpu);
      }
      std::printf("%-10s %6u %10s %10s %10.3f %9s | %7.2f %7s %8.2f %7s\n", m.name, m.drawCalls, vs, fs, record, gpuText,
                  double(m.drawCalls) / double(base.drawCalls), vsRatio, record / baseRecord, gpuRatio);
    }
    std::printf("VS/FS invoc.: %s\n", statistics_ ? "pipeline statistics queries in each render pass (last frame)"
                                                  : "n/a: the device has no pipelineStatisticsQuery");
    for (const Mode& m : modes_)
      if (m.unavailableViewQueries)
        std::printf("%s: the second view's query stayed unavailable; the counts are the first query's alone\n", m.name);
    std::printf("record ms: CPU, vkBeginCommandBuffer .. vkEndCommandBuffer; GPU ms: %s\n",
                frame_.timestamps ? "timestamps before and after the render passes" : "n/a: the queue writes no timestamps");
  }

  // 1 when the eyes of two-pass are the same image or a single-pass mode's frames differ from it.
  int verdict() const {
    bool failed = false;
    if (eyesDiffer_ == 0) {
      std::printf("FAILED: the two eyes of the two-pass frame are the same image: the comparison would mean nothing\n");
      failed = true;
    }
    for (size_t i = 1; i < modes_.size(); ++i) {
      const Mode& m = modes_[i];
      if (m.framesDiffering) {
        std::printf("FAILED: %s differs from two-pass in %zu of %d frames (last: %zu pixels in layer 0, %zu in layer 1)\n",
                    m.name, m.framesDiffering, reps_ + 1, m.lastDifferingPixels[0], m.lastDifferingPixels[1]);
        failed = true;
      } else {
        std::printf("images: %s equals two-pass layer by layer, bit for bit, in all %d frames (the eyes differ in %zu "
                    "pixels)\n",
                    m.name, reps_ + 1, eyesDiffer_);
      }
    }
    return failed ? 1 : 0;
  }

  VulkanContext& context_;
  Device gpu_;
  const VkDevice dev_;
  const Scene scene_;
  const uint32_t drawCount_, triangles_;
  const int reps_;
  const uint32_t size_;
  std::vector<Mode> modes_;
  TranspileResult fragment_;
  std::vector<Converted> vertex_;
  VkDescriptorSetLayoutBinding bindings_[2] = {};
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkDescriptorSet eyeSets_[3] = {};  // left, right, single-pass
  Frame frame_;
  uint32_t layers_ = 0;
  Device::LayeredImage colour_;
  VkCommandBuffer copy_ = VK_NULL_HANDLE;
  Device::Buffer readback_;
  size_t imageBytes_ = 0;
  bool statistics_ = false;
  uint32_t timestampBits_ = 0;
  double tickNs_ = 0;
  VkFence fence_ = VK_NULL_HANDLE;
  size_t eyesDiffer_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  uint32_t draws = 2000, triangles = 4, size = 256;
  int reps = 9;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--draws" && hasValue) {
      draws = uint32_t(std::max(1, std::atoi(argv[++i])));
    } else if (arg == "--triangles" && hasValue) {
      triangles = uint32_t(std::clamp(std::atoi(argv[++i]), 1, 256));
    } else if (arg == "--reps" && hasValue) {
      reps = std::max(1, std::atoi(argv[++i]));
    } else if (arg == "--size" && hasValue) {
      size = uint32_t(std::clamp(std::atoi(argv[++i]), 16, 4096));
    } else {
      std::fprintf(stderr, "usage: single_pass_bench [--draws N] [--triangles T] [--reps R] [--size S]\n");
      return 2;
    }
  }
  std::string error;
  if (!VulkanContext::anyDeviceAvailable(&error)) {
    std::fprintf(stderr, "single_pass_bench: skipped: %s\n", error.c_str());
    return 77;  // ctest's SKIP_RETURN_CODE for the smoke test
  }
  auto context = VulkanContext::create(&error);
  if (!context) {
    std::fprintf(stderr, "single_pass_bench: no Vulkan device: %s\n", error.c_str());
    return 1;
  }
  try {
    return SinglePassBench(*context, draws, triangles, reps, size).run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "single_pass_bench: %s\n", e.what());
    return 1;
  }
}
