// hud-at-depth alone (with detection): with --hud-at-depth a proven-2D position becomes pos * hudDepth;
// without the option, or on a perspective shader, nothing changes.
#include "test/unit/pass_fixture.h"

namespace stereoshift::test {
namespace {

TEST(HudAtDepthPass, PlacesATwoDimensionalShaderAtDepth) {
  TranspileOptions options = singlePassOptions();
  options.hudAtDepth = true;
  SinglePassRun run = runSinglePass(flatVertexShader(), "hud-at-depth", options);
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Changed);
  EXPECT_EQ(run.ran, (std::vector<std::string>{"clip-position-detection", "hud-at-depth"}));
  EXPECT_EQ(run.report["passes"]["hud-at-depth"]["stores"], 1);
  EXPECT_TRUE(containsInOrder(run.disassembly, {
      "OpMemberName %StereoParams 3 \"hudDepth\"", "%clip = OpCompositeConstruct %v4float",
      "OpAccessChain %_ptr_Uniform_float %stereo %int_3", "OpLoad %float", "OpVectorTimesScalar %v4float %clip",
      "OpStore %posptr"}));
  EXPECT_EQ(run.disassembly.find("OpStore %posptr %clip"), std::string::npos);
}

TEST(HudAtDepthPass, LeavesTwoDimensionalShadersMonoWithoutTheOption) {
  SinglePassRun run = runSinglePass(flatVertexShader(), "hud-at-depth");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Unchanged);
  EXPECT_EQ(run.disassembly.find("hudDepth"), std::string::npos);
  EXPECT_TRUE(containsInOrder(run.disassembly, {"OpStore %posptr %clip"}));
}

TEST(HudAtDepthPass, LeavesAPerspectiveShaderAlone) {
  TranspileOptions options = singlePassOptions();
  options.hudAtDepth = true;
  SinglePassRun run = runSinglePass(perspectiveVertexShader(false), "hud-at-depth", options);
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Unchanged);
  EXPECT_EQ(run.disassembly.find("OpVectorTimesScalar"), std::string::npos);
}

}  // namespace
}  // namespace stereoshift::test
