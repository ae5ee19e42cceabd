// Relief mapping per eye: the corpus's Vulkan parallax-occlusion pipeline (corpus/vk450/parallax_pom.*)
// renders a height-mapped floor on lavapipe, each eye three ways:
//   truth:    the original shaders with the true per-eye camera: stereo projection (mono P with row 0
//             [p00, 0, p02 - e S, -e S C]) and the eye centre C_eye = C + InvV * (e S C / P00, 0, 0, 0),
//             both computed in double precision on the host;
//   fix:      stereoshift's shaders (shift + per-eye-view), every matrix and the camera mono, the eye
//             parameters set;
//   baseline: the original shaders with the stereo projection but the mono camera position: what a
//             tool that only shifts positions gives (the relief is seen from between the eyes).
// PSNR and the largest channel difference of fix and baseline against the truth are printed; the fix
// must match the truth to rounding, the baseline must be measurably worse. Images are written as PNG.
#include "transpiler/verify/stereo_verify.h"
#include "transpiler/verify/capture_instrument.h"
#include "transpiler/frontend/front_end.h"
#include "passes/ir/module.h"
#include "transpiler/source/file_io.h"

#include <stereoshift/stereo_runtime.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cctype>
#include <cstring>
#include <functional>
#include <iomanip>
#include <map>

using namespace stereoshift;
using namespace stereoshift::harness;
namespace rt = stereoshift::runtime;

namespace {

constexpr uint32_t kSize = 256;
constexpr uint32_t kTexture = 128;
constexpr double kSeparation = 0.08, kConvergence = 2.5;
constexpr float kHeightScale = 0.1f;

using M = rt::Mat4<double>;

std::vector<uint32_t> words(const std::string& bytes) {
  std::vector<uint32_t> out(bytes.size() / 4);
  std::memcpy(out.data(), bytes.data(), out.size() * 4);
  return out;
}

std::vector<float> toFloats(const M& m) { return std::vector<float>(m.begin(), m.end()); }

void append(std::vector<uint8_t>& bytes, const std::vector<float>& values) {
  size_t at = bytes.size();
  bytes.resize(at + values.size() * 4);
  std::memcpy(bytes.data() + at, values.data(), values.size() * 4);
}

// The corpus CameraBlock (std140): view, proj, viewProj, invViewProj, cameraPosition, viewportSize.
std::vector<uint8_t> cameraBlock(const M& view, const M& proj, const rt::Vec3<double>& cameraPosition) {
  M viewProj = rt::multiply(proj, view);
  std::vector<uint8_t> bytes;
  append(bytes, toFloats(view));
  append(bytes, toFloats(proj));
  append(bytes, toFloats(viewProj));
  append(bytes, toFloats(rt::inverse(viewProj)));
  append(bytes, {float(cameraPosition[0]), float(cameraPosition[1]), float(cameraPosition[2]), 1.0f});
  append(bytes, {float(kSize), float(kSize), 1.0f / kSize, 1.0f / kSize});
  return bytes;
}

// Vulkan clip space (y down, depth 0..1), w = -z_view.
M projection() {
  const double f = 1.0 / std::tan(0.5 * 0.9), n = 0.05, far = 100.0;
  M p{};
  p[0] = f;
  p[5] = -f;
  p[10] = far / (n - far);
  p[11] = -1;
  p[14] = n * far / (n - far);
  return p;
}

// A camera above the floor looking down at it at a grazing angle (where parallax shows most).
const rt::Vec3<double> kCamera = {0.15, 0.9, 1.6};
M viewMatrix() {
  const double pitch = -0.55, yaw = 0.12;
  double cy = std::cos(yaw), sy = std::sin(yaw), cp = std::cos(pitch), sp = std::sin(pitch);
  double r[3][3] = {{cy, sy * sp, sy * cp}, {0, cp, -sp}, {-sy, cy * sp, cy * cp}};  // camera -> world
  M invView{};
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row) invView[4 * c + row] = r[row][c];
  invView[12] = kCamera[0];
  invView[13] = kCamera[1];
  invView[14] = kCamera[2];
  invView[15] = 1;
  return rt::inverse(invView);
}

// The floor y = 0, x in [-1, 1], z in [-1.5, 0.5]; normal +y, tangent +x (u), bitangent
// cross(n, t) = -z (v grows away from the camera).
VertexBuffer floorQuad() {
  VertexBuffer vb;
  vb.stride = 48;
  vb.attributes = {{0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                   {1, VK_FORMAT_R32G32B32_SFLOAT, 12},
                   {2, VK_FORMAT_R32G32B32A32_SFLOAT, 24},
                   {3, VK_FORMAT_R32G32_SFLOAT, 40}};
  const float corners[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
  for (const auto& c : corners) {
    float x = -1.0f + 2.0f * c[0], z = 0.5f - 2.0f * c[1];
    float v[12] = {x, 0, z, 0, 1, 0, 1, 0, 0, 1, c[0], c[1]};
    append(vb.bytes, std::vector<float>(v, v + 12));
  }
  return vb;
}

// Height: round bumps on a grid with grooves between them; albedo: a colour pattern with sharp
// stripes, so a parallax error moves visible edges.
std::vector<SampledTexture> textures() {
  SampledTexture height{1, 0, kTexture, kTexture, {}}, albedo{1, 1, kTexture, kTexture, {}};
  for (uint32_t y = 0; y < kTexture; ++y)
    for (uint32_t x = 0; x < kTexture; ++x) {
      double u = (x + 0.5) / kTexture, v = (y + 0.5) / kTexture;
      double cu = std::fmod(u * 6, 1.0) - 0.5, cv = std::fmod(v * 6, 1.0) - 0.5;
      double bump = std::max(0.0, 1.0 - 4.0 * (cu * cu + cv * cv));
      height.rgba.insert(height.rgba.end(), {float(bump), 0, 0, 1});
      bool stripe = std::fmod(u * 24 + v * 12, 1.0) < 0.35;
      albedo.rgba.insert(albedo.rgba.end(), {stripe ? 0.95f : float(0.25 + 0.6 * bump), float(0.2 + 0.7 * v),
                                             stripe ? 0.2f : float(0.3 + 0.6 * u), 1});
    }
  return {height, albedo};
}

struct Comparison {
  double psnr = 0;        // over the pixels the floor covers in either image, RGB, peak 255
  int maxDifference = 0;  // largest channel difference
  size_t differing = 0;   // pixels not bit-identical
  size_t notABoundaryMove = 0;  // differing pixels whose colour the truth has nowhere in its 3x3 neighbourhood
  // Differing pixels that are not a sub-pixel move at all: neither a neighbour's colour (a texel or
  // step boundary) nor, channel by channel, within the range of the truth's 3x3 neighbourhood (a
  // smooth shading gradient sampled a fraction of a pixel away; rounding to 8 bits is monotonic, so
  // such a sample rounds into the neighbours' range).
  size_t notASubpixelMove = 0;
  size_t covered = 0;
};

Comparison compare(const RenderResult& truth, const RenderResult& other) {
  Comparison c;
  double squared = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      const uint8_t *a = truth.pixel(x, y), *b = other.pixel(x, y);
      bool background = a[0] == 0 && a[1] == 0 && a[2] == 0 && b[0] == 0 && b[1] == 0 && b[2] == 0;
      if (background) continue;
      ++c.covered;
      if (std::memcmp(a, b, 3) != 0) {
        ++c.differing;
        // A texel or ray-march-step boundary that moved by less than a pixel: the pixel takes the
        // colour of a neighbour in the truth.
        bool neighbourColour = false;
        int low[3] = {255, 255, 255}, high[3] = {0, 0, 0};
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            int nx = int(x) + dx, ny = int(y) + dy;
            if (nx >= 0 && ny >= 0 && nx < int(kSize) && ny < int(kSize)) {
              const uint8_t* n = truth.pixel(nx, ny);
              neighbourColour |= std::memcmp(n, b, 3) == 0;
              for (int k = 0; k < 3; ++k) low[k] = std::min(low[k], int(n[k])), high[k] = std::max(high[k], int(n[k]));
            }
          }
        bool inRange = true;
        for (int k = 0; k < 3; ++k) inRange &= b[k] >= low[k] && b[k] <= high[k];
        c.notABoundaryMove += !neighbourColour;
        c.notASubpixelMove += !neighbourColour && !inRange;
      }
      for (int k = 0; k < 3; ++k) {
        int d = std::abs(int(a[k]) - int(b[k]));
        c.maxDifference = std::max(c.maxDifference, d);
        squared += double(d) * d;
      }
    }
  double mse = squared / (3.0 * std::max<size_t>(c.covered, 1));
  c.psnr = mse == 0 ? INFINITY : 10 * std::log10(255.0 * 255.0 / mse);
  return c;
}

TEST(ReliefRender, PerEyeCameraMatchesGroundTruth) {
  std::string error;
  auto context = VulkanContext::create(&error);
  ASSERT_TRUE(context) << error;

  std::vector<SourceFile> sources = {{CORPUS_DIR "/vk450/parallax_pom.vert", {}}, {CORPUS_DIR "/vk450/parallax_pom.frag", {}}};
  for (auto& s : sources) ASSERT_TRUE(readFile(s.path, &s.contents)) << s.path;
  TranspileOptions options;
  options.includeDirs = {CORPUS_DIR "/vk450/include"};
  options.target = TargetLanguage::Spirv;
  options.validateEach = true;

  std::vector<uint32_t> original[2];
  for (size_t i = 0; i < sources.size(); ++i) {
    Diagnostics diags;
    FrontEndResult front = compileToSpirv(sources[i], options, diags);
    ASSERT_TRUE(front.ok) << diags.format();
    original[i] = front.spirv;
  }
  std::vector<TranspileResult> converted = transpilePipeline(sources, options);
  ASSERT_EQ(converted.size(), 2u);
  for (const auto& r : converted) {
    ASSERT_TRUE(r.ok) << r.diagnostics.format();
    // Both stages were fixed (the fragment shader recomputes its view vector per pixel).
    ASSERT_EQ(r.report["passes"]["per-eye-view"]["result"], "changed") << r.report.dump(2);
  }
  std::vector<uint32_t> fixed[2] = {words(converted[0].output), words(converted[1].output)};
  const auto& eyeReport = converted[0].report["passes"]["eye-params"];
  ASSERT_EQ(eyeReport.value("set", -1), 0) << eyeReport.dump();
  const uint32_t eyeBinding = eyeReport.value("binding", 0u);
  ASSERT_EQ(converted[1].report["passes"]["eye-params"].value("binding", 0u), eyeBinding);

  const M view = viewMatrix(), proj = projection(), invView = rt::inverse(view);
  std::vector<uint8_t> push;
  append(push, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});  // object.model = identity
  push.resize(push.size() + 4, 0);                                 // object.materialIndex
  std::vector<uint8_t> pom;
  pom.resize(12);
  int32_t steps[2] = {24, 96};
  std::memcpy(pom.data(), &kHeightScale, 4);
  std::memcpy(pom.data() + 4, steps, 8);
  const VertexBuffer quad = floorQuad();
  const std::vector<SampledTexture> maps = textures();

  auto render = [&](const std::vector<uint32_t>& vert, const std::vector<uint32_t>& frag,
                    std::vector<uint8_t> camera, const float* eyeParams) {
    RenderRequest request;
    request.width = request.height = kSize;
    Draw draw;
    draw.pipeline.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vert, "main"}, {VK_SHADER_STAGE_FRAGMENT_BIT, frag, "main"}};
    draw.pipeline.vertices = quad;
    draw.pipeline.vertexCount = 6;
    draw.pipeline.uniformBuffers = {{0, 0, std::move(camera)}, {1, 2, pom}};
    if (eyeParams) {
      std::vector<uint8_t> bytes(16, 0);
      std::memcpy(bytes.data(), eyeParams, 12);
      draw.pipeline.uniformBuffers.push_back({0, eyeBinding, bytes});
    }
    draw.pipeline.textures = maps;
    draw.pipeline.pushConstants = push;
    request.draws = {draw};
    RenderResult result = context->render(request);
    EXPECT_TRUE(result.ok()) << result.error;
    return result;
  };

  // eyeSign 0: the converted pipeline is the original, pixel for pixel.
  {
    float mono[3] = {0.0f, float(kSeparation), float(kConvergence)};
    RenderResult a = render(original[0], original[1], cameraBlock(view, proj, kCamera), nullptr);
    RenderResult b = render(fixed[0], fixed[1], cameraBlock(view, proj, kCamera), mono);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a.pixels, b.pixels) << "mono (eyeSign 0) must be the original image";
  }

  RenderResult fixedEyes[2], truthEyes[2];
  for (int e = 0; e < 2; ++e) {
    const double eye = e == 0 ? -1.0 : 1.0;
    const M stereoProj = rt::stereoProjectionGL(proj, eye, kSeparation, kConvergence);
    const rt::Vec3<double> offset = rt::eyeOffsetFromInverseView(invView, proj[0], eye, kSeparation, kConvergence);
    const rt::Vec3<double> eyeCentre = {kCamera[0] + offset[0], kCamera[1] + offset[1], kCamera[2] + offset[2]};
    const float params[3] = {float(eye), float(kSeparation), float(kConvergence)};

    RenderResult truth = render(original[0], original[1], cameraBlock(view, stereoProj, eyeCentre), nullptr);
    RenderResult fix = render(fixed[0], fixed[1], cameraBlock(view, proj, kCamera), params);
    RenderResult baseline = render(original[0], original[1], cameraBlock(view, stereoProj, kCamera), nullptr);
    ASSERT_TRUE(truth.ok() && fix.ok() && baseline.ok());

    Comparison ours = compare(truth, fix), mono = compare(truth, baseline);
    std::cout << std::fixed << std::setprecision(2) << "[relief] " << (e == 0 ? "left " : "right") << " eye, "
              << ours.covered << " floor pixels: fix PSNR " << ours.psnr << " dB, max diff " << ours.maxDifference
              << ", " << ours.differing << " pixels differ (" << ours.notABoundaryMove
              << " not a boundary move) | mono-camera baseline PSNR " << mono.psnr << " dB, max diff "
              << mono.maxDifference << ", " << mono.differing << " pixels differ (" << mono.notABoundaryMove
              << " not a boundary move)\n";
    EXPECT_GT(ours.covered, kSize * kSize / 4) << "the floor should fill a good part of the image";
    // To rounding. The fix computes C_eye = C + InvVP * (e S C, 0, 0, 0) in fp32 where the truth
    // rounds the double C_eye once, and shifts the clip position (<= 2.5 ULP from the stereo matrix,
    // see execution.stress), so interpolated positions and view vectors differ in their last bits.
    // That changes a pixel only where a nearest-texel lookup or a ray-march step sits exactly on a
    // boundary: then the pixel takes its neighbour's colour (the boundary moved by less than a
    // pixel) and may differ by a whole texel's contrast. Bound: every differing pixel is such a
    // boundary move, and they are at most 5 in 10000 floor pixels. (PSNR is reported, not bounded:
    // one flipped pixel of 25000 already reads about 50 dB.)
    EXPECT_EQ(ours.notABoundaryMove, 0u) << "a differing pixel that is not a sub-pixel boundary move";
    EXPECT_LE(ours.differing * 10000, ours.covered * 5) << "more than 5 in 10000 pixels differ from the truth";
    // The mono camera is measurably wrong: the relief is seen from between the eyes.
    EXPECT_LE(mono.psnr, ours.psnr - 10.0);
    EXPECT_GT(mono.differing * 10000, mono.covered * 100) << "the baseline should differ on more than 1% of the floor";
    fixedEyes[e] = std::move(fix);
    truthEyes[e] = std::move(truth);
    EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/relief_" + std::string(e == 0 ? "left" : "right") + "_baseline.png", kSize,
                         kSize, baseline.pixels.data()));
  }
  EXPECT_NE(fixedEyes[0].pixels, fixedEyes[1].pixels);
  std::vector<uint8_t> anaglyph = harness::anaglyph(fixedEyes[0].pixels, fixedEyes[1].pixels, kSize * kSize);
  EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/relief_left.png", kSize, kSize, fixedEyes[0].pixels.data()));
  EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/relief_right.png", kSize, kSize, fixedEyes[1].pixels.data()));
  EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/relief_left_truth.png", kSize, kSize, truthEyes[0].pixels.data()));
  EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/relief_right_truth.png", kSize, kSize, truthEyes[1].pixels.data()));
  EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/relief_anaglyph.png", kSize, kSize, anaglyph.data()));
  std::cout << "[relief] wrote " IMAGE_OUT_DIR "/relief_{left,right}{,_truth,_baseline}.png and relief_anaglyph.png\n";
}


// ---- the tutorial form: `TangentViewPos = TBN * viewPos` in the vertex stage ---------------------
//
// corpus/relief-tutorial/ pipelines as public tutorials write them (GLSL 330 with loose uniforms,
// Vulkan GLSL with blocks, D3D-style HLSL): the camera goes to tangent space in the vertex stage and
// the fragment stage offsets uv along normalize(TangentViewPos - TangentFragPos). The same three
// renders per eye as above. Nothing here knows a shader's layout: uniforms (loose ones after the
// harness's Vulkan rewrite, block members, cbuffer members), textures and vertex inputs are filled
// from each module's own reflection, by name.

// Raw 32-bit words of a uniform value: floats or int bits.
using Words = std::vector<uint32_t>;
Words floats(std::initializer_list<double> values) {
  Words out;
  for (double v : values) {
    float f = float(v);
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    out.push_back(bits);
  }
  return out;
}
Words floats(const M& m) {
  Words out;
  for (double v : m) out.push_back(floats({v})[0]);
  return out;
}
Words integer(int32_t v) { return {uint32_t(v)}; }

struct Resources {
  std::vector<UniformBuffer> buffers;
  std::vector<SampledTexture> textures;
  std::vector<std::string> unfilled;  // block members no value was given for (a test error if read)
  std::vector<uint8_t> pushConstants;  // the push-constant block, filled likewise
};

// The texture a sampler's name asks for: a height field (bumps on a grid, `height`/`depth`/`disp`,
// in .r), a normal map with height in alpha (`normalheight`, as Vulkan samples pack it: height =
// 1 - a), a flat normal map (`normal`), else the albedo with sharp stripes (so a parallax error
// moves visible edges).
SampledTexture textureFor(const std::string& name, uint32_t set, uint32_t binding, VkDescriptorType type) {
  std::string lower;
  for (char c : name) lower += char(std::tolower(static_cast<unsigned char>(c)));
  SampledTexture t{set, binding, kTexture, kTexture, {}};
  t.type = type;
  if (type == VK_DESCRIPTOR_TYPE_SAMPLER) return t;
  const bool normalHeight = lower.find("normalheight") != std::string::npos;
  const bool height = !normalHeight && (lower.find("height") != std::string::npos || lower.find("depth") != std::string::npos ||
                                        lower.find("disp") != std::string::npos || lower.find("relief") != std::string::npos);
  const bool normal = !normalHeight && lower.find("normal") != std::string::npos;
  for (uint32_t y = 0; y < kTexture; ++y)
    for (uint32_t x = 0; x < kTexture; ++x) {
      double u = (x + 0.5) / kTexture, v = (y + 0.5) / kTexture;
      double cu = std::fmod(u * 6, 1.0) - 0.5, cv = std::fmod(v * 6, 1.0) - 0.5;
      float bump = float(std::max(0.0, 1.0 - 4.0 * (cu * cu + cv * cv)));
      if (normalHeight) t.rgba.insert(t.rgba.end(), {0.5f, 0.5f, 1.0f, 1.0f - bump});
      else if (height) t.rgba.insert(t.rgba.end(), {bump, 0, 0, 1});
      else if (normal) t.rgba.insert(t.rgba.end(), {0.5f, 0.5f, 1.0f, 1.0f});
      else {
        bool stripe = std::fmod(u * 24 + v * 12, 1.0) < 0.35;
        t.rgba.insert(t.rgba.end(), {stripe ? 0.95f : float(0.25 + 0.6 * bump), float(0.2 + 0.7 * v),
                                     stripe ? 0.2f : float(0.3 + 0.6 * u), 1});
      }
    }
  return t;
}

// Every uniform block (set, binding) and image/sampler of the stages, filled from `values` by member
// name (a block shared by two stages is one buffer). Matrices are written column by column: GLSL's
// column-major and HLSL's default column_major packing (which glslang decorates RowMajor on the
// transposed SPIR-V type) hold the same bytes for the same mathematical matrix.
Resources reflectResources(const std::vector<spirv::Module>& stages, const std::map<std::string, Words>& values) {
  Resources out;
  std::map<std::pair<uint32_t, uint32_t>, size_t> bufferAt, textureAt;
  for (const auto& m : stages)
    for (const auto& inst : m.typesValues) {
      if (inst.opcode != spv::OpVariable) continue;
      auto storage = spv::StorageClass(inst.operand(0));
      uint32_t set = m.decorationValue(inst.resultId, spv::DecorationDescriptorSet).value_or(0);
      uint32_t binding = m.decorationValue(inst.resultId, spv::DecorationBinding).value_or(0);
      uint32_t type = m.pointeeType(inst.typeId);
      if (storage == spv::StorageClassUniformConstant && m.isOpaqueType(type)) {
        if (textureAt.count({set, binding})) continue;
        const spirv::Instruction* def = m.definition(type);
        VkDescriptorType kind = def->opcode == spv::OpTypeSampler ? VK_DESCRIPTOR_TYPE_SAMPLER
                                : def->opcode == spv::OpTypeImage ? VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE
                                                                  : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        textureAt[{set, binding}] = out.textures.size();
        out.textures.push_back(textureFor(m.name(inst.resultId), set, binding, kind));
        continue;
      }
      const bool push = storage == spv::StorageClassPushConstant;
      if ((storage != spv::StorageClassUniform && !push) || !m.hasDecoration(type, spv::DecorationBlock)) continue;
      const spirv::Instruction* block = m.definition(type);
      std::vector<uint8_t> bytes;
      for (uint32_t member = 0; member < block->operands.size(); ++member) {
        std::string name = m.memberName(type, member);
        uint32_t offset = m.memberDecorationValue(type, member, spv::DecorationOffset).value_or(0);
        auto it = values.find(name);
        if (it == values.end()) {
          out.unfilled.push_back(name);
          continue;
        }
        if (bytes.size() < offset + it->second.size() * 4) bytes.resize(offset + it->second.size() * 4, 0);
        std::memcpy(bytes.data() + offset, it->second.data(), it->second.size() * 4);
      }
      bytes.resize((bytes.size() + 15) / 16 * 16, 0);
      if (push) {  // one range for every stage, as the harness binds it
        if (out.pushConstants.size() < bytes.size()) out.pushConstants = std::move(bytes);
        continue;
      }
      auto at = bufferAt.find({set, binding});
      if (at == bufferAt.end()) {
        bufferAt[{set, binding}] = out.buffers.size();
        out.buffers.push_back({set, binding, std::move(bytes)});
      } else if (out.buffers[at->second].bytes.size() < bytes.size()) {
        out.buffers[at->second].bytes = std::move(bytes);
      }
    }
  return out;
}

// The floor quad fed to whatever vertex inputs the shader declares, told apart by name: position,
// normal (+y), tangent (+x; a vec4 one carries the handedness w = 1), bitangent / binormal (-z:
// cross(n, t), v grows away from the camera), texture coordinates.
bool floorForInputs(const spirv::Module& vertex, VertexBuffer* out, std::string* error) {
  struct Input { uint32_t location, components; std::string role; };
  std::vector<Input> inputs;
  for (const auto& inst : vertex.typesValues) {
    if (inst.opcode != spv::OpVariable || inst.operand(0) != spv::StorageClassInput) continue;
    if (vertex.hasDecoration(inst.resultId, spv::DecorationBuiltIn)) continue;
    auto location = vertex.decorationValue(inst.resultId, spv::DecorationLocation);
    if (!location) continue;
    std::string lower;
    for (char c : vertex.name(inst.resultId)) lower += char(std::tolower(static_cast<unsigned char>(c)));
    const spirv::Instruction* type = vertex.definition(vertex.pointeeType(inst.typeId));
    uint32_t components = type->opcode == spv::OpTypeVector ? type->operand(1) : 1;
    auto has = [&](const char* word) { return lower.find(word) != std::string::npos; };
    std::string role = has("bitangent") || has("binormal") ? "bitangent"
                       : has("tangent")                    ? "tangent"
                       : has("normal")                     ? "normal"
                       : has("tex") || has("uv")           ? "uv"
                       : has("pos")                        ? "position"
                                                           : "";
    if (role.empty()) {
      *error = "vertex input " + vertex.name(inst.resultId) + " is none of position, normal, tangent, bitangent, uv";
      return false;
    }
    inputs.push_back({*location, components, role});
  }
  std::sort(inputs.begin(), inputs.end(), [](const Input& a, const Input& b) { return a.location < b.location; });
  const VkFormat formats[5] = {VK_FORMAT_UNDEFINED, VK_FORMAT_R32_SFLOAT, VK_FORMAT_R32G32_SFLOAT,
                               VK_FORMAT_R32G32B32_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT};
  out->stride = 0;
  out->attributes.clear();
  for (const auto& in : inputs) {
    out->attributes.push_back({in.location, formats[in.components], out->stride});
    out->stride += 4 * in.components;
  }
  const float corners[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
  for (const auto& c : corners) {
    float x = -1.0f + 2.0f * c[0], z = 0.5f - 2.0f * c[1];
    for (const auto& in : inputs) {
      std::vector<float> v = in.role == "position"  ? std::vector<float>{x, 0, z, 1}
                             : in.role == "normal"  ? std::vector<float>{0, 1, 0, 0}
                             : in.role == "tangent" ? std::vector<float>{1, 0, 0, 1}
                             : in.role == "bitangent" ? std::vector<float>{0, 0, -1, 0}
                                                    : std::vector<float>{c[0], c[1], 0, 0};
      v.resize(in.components);
      append(out->bytes, v);
    }
  }
  return true;
}

// One tutorial-form pipeline and the values of its uniforms. `camera` fills the matrices and the
// camera position, by the names the shader uses, from (view, projection, camera position).
struct TutorialCase {
  std::string name;
  std::vector<std::string> files;  // vertex, [geometry,] fragment (under corpus/relief-tutorial/)
  std::function<std::map<std::string, Words>(const M& view, const M& proj, const rt::Vec3<double>& camera)> camera;
  std::map<std::string, Words> material;  // height scale, layers, mapping mode, light
};

// The acceptance bound on the fix: at most 5 in 10000 floor pixels may differ from the truth (each a
// sub-pixel boundary move, see PerEyeCameraMatchesGroundTruth). A differing pixel is off by at most
// 255 per channel, so the fix's mean squared error is at most 5e-4 * 255^2: PSNR >= 10 log10(1e4 / 5)
// = 33.0 dB whatever the scene. The baseline must fail that same bound (its error is more than the
// most the fix is allowed), which is the margin: it is derived from the fix's tolerance, not from
// the measured figures.
constexpr double kMaxDifferingFraction = 5.0 / 10000.0;
const double kPsnrFloor = 10.0 * std::log10(1.0 / kMaxDifferingFraction);

// `spliced`: the pipeline converted to its own language, the vertex stage by the source splice (the
// camera's reads wrapped in the text), each output compiled as a driver would; else to SPIR-V.
void renderTutorialCase(VulkanContext& context, const TutorialCase& c, bool spliced = false) {
  SCOPED_TRACE(c.name + (spliced ? " (spliced text)" : ""));
  std::vector<SourceFile> sources;
  for (const auto& f : c.files) sources.push_back({CORPUS_DIR "/relief-tutorial/" + f, {}});
  for (auto& s : sources) ASSERT_TRUE(readFile(s.path, &s.contents)) << s.path;
  TranspileOptions options;
  options.target = spliced ? TargetLanguage::Auto : TargetLanguage::Spirv;
  options.validateEach = true;

  std::vector<TranspileResult> converted = transpilePipeline(sources, options);
  ASSERT_EQ(converted.size(), sources.size());
  for (const auto& r : converted) ASSERT_TRUE(r.ok) << r.diagnostics.format();
  // The tutorial form is fixed in the vertex stage (in front of a geometry stage too): the later
  // stages only pass on or read the varyings.
  ASSERT_EQ(converted[0].report["passes"]["per-eye-view"]["result"], "changed") << converted[0].report.dump(2);
  if (spliced) {
    std::string route = converted[0].report.value("route", "");
    ASSERT_TRUE(route == "glsl-source-splice" || route == "hlsl-source-splice") << converted[0].report.dump(2);
    for (size_t i = 0; i < sources.size(); ++i) {
      Diagnostics diags;
      FrontEndResult text = compileToSpirv(SourceFile{sources[i].path, converted[i].output}, options, diags);
      ASSERT_TRUE(text.ok) << diags.format() << converted[i].output;
      converted[i].output.assign(reinterpret_cast<const char*>(text.spirv.data()), text.spirv.size() * 4);
    }
  }

  // Original and fixed modules, each through the harness's OpenGL-to-Vulkan rewrite (loose uniforms
  // into one block per stage, a no-op for Vulkan GLSL and HLSL).
  std::vector<spirv::Module> original, fixed;
  for (size_t i = 0; i < sources.size(); ++i) {
    Diagnostics diags;
    FrontEndResult front = compileToSpirv(sources[i], options, diags);
    ASSERT_TRUE(front.ok) << diags.format();
    std::string error;
    auto a = spirv::Module::parse(front.spirv, &error);
    auto b = spirv::Module::parse(words(converted[i].output), &error);
    ASSERT_TRUE(a && b) << error;
    convertOpenGLForVulkan(*a, 16 + uint32_t(i), &error);
    ASSERT_TRUE(error.empty()) << error;
    convertOpenGLForVulkan(*b, 16 + uint32_t(i), &error);
    ASSERT_TRUE(error.empty()) << error;
    if (front.info.language == SourceLanguage::Hlsl && !front.info.vulkanBindings) {  // b1 and t1 apart
      separateRegisterClasses(*a);
      separateRegisterClasses(*b);
    }
    original.push_back(std::move(*a));
    fixed.push_back(std::move(*b));
  }
  VertexBuffer quad;
  std::string error;
  ASSERT_TRUE(floorForInputs(original[0], &quad, &error)) << error;

  auto render = [&](const std::vector<spirv::Module>& modules, const M& view, const M& proj,
                    const rt::Vec3<double>& camera, const float* eyeParams) {
    std::map<std::string, Words> values = c.camera(view, proj, camera);
    values.insert(c.material.begin(), c.material.end());
    if (eyeParams) {
      values["eyeSign"] = floats({eyeParams[0]});
      values["separation"] = floats({eyeParams[1]});
      values["convergence"] = floats({eyeParams[2]});
    }
    Resources resources = reflectResources(modules, values);
    EXPECT_TRUE(resources.unfilled.empty()) << "no value for uniform " << resources.unfilled.front();
    RenderRequest request;
    request.width = request.height = kSize;
    Draw draw;
    for (const auto& m : modules) {
      auto model = m.executionModel();
      VkShaderStageFlagBits stage = model == spv::ExecutionModelVertex     ? VK_SHADER_STAGE_VERTEX_BIT
                                    : model == spv::ExecutionModelGeometry ? VK_SHADER_STAGE_GEOMETRY_BIT
                                                                           : VK_SHADER_STAGE_FRAGMENT_BIT;
      draw.pipeline.stages.push_back({stage, m.encode(), m.entryPointName()});
    }
    draw.pipeline.vertices = quad;
    draw.pipeline.vertexCount = 6;
    draw.pipeline.uniformBuffers = resources.buffers;
    draw.pipeline.textures = resources.textures;
    draw.pipeline.pushConstants = resources.pushConstants;
    request.draws = {draw};
    RenderResult result = context.render(request);
    EXPECT_TRUE(result.ok()) << result.error;
    return result;
  };

  const M view = viewMatrix(), proj = projection(), invView = rt::inverse(view);
  {
    float mono[3] = {0.0f, float(kSeparation), float(kConvergence)};
    RenderResult a = render(original, view, proj, kCamera, nullptr);
    RenderResult b = render(fixed, view, proj, kCamera, mono);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a.pixels, b.pixels) << "mono (eyeSign 0) must be the original image";
  }
  for (int e = 0; e < 2; ++e) {
    const double eye = e == 0 ? -1.0 : 1.0;
    const M stereoProj = rt::stereoProjectionGL(proj, eye, kSeparation, kConvergence);
    const rt::Vec3<double> offset = rt::eyeOffsetFromInverseView(invView, proj[0], eye, kSeparation, kConvergence);
    const rt::Vec3<double> eyeCentre = {kCamera[0] + offset[0], kCamera[1] + offset[1], kCamera[2] + offset[2]};
    const float params[3] = {float(eye), float(kSeparation), float(kConvergence)};
    RenderResult truth = render(original, view, stereoProj, eyeCentre, nullptr);
    RenderResult fix = render(fixed, view, proj, kCamera, params);
    RenderResult baseline = render(original, view, stereoProj, kCamera, nullptr);
    ASSERT_TRUE(truth.ok() && fix.ok() && baseline.ok());
    Comparison ours = compare(truth, fix), mono = compare(truth, baseline);
    std::cout << std::fixed << std::setprecision(2) << "[relief-tutorial] " << c.name << ", "
              << (e == 0 ? "left " : "right") << " eye, " << ours.covered << " floor pixels: fix PSNR " << ours.psnr
              << " dB, max diff " << ours.maxDifference << ", " << ours.differing << " pixels differ ("
              << ours.notASubpixelMove << " not a sub-pixel move) | mono-camera baseline PSNR " << mono.psnr << " dB, " << mono.differing
              << " pixels differ\n";
    EXPECT_GT(ours.covered, kSize * kSize / 4) << "the floor should fill a good part of the image";
    // Lit tutorials (diffuse + specular from the interpolated tangent-space vectors) shade smoothly,
    // so a last-bit change of the interpolants can also step a gradient by one rounding.
    EXPECT_EQ(ours.notASubpixelMove, 0u) << "a differing pixel that is not a sub-pixel move";
    EXPECT_LE(double(ours.differing), double(ours.covered) * kMaxDifferingFraction);
    EXPECT_GE(ours.psnr, kPsnrFloor);
    EXPECT_LT(mono.psnr, kPsnrFloor) << "the mono-camera baseline passes the fix's bound: the test cannot tell them apart";
    if (e == 1) {
      std::string stem = IMAGE_OUT_DIR "/relief_tutorial_" + c.name;
      EXPECT_TRUE(writePng(stem + "_right.png", kSize, kSize, fix.pixels.data()));
      EXPECT_TRUE(writePng(stem + "_right_truth.png", kSize, kSize, truth.pixels.data()));
      EXPECT_TRUE(writePng(stem + "_right_baseline.png", kSize, kSize, baseline.pixels.data()));
    }
  }
}

const rt::Vec3<double> kLight = {0.4, 2.0, 0.9};

// GLSL 330, loose uniforms `projection`, `view`, `model`, `viewPos` (the LearnOpenGL names).
std::map<std::string, Words> looseCamera(const M& view, const M& proj, const rt::Vec3<double>& camera) {
  return {{"projection", floats(proj)},
          {"view", floats(view)},
          {"model", floats(M{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1})},
          {"viewPos", floats({camera[0], camera[1], camera[2]})},
          {"lightPos", floats({kLight[0], kLight[1], kLight[2]})}};
}

const M kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// Vulkan GLSL: one block with the matrices and `cameraPos` (a vec4 used as .xyz); the fragment
// block selects plain (1) or occlusion (3) parallax.
std::map<std::string, Words> vulkanCamera(const M& view, const M& proj, const rt::Vec3<double>& camera) {
  return {{"projection", floats(proj)},
          {"view", floats(view)},
          {"model", floats(kIdentity)},
          {"lightPos", floats({kLight[0], kLight[1], kLight[2], 1})},
          {"cameraPos", floats({camera[0], camera[1], camera[2], 1})}};
}

// Vulkan GLSL with the camera in a struct (`CameraData { view; projection; position; }`) that the
// vertex stage copies whole into a local before reading it.
std::map<std::string, Words> structCamera(const M& view, const M& proj, const rt::Vec3<double>& camera) {
  Words whole = floats(view), projection = floats(proj), position = floats({camera[0], camera[1], camera[2], 1});
  whole.insert(whole.end(), projection.begin(), projection.end());  // std140: view, projection, position
  whole.insert(whole.end(), position.begin(), position.end());
  return {{"camera", whole}, {"model", floats(kIdentity)}};
}

// D3D-style HLSL: one cbuffer with the world and view-projection matrices and the eye position.
std::map<std::string, Words> hlslCamera(const M& view, const M& proj, const rt::Vec3<double>& camera) {
  return {{"gWorld", floats(kIdentity)},
          {"gViewProj", floats(rt::multiply(proj, view))},
          {"gEyePosW", floats({camera[0], camera[1], camera[2]})}};
}

// The tutorial pipelines, each with its uniforms: GLSL 330 loose uniforms, GLSL 330 through a
// geometry stage, Vulkan GLSL with a block, D3D-style HLSL.
std::vector<TutorialCase> tutorialCases() {
  std::vector<TutorialCase> cases = {
      {"gl330_parallax_mapping", {"gl330/parallax_mapping.vert", "gl330/parallax_mapping.frag"}, looseCamera,
       {{"heightScale", floats({kHeightScale})}}},
      {"gl330_steep_parallax", {"gl330/steep_parallax.vert", "gl330/steep_parallax.frag"}, looseCamera,
       {{"heightScale", floats({kHeightScale})}}},
  };
  // Through a geometry stage (the LearnOpenGL "explode" effect, GLSL 330): at time = -pi/2 the
  // triangles are not pushed out (sin = -1), so the truth is the same floor.
  cases.push_back({"gl330_explode_parallax_geometry",
                   {"gl330/explode_parallax.vert", "gl330/explode_parallax.geom", "gl330/explode_parallax.frag"},
                   looseCamera,
                   {{"heightScale", floats({kHeightScale})}, {"time", floats({-M_PI / 2})}}});
  for (int mode : {1, 3})
    cases.push_back({mode == 1 ? "vk450_parallax_plain" : "vk450_parallax_occlusion",
                     {"vk450/parallax.vert", "vk450/parallax.frag"},
                     vulkanCamera,
                     {{"heightScale", floats({kHeightScale})},
                      {"parallaxBias", floats({-0.02})},
                      {"numLayers", floats({48})},
                      {"mappingMode", integer(mode)}}});
  // The camera struct copied whole (`CameraData cam = camera;`): spliced, that copy is taken through
  // stereoshift_holder_camera(), which gives it this eye's camera; the fragment stage relief-maps
  // with a linear then binary search.
  cases.push_back({"vk450_camera_struct_copied_whole",
                   {"vk450/camera_block.vert", "vk450/camera_block.frag"},
                   structCamera,
                   {{"depthScale", floats({kHeightScale})}}});
  // D3D-style HLSL: one cbuffer with the world and view-projection matrices and the eye position,
  // an output struct; the pixel shader ray-marches with SampleGrad. Spliced, the camera's offset goes
  // through the inverse of gViewProj, which the splice writes as its own cofactor inverse.
  cases.push_back({"hlsl_parallax_occlusion",
                   {"hlsl/parallax.vert.hlsl", "hlsl/parallax.frag.hlsl"},
                   hlslCamera,
                   {{"gHeightScale", floats({kHeightScale})}, {"gMinSamples", integer(8)}, {"gMaxSamples", integer(32)}}});
  return cases;
}

TEST(ReliefRender, TutorialFormMatchesGroundTruth) {
  std::string error;
  auto context = VulkanContext::create(&error);
  ASSERT_TRUE(context) << error;
  for (const auto& c : tutorialCases()) renderTutorialCase(*context, c);
}

// The same scenes with the vertex stage spliced into its own text (the geometry case: the vertex
// stage before it gets the camera helper alone): the wrapped camera reads give the same images as
// the IR fix.
TEST(ReliefRender, TutorialFormSplicedTextMatchesGroundTruth) {
  std::string error;
  auto context = VulkanContext::create(&error);
  ASSERT_TRUE(context) << error;
  for (const auto& c : tutorialCases()) renderTutorialCase(*context, c, true);
}

}  // namespace
