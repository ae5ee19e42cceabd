// Single-pass stereo by execution (--eye-source multiview | instanced, single-pass-stereo pass).
//
// One mono scene (eight small perspective triangles, one per instance, each placed and coloured by
// gl_InstanceIndex; blended at alpha 0.5 with the depth test off, so an instance drawn twice into a
// layer shows) is converted three ways to SPIR-V and rendered on lavapipe into 32x32 targets:
//   * two passes (the default eye source): drawn once with eyeSign -1 and once with +1;
//   * multiview: one draw, view mask 0b11, into a two-layer target; eyeSign in the block is 0,
//     so a shader that still read it would not shift at all;
//   * instanced: one draw of twice the instances into a plain two-layer target (the vertex shader
//     writes gl_Layer), eyeSign 0 likewise.
// Each layer L of a single-pass render must equal, bit for bit, the two-pass render of eye L (view 0 /
// even instances the left eye, -1): the shift is the same arithmetic with eyeSign exactly +-1. The
// instanced render must also show every original instance (its own colour) exactly once per eye:
// twice would blend to another colour, the wrong instance index to another colour or place.
//
// The same scene through a geometry stage and through tessellation (the vertex stage only offsets
// by the instance; the last stage projects and gets the shift), converted as a pipeline: in
// instanced mode the eye is handed on from the vertex stage (stereoEyeStage, stereoEyePatch) to the
// stage that rasterizes, which writes gl_Layer; in multiview each stage reads gl_ViewIndex.
#include "transpiler/stereoshift.h"
#include "test/harness/vulkan_suite.h"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <map>

using namespace stereoshift;
using namespace stereoshift::harness;

namespace {

const char* kSceneVert = R"(#version 450
layout(location = 0) in vec3 inPos;
layout(set = 0, binding = 0) uniform Scene { mat4 proj; vec4 offsets[8]; } scene;
layout(location = 0) flat out vec3 vColor;
void main() {
  vec4 offset = scene.offsets[gl_InstanceIndex];
  gl_Position = scene.proj * vec4(inPos + offset.xyz, 1.0);
  vColor = vec3(float(gl_InstanceIndex + 1) / 8.0, 1.0 - float(gl_InstanceIndex) / 8.0, 0.25);
}
)";

const char* kSceneFrag = R"(#version 450
layout(location = 0) flat in vec3 vColor;
layout(location = 0) out vec4 outColor;
void main() { outColor = vec4(vColor, 0.5); }
)";

constexpr uint32_t kSize = 32, kInstances = 8;
constexpr float kSeparation = 0.2f, kConvergence = 2.5f;

std::vector<uint32_t> words(const std::string& bytes) {
  std::vector<uint32_t> w(bytes.size() / 4);
  std::memcpy(w.data(), bytes.data(), w.size() * 4);
  return w;
}

struct Converted {
  std::vector<uint32_t> spirv;
  uint32_t eyeSet = 0, eyeBinding = 0;
};

class SinglePassStereo : public VulkanSuite<> {
 protected:
  void SetUp() override {
    if (!context_) GTEST_SKIP() << setupError_;
  }

  static Converted convert(EyeSelect select) {
    TranspileOptions options;
    options.target = TargetLanguage::Spirv;
    options.eye.select = select;
    TranspileResult r = transpile(SourceFile{"scene.vert", kSceneVert}, options);
    EXPECT_TRUE(r.ok) << r.diagnostics.format();
    EXPECT_EQ(r.report.value("classification", std::string()), "perspective");
    const auto& eye = r.report["passes"]["eye-params"];
    return {words(r.output), eye.value("set", 0u), eye.value("binding", 0u)};
  }

  static std::vector<uint32_t> fragment() {
    TranspileResult r = transpile(SourceFile{"scene.frag", kSceneFrag}, TranspileOptions{});
    EXPECT_TRUE(r.ok) << r.diagnostics.format();
    return r.originalSpirv;
  }

  // The scene as one draw of `instances` instances with eyeSign `eyeSign` in the eye block.
  static Draw sceneDraw(const Converted& vert, float eyeSign, uint32_t instances) {
    Draw d;
    d.depthTest = false;
    d.depthWrite = false;
    d.alphaBlend = true;
    d.pipeline.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vert.spirv, "main"}, {VK_SHADER_STAGE_FRAGMENT_BIT, fragment(), "main"}};
    // A small triangle; the projection makes w = z (2 .. 3 here), so each instance gets a parallax.
    const std::vector<float> tri = {-0.45f, -0.4f, 0.0f, 0.45f, -0.35f, 0.0f, 0.05f, 0.45f, 0.0f};
    d.pipeline.vertices = {toBytes(tri), 12, {{0, VK_FORMAT_R32G32B32_SFLOAT, 0}}};
    d.pipeline.vertexCount = 3;
    d.pipeline.instanceCount = instances;
    std::vector<float> scene = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0.5f, 1, 0, 0, 0, 0};  // column-major proj
    for (uint32_t i = 0; i < kInstances; ++i) {
      float z = 2.0f + 0.125f * float(i);
      // A 4 x 2 grid in NDC (cells 8 x 16 pixels), apart in both eyes.
      float offset[4] = {(-0.75f + 0.5f * float(i % 4)) * z, (i < 4 ? -0.5f : 0.5f) * z, z, 0};
      scene.insert(scene.end(), offset, offset + 4);
    }
    const float eye[3] = {eyeSign, kSeparation, kConvergence};
    d.pipeline.uniformBuffers = {{0, 0, toBytes(scene)}, {vert.eyeSet, vert.eyeBinding, toBytes(eye, 3)}};
    return d;
  }

  static RenderResult render(std::vector<Draw> draws, uint32_t layers, bool layeredWithoutMultiview) {
    RenderRequest req;
    req.width = req.height = kSize;
    req.viewCount = layers;
    req.layeredWithoutMultiview = layeredWithoutMultiview;
    req.draws = std::move(draws);
    RenderResult r = context_->render(req);
    EXPECT_TRUE(r.ok()) << r.error;
    return r;
  }

  // The two-pass reference: eye 0 (eyeSign -1) and eye 1 (+1), each its own render.
  static std::array<RenderResult, 2> twoPass() {
    Converted vert = convert(EyeSelect::Parameter);
    return {render({sceneDraw(vert, -1.0f, kInstances)}, 1, false), render({sceneDraw(vert, 1.0f, kInstances)}, 1, false)};
  }

  static std::vector<uint8_t> layer(const RenderResult& r, uint32_t view) {
    const uint8_t* first = r.pixel(0, 0, view);
    return std::vector<uint8_t>(first, first + size_t(kSize) * kSize * 4);
  }

  // Pixels per colour (RGBA packed) of one layer.
  static std::map<uint32_t, int> colours(const RenderResult& r, uint32_t view) {
    std::map<uint32_t, int> count;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        uint32_t c;
        std::memcpy(&c, r.pixel(x, y, view), 4);
        ++count[c];
      }
    return count;
  }

  // Each layer of an instanced render equals the two-pass eye bit for bit, and every original
  // instance's colour (blended once over black) is there and nothing else but the background: no
  // instance is missing, doubled or drawn with a doubled index.
  static void expectEyesOfInstancedRender(const RenderResult& single, const std::array<RenderResult, 2>& reference) {
    for (uint32_t eye = 0; eye < 2; ++eye) {
      EXPECT_EQ(layer(single, eye), layer(reference[eye], 0)) << "layer " << eye;
      std::map<uint32_t, int> expected = colours(reference[eye], 0), seen = colours(single, eye);
      ASSERT_EQ(expected.size(), kInstances + 1) << "every instance must be visible in eye " << eye;
      EXPECT_EQ(seen, expected) << "layer " << eye;
    }
  }
};

TEST_F(SinglePassStereo, MultiviewLayersEqualTheTwoPassEyesBitForBit) {
  if (!context_->multiviewSupported()) GTEST_SKIP() << "multiview not supported";
  auto reference = twoPass();
  ASSERT_TRUE(reference[0].ok() && reference[1].ok());
  ASSERT_NE(layer(reference[0], 0), layer(reference[1], 0)) << "the eyes must differ for the test to mean anything";
  RenderResult single = render({sceneDraw(convert(EyeSelect::ViewIndex), 0.0f, kInstances)}, 2, false);
  ASSERT_TRUE(single.ok());
  for (uint32_t eye = 0; eye < 2; ++eye) EXPECT_EQ(layer(single, eye), layer(reference[eye], 0)) << "layer " << eye;
}

TEST_F(SinglePassStereo, InstancedLayersEqualTheTwoPassEyesAndDrawEachInstanceOncePerEye) {
  auto reference = twoPass();
  ASSERT_TRUE(reference[0].ok() && reference[1].ok());
  RenderResult single = render({sceneDraw(convert(EyeSelect::InstanceIndex), 0.0f, 2 * kInstances)}, 2, true);
  ASSERT_TRUE(single.ok());
  expectEyesOfInstancedRender(single, reference);
}

// ---- through a geometry stage and through tessellation ----

const char* kStagedVert = R"(#version 450
layout(location = 0) in vec3 inPos;
layout(set = 0, binding = 0) uniform Scene { mat4 proj; vec4 offsets[8]; } scene;
layout(location = 0) out vec3 vWorld;
layout(location = 1) flat out int vInstance;
void main() {
  vWorld = inPos + scene.offsets[gl_InstanceIndex].xyz;
  vInstance = gl_InstanceIndex;
}
)";

const char* kStagedGeom = R"(#version 450
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
layout(set = 0, binding = 0) uniform Scene { mat4 proj; vec4 offsets[8]; } scene;
layout(location = 0) in vec3 vWorld[];
layout(location = 1) flat in int vInstance[];
layout(location = 0) flat out vec3 vColor;
void main() {
  for (int i = 0; i < 3; ++i) {
    vColor = vec3(float(vInstance[i] + 1) / 8.0, 1.0 - float(vInstance[i]) / 8.0, 0.25);
    gl_Position = scene.proj * vec4(vWorld[i], 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
)";

const char* kStagedTesc = R"(#version 450
layout(vertices = 3) out;
layout(location = 0) in vec3 vWorld[];
layout(location = 1) flat in int vInstance[];
layout(location = 0) out vec3 cWorld[];
layout(location = 1) patch out int cInstance;
void main() {
  cWorld[gl_InvocationID] = vWorld[gl_InvocationID];
  cInstance = vInstance[0];
  gl_TessLevelOuter[0] = 1.0; gl_TessLevelOuter[1] = 1.0; gl_TessLevelOuter[2] = 1.0;
  gl_TessLevelInner[0] = 1.0;
}
)";

const char* kStagedTese = R"(#version 450
layout(triangles, equal_spacing, ccw) in;
layout(set = 0, binding = 0) uniform Scene { mat4 proj; vec4 offsets[8]; } scene;
layout(location = 0) in vec3 cWorld[];
layout(location = 1) patch in int cInstance;
layout(location = 0) flat out vec3 vColor;
void main() {
  vec3 p = gl_TessCoord.x * cWorld[0] + gl_TessCoord.y * cWorld[1] + gl_TessCoord.z * cWorld[2];
  vColor = vec3(float(cInstance + 1) / 8.0, 1.0 - float(cInstance) / 8.0, 0.25);
  gl_Position = scene.proj * vec4(p, 1.0);
}
)";

class SinglePassThroughStages : public SinglePassStereo, public ::testing::WithParamInterface<bool> {
 protected:
  static bool tessellated() { return GetParam(); }

  // The pipeline (vertex, then geometry or tessellation control + evaluation, then fragment) as
  // stereoshift converts it in one mode, as SPIR-V stages.
  static std::vector<ShaderStage> convertPipeline(EyeSelect select, Converted* last) {
    TranspileOptions options;
    options.target = TargetLanguage::Spirv;
    options.eye.select = select;
    std::vector<SourceFile> sources = {{"scene.vert", kStagedVert}};
    if (tessellated()) {
      sources.push_back({"scene.tesc", kStagedTesc});
      sources.push_back({"scene.tese", kStagedTese});
    } else {
      sources.push_back({"scene.geom", kStagedGeom});
    }
    sources.push_back({"scene.frag", kSceneFrag});
    std::vector<TranspileResult> results = transpilePipeline(sources, options);
    const VkShaderStageFlagBits kinds[] = {VK_SHADER_STAGE_VERTEX_BIT, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT,
                                           VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, VK_SHADER_STAGE_FRAGMENT_BIT};
    const VkShaderStageFlagBits geometryKinds[] = {VK_SHADER_STAGE_VERTEX_BIT, VK_SHADER_STAGE_GEOMETRY_BIT,
                                                   VK_SHADER_STAGE_FRAGMENT_BIT};
    std::vector<ShaderStage> stages;
    for (size_t i = 0; i < results.size(); ++i) {
      EXPECT_TRUE(results[i].ok) << sources[i].path << ": " << results[i].diagnostics.format();
      stages.push_back({tessellated() ? kinds[i] : geometryKinds[i], words(results[i].output), "main"});
    }
    const TranspileResult& shifted = results[results.size() - 2];
    EXPECT_EQ(shifted.report.value("classification", std::string()), "perspective");
    const auto& eye = shifted.report["passes"]["eye-params"];
    *last = {{}, eye.value("set", 0u), eye.value("binding", 0u)};
    return stages;
  }

  static Draw stagedDraw(EyeSelect select, float eyeSign, uint32_t instances) {
    Converted last;
    std::vector<ShaderStage> stages = convertPipeline(select, &last);
    Draw d = sceneDraw(last, eyeSign, instances);
    d.pipeline.stages = std::move(stages);
    if (tessellated()) {
      d.pipeline.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
      d.pipeline.patchControlPoints = 3;
    }
    return d;
  }

  static std::array<RenderResult, 2> stagedTwoPass() {
    return {render({stagedDraw(EyeSelect::Parameter, -1.0f, kInstances)}, 1, false),
            render({stagedDraw(EyeSelect::Parameter, 1.0f, kInstances)}, 1, false)};
  }
};

TEST_P(SinglePassThroughStages, InstancedEyeHandedOnToTheRasterizingStage) {
  auto reference = stagedTwoPass();
  ASSERT_TRUE(reference[0].ok() && reference[1].ok());
  ASSERT_NE(layer(reference[0], 0), layer(reference[1], 0)) << "the eyes must differ for the test to mean anything";
  RenderResult single = render({stagedDraw(EyeSelect::InstanceIndex, 0.0f, 2 * kInstances)}, 2, true);
  ASSERT_TRUE(single.ok());
  expectEyesOfInstancedRender(single, reference);
}

TEST_P(SinglePassThroughStages, MultiviewLayersEqualTheTwoPassEyes) {
  if (!context_->multiviewSupported()) GTEST_SKIP() << "multiview not supported";
  auto reference = stagedTwoPass();
  ASSERT_TRUE(reference[0].ok() && reference[1].ok());
  RenderRequest req;
  req.width = req.height = kSize;
  req.viewCount = 2;
  req.draws = {stagedDraw(EyeSelect::ViewIndex, 0.0f, kInstances)};
  RenderResult single = context_->render(req);
  if (single.error.find("does not support multiview with") != std::string::npos) GTEST_SKIP() << single.error;
  ASSERT_TRUE(single.ok()) << single.error;
  for (uint32_t eye = 0; eye < 2; ++eye) EXPECT_EQ(layer(single, eye), layer(reference[eye], 0)) << "layer " << eye;
}

INSTANTIATE_TEST_SUITE_P(Stages, SinglePassThroughStages, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? std::string("Tessellation") : std::string("Geometry");
                         });

}  // namespace
