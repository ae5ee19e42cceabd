// The depth-reprojection scene the execution test (reproject_render_test.cpp) and the benchmark
// (bench/reproject_bench.cpp) share: a few quads with depth edges, in front of and behind the
// convergence plane, a thin pole, a far wall and a slanted floor, rendered on lavapipe with the
// stereo-shifted scene shaders (the ground truth for each eye), and the reprojection pass run on a
// source view's colour and depth. Also the comparison: PSNR, pixels off by more than 8 levels outside
// the disoccluded area (found from the truth's own depth, independently of the pass), and the bound
// such errors must stay under. Header-only; test and bench code, never the tool.
#pragma once

#include "transpiler/frontend/front_end.h"
#include "transpiler/reproject/reproject_shaders.h"
#include "transpiler/stereoshift.h"
#include "transpiler/verify/vk_harness.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace stereoshift::reproject_scene {

using namespace stereoshift::harness;

constexpr uint32_t kWidth = 256, kHeight = 128;
constexpr double kFloorY = -2.5;
constexpr double kSeparation = 0.08, kConvergence = 4.0, kNear = 0.1, kFocal = 1.7320508075688772;  // 60 deg

inline const char* kSceneVertex = R"(#version 450
layout(set = 0, binding = 0) uniform Camera { mat4 viewProj; } camera;
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 baseColour;
layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 colour;
void main() {
  worldPosition = position;
  colour = baseColour;
  gl_Position = camera.viewProj * vec4(position, 1.0);
}
)";

// A smooth pattern with a few sharp stripes, so a misplaced pixel shows.
inline const char* kSceneFragment = R"(#version 450
layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 colour;
layout(location = 0) out vec4 fragColour;
void main() {
  vec3 p = worldPosition;
  float smoothPart = 0.5 + 0.5 * sin(0.35 * p.x + 0.25 * p.y + 0.2 * p.z);
  float stripe = step(0.8, fract(0.12 * p.x + 0.07 * p.z + 0.1 * p.y));
  fragColour = vec4(colour * (0.35 + 0.45 * smoothPart) + 0.2 * stripe, 1.0);
}
)";

// Depth encodings the scene is rendered with: Vulkan [0, 1], infinite far, standard or reversed.
struct DepthSetup {
  bool reversed = false;
  bool quantize24 = false;  // store as D24 UNORM would (k / (2^24 - 1)); else D32F
};

// Column-major Vulkan projection (y down), w = -z_eye, infinite far: z_ndc = 1 - n/w, or n/w reversed.
inline std::array<float, 16> projection(bool reversed) {
  std::array<float, 16> p{};
  p[0] = float(kFocal * kHeight / kWidth);
  p[5] = float(-kFocal);
  p[10] = reversed ? 0.0f : -1.0f;
  p[14] = float(reversed ? kNear : -kNear);
  p[11] = -1.0f;
  return p;
}

inline void quad(std::vector<float>& v, std::array<float, 3> a, std::array<float, 3> b, std::array<float, 3> c,
                 std::array<float, 3> d, std::array<float, 3> colour) {
  for (const auto* corner : {&a, &b, &c, &a, &c, &d}) {
    v.insert(v.end(), corner->begin(), corner->end());
    v.insert(v.end(), colour.begin(), colour.end());
  }
}

// The scene: far wall (w = 30), floor y = -2.5 (the slanted plane, seen from w = 2.5 f = 4.3 to 30,
// all behind the screen), a box face behind the screen (w = 6), a panel in front of it (w = 3:
// negative parallax, t = -1/3), a thin pole (w = 5, 2 pixels wide).
inline VertexBuffer sceneVertices(uint32_t* count) {
  std::vector<float> v;
  quad(v, {-40, -2.5f, -30}, {40, -2.5f, -30}, {40, 20, -30}, {-40, 20, -30}, {0.3f, 0.5f, 0.9f});
  quad(v, {-40, -2.5f, -0.5f}, {40, -2.5f, -0.5f}, {40, -2.5f, -30}, {-40, -2.5f, -30}, {0.6f, 0.55f, 0.3f});
  quad(v, {-2.5f, -0.8f, -6}, {-0.5f, -0.8f, -6}, {-0.5f, 1.5f, -6}, {-2.5f, 1.5f, -6}, {0.9f, 0.3f, 0.2f});
  quad(v, {0.2f, -0.6f, -3}, {1.2f, -0.6f, -3}, {1.2f, 0.5f, -3}, {0.2f, 0.5f, -3}, {0.2f, 0.85f, 0.3f});
  quad(v, {-0.05f, -2.5f, -5}, {0.04f, -2.5f, -5}, {0.04f, 2, -5}, {-0.05f, 2, -5}, {0.95f, 0.95f, 0.9f});
  VertexBuffer vb;
  vb.stride = 24;
  vb.attributes = {{0, VK_FORMAT_R32G32B32_SFLOAT, 0}, {1, VK_FORMAT_R32G32B32_SFLOAT, 12}};
  vb.bytes = toBytes(v);
  *count = uint32_t(v.size() / 6);
  return vb;
}

inline std::vector<uint32_t> words(const std::string& bytes) {
  std::vector<uint32_t> out(bytes.size() / 4);
  std::memcpy(out.data(), bytes.data(), out.size() * 4);
  return out;
}

struct Scene {
  std::vector<uint32_t> vertex, fragment;  // the vertex shader as stereoshift shifts it
  uint32_t eyeBinding = 1;
  VertexBuffer vertices;
  uint32_t vertexCount = 0;
  std::string error;
};

inline Scene makeScene() {
  Scene s;
  TranspileOptions options;
  options.target = TargetLanguage::Spirv;
  TranspileResult vert = transpile({"reproject_scene.vert", kSceneVertex}, options);
  if (!vert.ok) {
    s.error = vert.diagnostics.format();
    return s;
  }
  s.vertex = words(vert.output);
  s.eyeBinding = vert.report["passes"]["eye-params"].value("binding", 1u);
  Diagnostics diags;
  FrontEndResult frag = compileToSpirv({"reproject_scene.frag", kSceneFragment}, options, diags);
  if (!frag.ok) {
    s.error = diags.format();
    return s;
  }
  s.fragment = frag.spirv;
  s.vertices = sceneVertices(&s.vertexCount);
  return s;
}

inline std::vector<uint8_t> eyeBlock(double eyeSign) {
  float values[4] = {float(eyeSign), float(kSeparation), float(kConvergence), 0.0f};
  return toBytes(values, 4);
}

// The scene as the stereo-shifted shaders draw it for `eyeSign`, colour and depth.
// `scale` > 1 draws it `scale` times larger each way (the benchmark, so that pixel work dominates).
inline RenderResult renderEye(VulkanContext& context, const Scene& scene, double eyeSign, const DepthSetup& depth,
                              uint32_t scale = 1) {
  RenderRequest request;
  request.width = kWidth * scale;
  request.height = kHeight * scale;
  request.readDepth = true;
  request.clearDepth = depth.reversed ? 0.0f : 1.0f;
  Draw draw;
  draw.depthCompare = depth.reversed ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_LESS;
  draw.pipeline.stages = {{VK_SHADER_STAGE_VERTEX_BIT, scene.vertex, "main"},
                          {VK_SHADER_STAGE_FRAGMENT_BIT, scene.fragment, "main"}};
  draw.pipeline.vertices = scene.vertices;
  draw.pipeline.vertexCount = scene.vertexCount;
  std::array<float, 16> p = projection(depth.reversed);
  draw.pipeline.uniformBuffers = {{0, 0, toBytes(p.data(), 16)}, {0, scene.eyeBinding, eyeBlock(eyeSign)}};
  request.draws = {draw};
  RenderResult r = context.render(request);
  if (r.ok() && depth.quantize24)
    for (float& d : r.depth) d = float(std::nearbyint(double(d) * 16777215.0) / 16777215.0);
  return r;
}

inline ReprojectOptions passOptions(const DepthSetup& depth, ReprojectSource source) {
  ReprojectOptions o;
  o.source = source;
  o.depth = ReprojectDepth::ZeroToOne;
  o.reversedZ = depth.reversed;
  o.nearPlane = kNear;
  o.target = TargetLanguage::Spirv;
  return o;
}

struct Pass {
  std::vector<uint32_t> vertex, fragment;
  std::string error;
};

inline Pass makePass(const ReprojectOptions& options) {
  Pass pass;
  ReprojectResult r = generateReprojectShaders(options);
  if (!r.ok) {
    pass.error = r.diagnostics.format();
    return pass;
  }
  pass.vertex = words(r.shaders[0].output);
  pass.fragment = words(r.shaders[1].output);
  return pass;
}

// The reprojection pass run on `source`'s colour and depth for the eye `eyeSign`.
// The pass's target has the source's size.
inline RenderResult reproject(VulkanContext& context, const Pass& pass, const RenderResult& source, double eyeSign) {
  const uint32_t width = source.width, height = source.height;
  SampledTexture colour{0, 0, width, height, {}}, depth{0, 1, width, height, {}};
  colour.rgba.resize(size_t(width) * height * 4);
  for (size_t i = 0; i < colour.rgba.size(); ++i) colour.rgba[i] = float(source.pixels[i] / 255.0);
  depth.rgba.reserve(size_t(width) * height * 4);
  for (float d : source.depth) depth.rgba.insert(depth.rgba.end(), {d, 0.0f, 0.0f, 1.0f});
  RenderRequest request;
  request.width = width;
  request.height = height;
  Draw draw;
  draw.depthTest = false;
  draw.depthWrite = false;
  draw.pipeline.stages = {{VK_SHADER_STAGE_VERTEX_BIT, pass.vertex, "main"},
                          {VK_SHADER_STAGE_FRAGMENT_BIT, pass.fragment, "main"}};
  draw.pipeline.vertexCount = 3;
  draw.pipeline.textures = {colour, depth};
  draw.pipeline.uniformBuffers = {{0, 2, eyeBlock(eyeSign)}};
  request.draws = {draw};
  return context.render(request);
}

// 1/w from a stored depth of the scene's projection.
inline double inverseDepth(float stored, bool reversed) { return reversed ? stored / kNear : (1.0 - stored) / kNear; }

struct Comparison {
  double psnr = 0, monoPsnr = 0;  // over the whole image; mono: the source image shown to the target eye
  size_t pixels = 0;
  size_t disoccluded = 0;   // target pixels whose surface point the source does not see (or off screen)
  size_t wrong = 0;         // outside those: some channel off by more than 8 levels
  size_t edgePixels = 0;    // outside those: truth pixels that differ from a horizontal neighbour by > 8
  // The same counts restricted to the floor (the slanted plane), for the depth-quantisation check.
  size_t floorPixels = 0, floorWrong = 0, floorEdges = 0;
  std::vector<uint8_t> difference, mask;  // RGBA8 images for a person to look at
};

inline int channelDifference(const uint8_t* a, const uint8_t* b) {
  int d = 0;
  for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
  return d;
}

// `truth` (the target eye drawn directly, with depth), `source` the view the pass read, `result` the pass.
inline Comparison compare(const RenderResult& truth, const RenderResult& source, const RenderResult& result,
                          double targetSign, double sourceSign, bool reversed) {
  Comparison c;
  c.pixels = size_t(kWidth) * kHeight;
  c.difference.assign(c.pixels * 4, 255);
  c.mask.assign(c.pixels * 4, 255);
  const double k = (targetSign - sourceSign) * kSeparation * 0.5 * kWidth;
  double squared = 0, monoSquared = 0;
  for (uint32_t y = 0; y < kHeight; ++y)
    for (uint32_t x = 0; x < kWidth; ++x) {
      const uint8_t *t = truth.pixel(x, y), *r = result.pixel(x, y), *m = source.pixel(x, y);
      for (int ch = 0; ch < 3; ++ch) {
        double d = double(t[ch]) - r[ch], dm = double(t[ch]) - m[ch];
        squared += d * d;
        monoSquared += dm * dm;
      }
      // Where the source sees this pixel's surface point: x - k*t with t = 1 - C/w from the truth's depth.
      const double invW = inverseDepth(truth.depthAt(x, y), reversed);
      const double q = x + 0.5 - k * (1.0 - kConvergence * invW);
      bool seen = false;
      for (int dx = -1; dx <= 1 && !seen; ++dx) {
        int sx = int(std::floor(q)) + dx;
        if (sx < 0 || sx >= int(kWidth)) continue;
        double sourceInvW = inverseDepth(source.depthAt(uint32_t(sx), y), reversed);
        seen = std::abs(sourceInvW - invW) <= 0.02 * invW;
      }
      if (q < 0 || q >= kWidth) seen = false;
      const size_t at = (size_t(y) * kWidth + x) * 4;
      const int difference = channelDifference(t, r);
      for (int ch = 0; ch < 3; ++ch) c.difference[at + ch] = uint8_t(255 - std::min(255, 4 * difference));
      if (!seen) {
        ++c.disoccluded;
        c.mask[at] = 255;
        c.mask[at + 1] = c.mask[at + 2] = 0;
        continue;
      }
      bool edge = false;
      for (int dx : {-1, 1}) {
        int nx = int(x) + dx;
        if (nx >= 0 && nx < int(kWidth)) edge |= channelDifference(t, truth.pixel(uint32_t(nx), y)) > 8;
      }
      bool wrong = difference > 8;
      c.wrong += wrong;
      c.edgePixels += edge;
      // The floor: world y = -2.5 for the pixel's depth (y_ndc = -f*y/w, Vulkan y down).
      const double ndcY = (y + 0.5) / kHeight * 2.0 - 1.0;
      const bool floor = std::abs(-ndcY / (kFocal * invW) - kFloorY) < 0.01;
      if (floor) {
        ++c.floorPixels;
        c.floorWrong += wrong;
        c.floorEdges += edge;
      }
    }
  auto psnr = [&](double sum) { return sum == 0 ? INFINITY : 10 * std::log10(255.0 * 255.0 * 3.0 * c.pixels / sum); };
  c.psnr = psnr(squared);
  c.monoPsnr = psnr(monoSquared);
  return c;
}

}  // namespace stereoshift::reproject_scene
