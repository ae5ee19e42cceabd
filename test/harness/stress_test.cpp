// Numerical stress suite: a pass-through vertex shader (gl_Position = the attribute) gives full
// control of x and w, so the sweep reaches every regime of docs/stereo-math.md section 2 and 6. Each case states
// its bound and checks it on lavapipe against the double-precision reference.
#include "transpiler/verify/stereo_verify.h"
#include "test/harness/vulkan_suite.h"

#include "passes/ir/module.h"

#include <gtest/gtest.h>

#include <array>
#include <cstring>

#include <cmath>
#include <limits>

using namespace stereoshift;
using namespace stereoshift::harness;

namespace {

const char* kPassThrough = R"(#version 450
layout(location = 0) in vec4 inClip;
void main() { gl_Position = inClip; }
)";

// The same with mediump inputs and arithmetic: the injected maths must stay full precision.
const char* kMediump = R"(#version 450
layout(location = 0) in mediump vec4 inClip;
layout(set = 0, binding = 0) uniform Scale { mediump float k; } scale;
void main() { mediump vec4 p = inClip * scale.k; gl_Position = p; }
)";

std::vector<StageModules> build(const char* source, const TranspileOptions& options) {
  std::vector<StageModules> stages;
  std::string classification;
  Diagnostics diags;
  EXPECT_TRUE(buildStageModules({{"stress.vert", source}}, options, &stages, &classification, diags))
      << diags.format();
  EXPECT_EQ(classification, "perspective");
  return stages;
}

// w log-spaced over [1e-4, 1e7], x inside and outside the frustum, and the cutoff's own cases.
std::vector<std::array<float, 4>> sweep() {
  std::vector<std::array<float, 4>> v;
  for (int i = 0; i <= 110; ++i) {
    float w = static_cast<float>(std::pow(10.0, -4.0 + 11.0 * i / 110.0));
    v.push_back({0.37f * w, -0.2f * w, 0.5f * w, w});
    v.push_back({-1.9f * w, 0.1f, 0.0f, w});
  }
  v.push_back({0.25f, 0.5f, 0.5f, 1.0f});                          // w exactly 1 (HUD, and a 3D vertex at depth 1)
  v.push_back({0.25f, 0.5f, 0.5f, std::nextafter(1.0f, 0.0f)});    // 1 - 2^-24: inverted orthographic matrix
  v.push_back({0.25f, 0.5f, 0.5f, std::nextafter(1.0f, 2.0f)});    // 1 + 2^-23
  v.push_back({-0.0f, 0.0f, 0.0f, 5.0f});                          // a negative zero x
  while (v.size() % 3) v.push_back({0.f, 0.f, 0.f, 2.f});
  return v;
}

class Stress : public VulkanSuite<> {};

// Runs the sweep over the 25 (separation, convergence) pairs and checks what every arithmetic form
// must keep: bit-exact mono identity, unchanged other outputs, no new NaN, and the cutoff keeping
// exactly the vertices with |w - 1| <= 1e-5 (w == 1 three times, 1 - 2^-24, 1 + 2^-23). Returns the
// worst stereo error; each test states its own bound on it.
double worstOverGrid(VulkanContext& context, const TranspileOptions& options, const char* label) {
  auto stages = build(kPassThrough, options);
  auto vertices = sweep();
  double worst = 0;
  for (float separation : {0.0f, 0.01f, 0.065f, 0.5f, 1.0f})
    for (float convergence : {0.01f, 1.0f, 3.0f, 100.0f, 1e4f}) {
      VerifySettings s;
      s.separation = separation;
      s.convergence = convergence;
      s.vertices = clipVertices(vertices);
      s.vertexCount = static_cast<uint32_t>(vertices.size());
      VerifyResult r = verifyStereo(context, stages, s);
      EXPECT_TRUE(r.error.empty()) << r.error;
      EXPECT_TRUE(r.monoIdentical) << label << " S=" << separation << " C=" << convergence << ": "
                                   << (r.problems.empty() ? "" : r.problems.front());
      EXPECT_TRUE(r.otherOutputsUnchanged) << label;
      EXPECT_EQ(r.newNaNs, 0u) << label;
      EXPECT_EQ(r.cutoffVertices, 5u) << label << " S=" << separation << " C=" << convergence;
      worst = std::max(worst, r.maxStereoUlps);
    }
  std::cout << "[stress] " << label << ": worst stereo error over 25 (S, C) pairs x " << vertices.size()
            << " vertices: " << worst << " ULP\n";
  return worst;
}

TEST_F(Stress, SeparationConvergenceAndDepthSweep) {
  ASSERT_TRUE(context_) << setupError_;
  // Bound: 2.5 ULP of max(|x|, |S(w - C)|), the analytic bound of three fp32 roundings.
  EXPECT_LE(worstOverGrid(*context_, {}, "separate"), 2.5);
}

TEST_F(Stress, FusedShiftSweep) {
  ASSERT_TRUE(context_) << setupError_;
  TranspileOptions fused;
  fused.fusedShift = true;
  // Bound: fma saves the product's rounding, but w - C and the final sum still round: <= 2 ULP
  // analytically; the separate-rounding bound 2.5 is asserted for both forms.
  EXPECT_LE(worstOverGrid(*context_, fused, "fused"), 2.5);
}

TEST_F(Stress, CompensatedShiftSweepWithinOneUlp) {
  ASSERT_TRUE(context_) << setupError_;
  TranspileOptions compensated;
  compensated.compensatedShift = true;
  // Bound: one final rounding of a nearly exact sum: <= 0.5 ulp(x') <= 1 ULP of max(|x|, |S(w - C)|).
  EXPECT_LE(worstOverGrid(*context_, compensated, "compensated"), 1.0);
}

TEST_F(Stress, ExactCutoffShiftsTheOrthographicOffByOne) {
  ASSERT_TRUE(context_) << setupError_;
  TranspileOptions exact;
  exact.cutoff = CutoffMode::Exact;
  auto stages = build(kPassThrough, exact);
  auto vertices = sweep();
  VerifySettings s;
  s.cutoffEpsilon = 0.0f;
  s.vertices = clipVertices(vertices);
  s.vertexCount = static_cast<uint32_t>(vertices.size());
  VerifyResult r = verifyStereo(*context_, stages, s);
  ASSERT_TRUE(r.error.empty()) << r.error;
  // The driver's exact rule keeps only w == 1 itself (3 vertices of the sweep): 1 - 2^-24 and
  // 1 + 2^-23 are shifted (the orthographic HUD pitfall of docs/stereo-math.md section 2).
  EXPECT_EQ(r.cutoffVertices, 3u);
  EXPECT_LE(r.maxStereoUlps, 2.5);
}

TEST_F(Stress, NaNAndInfinityNeverCreateNaN) {
  ASSERT_TRUE(context_) << setupError_;
  auto stages = build(kPassThrough, {});
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<std::array<float, 4>> v = {
      {1.f, 0.f, 0.f, inf}, {1.f, 0.f, 0.f, -inf}, {inf, 0.f, 0.f, 2.f}, {nan, 0.f, 0.f, 2.f},
      {1.f, 0.f, 0.f, nan}, {-inf, 0.f, 0.f, 3.f}};
  for (float separation : {0.0f, 0.065f}) {
    VerifySettings s;
    s.separation = separation;
    s.vertices = clipVertices(v);
    s.vertexCount = static_cast<uint32_t>(v.size());
    VerifyResult r = verifyStereo(*context_, stages, s);
    ASSERT_TRUE(r.error.empty()) << r.error;
    // Bound: no NaN where the original had none, and bit-exact mono identity.
    EXPECT_EQ(r.newNaNs, 0u) << "S=" << separation;
    EXPECT_TRUE(r.monoIdentical);
    EXPECT_TRUE(r.ok) << (r.problems.empty() ? "" : r.problems.front());
  }
}

TEST_F(Stress, MediumPrecisionShaderGetsFullPrecisionShift) {
  ASSERT_TRUE(context_) << setupError_;
  auto stages = build(kMediump, {});
  // The injected arithmetic carries no RelaxedPrecision: count the decorations before and after.
  auto countRelaxed = [](const std::vector<uint32_t>& words) {
    std::string error;
    auto m = spirv::Module::parse(words, &error);
    size_t n = 0;
    for (const auto& inst : m->annotations)
      n += inst.opcode == spv::OpDecorate && inst.operand(1) == uint32_t(spv::DecorationRelaxedPrecision);
    return n;
  };
  EXPECT_EQ(countRelaxed(stages[0].original), countRelaxed(stages[0].transpiled));
  auto vertices = sweep();
  VerifySettings s;
  s.vertices = clipVertices(vertices);
  s.vertexCount = static_cast<uint32_t>(vertices.size());
  VerifyResult r = verifyStereo(*context_, stages, s);
  ASSERT_TRUE(r.error.empty()) << r.error;
  EXPECT_TRUE(r.monoIdentical);
  EXPECT_LE(r.maxStereoUlps, 2.5);
}

}  // namespace
