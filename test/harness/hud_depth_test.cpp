// HUD at depth by execution (hud-at-depth pass, --hud-at-depth, docs/stereo-math.md section 2).
//
// A 2D HUD vertex shader (every position written with the literal w = 1) is converted with
// TranspileOptions::hudAtDepth to SPIR-V; original and converted shader run on lavapipe with
// transform-feedback capture (capture_instrument.h) on the same vertices, the converted one with the
// eye parameters {eyeSign e, separation S, convergence C, hudDepth d} in its StereoParams block.
// From the original's captured (x, y, z, 1), the converted position must be
//   (x*d + e*S*(d - C), y*d, z*d, d),
// so that after the divide the NDC x parallax is e*S*(1 - C/d) and NDC y, z are the original ones.
// Bounds (u = 2^-24, fp32 round to nearest; the double reference below is exact up to its last
// addition, since x*d, d - C and S*(d - C) of these fp32 values fit in a double; that one rounding,
// 2^-53 relative, is far below the bound):
//   * y*d, z*d: one fp32 multiply (OpVectorTimesScalar), correctly rounded: bit-exact fl(y*d), fl(z*d);
//   * w: 1 * d, exact: bit-exact d;
//   * x: fl(x*d), then the shift's three roundings fl(w - C), fl(eS * (w - C)), fl(x*d + that)
//     (eS exact for e = +-1): |X - X_exact| <= u (|x d| + 2 |S (d - C)| + |X_exact|) (1 + 4u),
//     the factor covering the second-order terms (a fused evaluation only removes roundings);
//   * e = 0: the shift adds nothing: X bit-exact fl(x*d), and with d = 1 every output bit for bit
//     the original's;
//   * the non-position output (a varying) bit for bit the original's in every case.
// Without hudAtDepth the 2D shader is copied through: the SPIR-V is the original's, word for word.
#include "transpiler/verify/capture_instrument.h"
#include "transpiler/verify/stereo_verify.h"
#include "test/harness/vulkan_suite.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <iostream>

using namespace stereoshift;
using namespace stereoshift::harness;

namespace {

const char* kHudVert = R"(#version 450
layout(location = 0) in vec3 inPos;
layout(location = 1) in vec2 inUV;
layout(location = 0) out vec2 vUV;
void main() {
  vUV = inUV;
  gl_Position = vec4(inPos.xy, inPos.z * 0.5 + 0.25, 1.0);
}
)";

constexpr float kSeparation = 0.065f, kConvergence = 3.0f;
constexpr double kUnitRoundoff = 1.0 / (1 << 24);
constexpr uint32_t kVertexCount = 48;

VertexBuffer hudVertices() {
  VertexBuffer vb;
  vb.stride = 20;
  vb.attributes = {{0, VK_FORMAT_R32G32B32_SFLOAT, 0}, {1, VK_FORMAT_R32G32_SFLOAT, 12}};
  for (uint32_t i = 0; i < kVertexCount; ++i) {
    // x, y over [-1, 1] with non-dyadic values (the products round), z over [0, 1].
    float v[5] = {-1.0f + 2.0f * float(i) / 47.0f, 0.9f - 0.037f * float(i), float(i % 7) / 6.3f,
                  float(i) / 47.0f, 1.0f - float(i % 5) / 4.1f};
    if (i == 5) v[0] = -0.0f;  // a negative zero x
    size_t at = vb.bytes.size();
    vb.bytes.resize(at + 20);
    std::memcpy(vb.bytes.data() + at, v, 20);
  }
  return vb;
}

class HudDepth : public VulkanSuite<> {
 protected:
  void SetUp() override { ASSERT_TRUE(context_) << setupError_; }

  // Instruments a module for capture and runs it on the HUD vertices, with `eye` (4 floats) in the
  // eye-parameter block at (set, binding) when given.
  CaptureResult run(const std::vector<uint32_t>& words, const float* eye, uint32_t set, uint32_t binding,
                    CaptureLayout* layout) {
    std::string error;
    auto module = spirv::Module::parse(words, &error);
    EXPECT_TRUE(module) << error;
    if (!module) return {};
    Result<CaptureLayout> captured = instrumentForCapture(*module);
    EXPECT_TRUE(captured) << captured.error().message;
    if (captured) *layout = std::move(*captured);
    CaptureRequest request;
    request.pipeline.stages = {{VK_SHADER_STAGE_VERTEX_BIT, module->encode(), module->entryPointName()}};
    request.pipeline.vertices = hudVertices();
    request.pipeline.vertexCount = kVertexCount;
    if (eye) request.pipeline.uniformBuffers = {{set, binding, toBytes(eye, 4)}};
    request.xfbStride = layout->stride;
    request.expectedVertices = kVertexCount;
    CaptureResult r = context_->capture(request);
    EXPECT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.vertexCount(), kVertexCount);
    return r;
  }
};

std::vector<uint32_t> words(const std::string& bytes) {
  std::vector<uint32_t> w(bytes.size() / 4);
  std::memcpy(w.data(), bytes.data(), w.size() * 4);
  return w;
}

TEST_F(HudDepth, ClipPositionIsPlacedAtTheEyeDepthWithTheExactParallax) {
  TranspileOptions options;
  options.hudAtDepth = true;
  options.target = TargetLanguage::Spirv;
  TranspileResult r = transpile(SourceFile{"hud.vert", kHudVert}, options);
  ASSERT_TRUE(r.ok) << r.diagnostics.format();
  ASSERT_TRUE(r.changed);
  EXPECT_EQ(r.report.value("classification", std::string()), "2d-constant-w") << r.report.dump(2);
  EXPECT_EQ(r.report["passes"]["hud-at-depth"].value("result", std::string()), "changed") << r.report.dump(2);
  EXPECT_EQ(r.report["passes"]["stereo-shift"].value("result", std::string()), "changed") << r.report.dump(2);
  const auto& eyeReport = r.report["passes"]["eye-params"];
  ASSERT_EQ(eyeReport.value("declared", std::string()), "uniform block") << eyeReport.dump(2);
  const uint32_t set = eyeReport.value("set", 0u), binding = eyeReport.value("binding", 0u);

  CaptureLayout originalLayout, hudLayout;
  CaptureResult original = run(r.originalSpirv, nullptr, 0, 0, &originalLayout);
  ASSERT_TRUE(original.ok());
  ASSERT_EQ(originalLayout.stride, 24u);  // gl_Position, then vUV
  for (uint32_t v = 0; v < kVertexCount; ++v) ASSERT_EQ(original.f32(v, 3), 1.0f) << "a 2D shader writes w = 1";

  const double u = kUnitRoundoff;
  double worstRatio = 0, worstNdcParallaxError = 0;
  int cases = 0;
  for (float d : {kConvergence / 2, kConvergence, 4 * kConvergence, 1.0f})
    for (float e : {-1.0f, 0.0f, 1.0f}) {
      const float eye[4] = {e, kSeparation, kConvergence, d};
      CaptureResult hud = run(words(r.output), eye, set, binding, &hudLayout);
      ASSERT_TRUE(hud.ok());
      ASSERT_EQ(hudLayout.stride, originalLayout.stride);
      ++cases;
      for (uint32_t v = 0; v < kVertexCount; ++v) {
        SCOPED_TRACE("e " + std::to_string(e) + ", d " + std::to_string(d) + ", vertex " + std::to_string(v));
        const double x = original.f32(v, 0), y = original.f32(v, 1), z = original.f32(v, 2);
        // The varying is never touched.
        EXPECT_EQ(hud.u32(v, 4), original.u32(v, 4));
        EXPECT_EQ(hud.u32(v, 5), original.u32(v, 5));
        if (d == 1.0f) {
          // hudDepth 1: mono by construction; with e = +-1 the documented cutoff (|w - 1| <= eps
          // leaves the position unshifted) gives the same. Bit for bit the original.
          for (uint32_t c = 0; c < 4; ++c) EXPECT_EQ(hud.u32(v, c), original.u32(v, c)) << "component " << c;
          continue;
        }
        EXPECT_EQ(hud.u32(v, 1), floatBits(float(y * d))) << "y must be fl(y*d)";
        EXPECT_EQ(hud.u32(v, 2), floatBits(float(z * d))) << "z must be fl(z*d)";
        EXPECT_EQ(hud.u32(v, 3), floatBits(d)) << "w must be d";
        const double X = hud.f32(v, 0);
        if (e == 0.0f) {
          EXPECT_EQ(hud.u32(v, 0), floatBits(float(x * d))) << "mono: x must be fl(x*d)";
          continue;
        }
        const double shift = double(e) * kSeparation * (double(d) - kConvergence);
        const double exact = x * d + shift;
        const double bound = u * (std::abs(x * d) + 2 * std::abs(shift) + std::abs(exact)) * (1 + 4 * u);
        EXPECT_LE(std::abs(X - exact), bound) << "x' " << X << ", exact " << exact;
        worstRatio = std::max(worstRatio, std::abs(X - exact) / bound);
        // After the divide: NDC x parallax e*S*(1 - C/d) (within bound/d).
        const double parallax = X / d - x, exactParallax = double(e) * kSeparation * (1 - double(kConvergence) / d);
        worstNdcParallaxError = std::max(worstNdcParallaxError, std::abs(parallax - exactParallax));
      }
    }
  std::cout << std::setprecision(3) << "[hud-depth] S " << kSeparation << ", C " << kConvergence << ", d in {C/2, C, 4C, 1}, e in {-1, 0, 1}: "
            << cases << " runs of " << kVertexCount << " vertices; y, z, w bit-exact (fl(y d), fl(z d), d), e = 0 x bit-exact fl(x d), d = 1 "
            << "bit-identical to the original; worst |x' - x_exact| / bound " << worstRatio
            << "; worst NDC parallax error " << worstNdcParallaxError << "\n";
}

TEST_F(HudDepth, WithoutTheOptionTheShaderIsCopiedUnchanged) {
  TranspileOptions options;
  options.target = TargetLanguage::Spirv;
  TranspileResult r = transpile(SourceFile{"hud.vert", kHudVert}, options);
  ASSERT_TRUE(r.ok) << r.diagnostics.format();
  EXPECT_FALSE(r.changed) << r.report.dump(2);
  EXPECT_EQ(r.report.value("classification", std::string()), "2d-constant-w") << r.report.dump(2);
  EXPECT_NE(r.report["passes"]["hud-at-depth"].value("result", std::string()), "changed") << r.report.dump(2);
  EXPECT_EQ(words(r.output), r.originalSpirv) << "the 2D shader must come out as the front end made it";
}

}  // namespace
