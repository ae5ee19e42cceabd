// stereo-shift alone: `--pass stereo-shift` pulls in what it requires (detection and eye-params)
// and shifts; it used to return the original shader silently.
#include "test/unit/pass_fixture.h"

namespace stereoshift::test {
namespace {

TEST(StereoShiftPass, ShiftsThePositionAndPullsInWhatItRequires) {
  SinglePassRun run = runSinglePass(perspectiveVertexShader(false), "stereo-shift");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Changed);
  EXPECT_EQ(run.ran, (std::vector<std::string>{"clip-position-detection", "eye-params", "stereo-shift"}));
  EXPECT_EQ(run.report["passes"]["clip-position-detection"]["required_by"], "stereo-shift");
  EXPECT_EQ(run.report["passes"]["eye-params"]["required_by"], "stereo-shift");
  EXPECT_FALSE(run.report["passes"]["stereo-shift"].contains("required_by"));
  EXPECT_EQ(run.report["passes"]["stereo-shift"]["sites"], 1);
  // The guarded form: load, cutoff test, branch, x + eyeSign*separation*(w - convergence), store x.
  EXPECT_TRUE(containsInOrder(run.disassembly, {
      "OpMemberDecorate %gl_PerVertex 0 Invariant", "OpStore %posptr %clip",
      "OpAccessChain %_ptr_Output_v4float %pv %int_0", "OpCompositeExtract %float", "OpFUnordNotEqual %bool",
      "OpFOrdGreaterThan %bool", "OpIsInf %bool", "OpSelectionMerge", "OpBranchConditional",
      "OpFSub %float", "OpFMul %float", "OpFMul %float", "OpFAdd %float",
      "OpAccessChain %_ptr_Output_float %pv %int_0 %int_0", "OpStore", "OpReturn"}));
  // The copy to vClip is halo's business, not the shift's.
  EXPECT_TRUE(containsInOrder(run.disassembly, {"OpStore %vClip %local"}));
}

TEST(StereoShiftPass, LeavesATwoDimensionalShaderAlone) {
  SinglePassRun run = runSinglePass(flatVertexShader(), "stereo-shift");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Unchanged);
  EXPECT_EQ(run.report["passes"]["clip-position-detection"]["classification"], "2d-constant-w");
  EXPECT_EQ(run.disassembly.find("OpSelectionMerge"), std::string::npos);
  EXPECT_EQ(run.disassembly.find("StereoParams"), std::string::npos);
}

}  // namespace
}  // namespace stereoshift::test
