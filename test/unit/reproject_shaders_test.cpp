// transpiler/reproject: the depth decode against the projection it inverts, the option checks, and
// every option varied one at a time producing shaders that compile and validate in every language.
#include "transpiler/reproject/reproject_shaders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace stereoshift;

namespace {

// z_ndc of eye depth w for the projection the options describe, computed from its definition
// (near -> one end of the range, far -> the other, affine in 1/w), then stored as the texture holds it.
double storedDepth(const ReprojectOptions& o, double w) {
  const double n = o.nearPlane, inverseFar = o.farPlane ? 1.0 / *o.farPlane : 0.0;
  double fromNear = (1.0 / n - 1.0 / w) / (1.0 / n - inverseFar);  // 0 at the near plane, 1 at the far one
  if (o.reversedZ) fromNear = 1.0 - fromNear;
  return fromNear;  // window depth: both conventions store [0, 1]
}

TEST(ReprojectShaders, DepthDecodeInvertsTheProjection) {
  for (ReprojectDepth kind : {ReprojectDepth::ZeroToOne, ReprojectDepth::MinusOneToOne})
    for (bool reversed : {false, true})
      for (std::optional<double> far : {std::optional<double>(), std::optional<double>(250.0)}) {
        ReprojectOptions o;
        o.depth = kind;
        o.reversedZ = reversed;
        o.nearPlane = 0.05;
        o.farPlane = far;
        DepthDecode d = depthDecode(o);
        ASSERT_FALSE(d.linear);
        for (double w : {0.05, 0.3, 4.0, 77.0, 250.0}) {
          double invW = storedDepth(o, w) * d.scale + d.offset;
          EXPECT_NEAR(invW, 1.0 / w, 1e-12 / w) << reprojectDepthName(kind) << (reversed ? " reversed" : "") << " w " << w;
        }
      }
  // The projection's own depth row: OpenGL z_clip = -(f+n)/(f-n) z - 2fn/(f-n) is the same decode as near/far.
  ReprojectOptions byPlanes, byRow;
  byPlanes.depth = byRow.depth = ReprojectDepth::MinusOneToOne;
  byPlanes.nearPlane = 0.5;
  byPlanes.farPlane = 40.0;
  byRow.depthScale = -(40.0 + 0.5) / (40.0 - 0.5);
  byRow.depthOffset = -2.0 * 40.0 * 0.5 / (40.0 - 0.5);
  EXPECT_NEAR(depthDecode(byPlanes).scale, depthDecode(byRow).scale, 1e-12);
  EXPECT_NEAR(depthDecode(byPlanes).offset, depthDecode(byRow).offset, 1e-12);
  ReprojectOptions linear;
  linear.depth = ReprojectDepth::Linear;
  EXPECT_TRUE(depthDecode(linear).linear);
}

TEST(ReprojectShaders, OptionChecksNameTheOption) {
  ReprojectOptions o;
  EXPECT_TRUE(checkReprojectOptions(o).empty());
  o.samples = 1;
  o.nearPlane = 0;
  o.farPlane = -3.0;
  auto problems = checkReprojectOptions(o);
  ASSERT_EQ(problems.size(), 3u);
  EXPECT_NE(problems[0].find("--samples"), std::string::npos);
  EXPECT_NE(problems[1].find("--near"), std::string::npos);
  EXPECT_NE(problems[2].find("--far"), std::string::npos);
  ReprojectOptions loose;
  loose.eye.source = EyeSource::LooseUniforms;
  loose.target = TargetLanguage::Spirv;
  EXPECT_EQ(checkReprojectOptions(loose).size(), 1u);
  loose.target = TargetLanguage::Glsl;
  EXPECT_TRUE(checkReprojectOptions(loose).empty());
}

// Each option away from its default, every target: both shaders come out (compiled again, validated).
TEST(ReprojectShaders, EveryOptionEveryTargetCompiles) {
  std::vector<std::pair<const char*, std::function<void(ReprojectOptions&)>>> variants = {
      {"default", [](ReprojectOptions&) {}},
      {"push constants", [](ReprojectOptions& o) { o.eye.source = EyeSource::PushConstant; }},
      {"spec constants", [](ReprojectOptions& o) { o.eye.source = EyeSource::SpecConstant; }},
      {"centre", [](ReprojectOptions& o) { o.source = ReprojectSource::Centre; }},
      {"right", [](ReprojectOptions& o) { o.source = ReprojectSource::RightEye; }},
      {"linear", [](ReprojectOptions& o) { o.depth = ReprojectDepth::Linear; }},
      {"gl reversed", [](ReprojectOptions& o) { o.depth = ReprojectDepth::MinusOneToOne; o.reversedZ = true; o.farPlane = 10.0; }},
      {"secant", [](ReprojectOptions& o) { o.refinement = ReprojectRefinement::Secant; }},
      {"no refinement", [](ReprojectOptions& o) { o.refinement = ReprojectRefinement::None; }},
      {"interpolated", [](ReprojectOptions& o) { o.colour = ReprojectColour::Interpolated; }},
      {"farther + mask", [](ReprojectOptions& o) { o.fill = DisocclusionFill::FartherSample; o.maskOutput = true; }},
  };
  for (const auto& [name, apply] : variants)
    for (TargetLanguage target : {TargetLanguage::Glsl, TargetLanguage::Essl, TargetLanguage::Hlsl, TargetLanguage::Msl,
                                  TargetLanguage::Spirv}) {
      ReprojectOptions o;
      apply(o);
      o.target = target;
      ReprojectResult r = generateReprojectShaders(o);
      ASSERT_TRUE(r.ok) << name << ": " << r.diagnostics.format();
      ASSERT_EQ(r.shaders.size(), 2u);
      EXPECT_EQ(r.shaders[1].binary, target == TargetLanguage::Spirv);
      for (const auto& output : r.report["outputs"])
        EXPECT_EQ(output.value("verified", false), target != TargetLanguage::Msl && target != TargetLanguage::Spirv)
            << name << " " << output.dump();
    }
  ReprojectOptions loose;
  loose.eye.source = EyeSource::LooseUniforms;
  for (TargetLanguage target : {TargetLanguage::Glsl, TargetLanguage::Essl}) {
    loose.target = target;
    ReprojectResult r = generateReprojectShaders(loose);
    EXPECT_TRUE(r.ok) << r.diagnostics.format();
  }
}

}  // namespace
