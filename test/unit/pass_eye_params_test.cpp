// eye-params alone (with clip-position detection, which it requires): declares the block for a
// shader that gets the shift, nothing for one that does not.
#include "test/unit/pass_fixture.h"

namespace stereoshift::test {
namespace {

TEST(EyeParamsPass, DeclaresTheBlockForAPerspectiveShader) {
  SinglePassRun run = runSinglePass(perspectiveVertexShader(false), "eye-params");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Changed);
  EXPECT_EQ(run.ran, (std::vector<std::string>{"clip-position-detection", "eye-params"}));
  EXPECT_EQ(run.report["passes"]["clip-position-detection"]["required_by"], "eye-params");
  EXPECT_TRUE(containsInOrder(run.disassembly, {
      "OpMemberName %StereoParams 0 \"eyeSign\"", "OpMemberName %StereoParams 1 \"separation\"",
      "OpMemberName %StereoParams 2 \"convergence\"", "OpDecorate %stereo DescriptorSet 0",
      "OpDecorate %stereo Binding 1", "%StereoParams = OpTypeStruct %float %float %float",
      "%stereo = OpVariable %_ptr_Uniform_StereoParams Uniform"}));
  // Declared, but nothing loads it yet: the shift is stereo-shift's.
  EXPECT_EQ(run.disassembly.find("%stereo %int"), std::string::npos);
}

TEST(EyeParamsPass, DeclaresNothingForATwoDimensionalShader) {
  SinglePassRun run = runSinglePass(flatVertexShader(), "eye-params");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Unchanged);
  EXPECT_EQ(run.disassembly.find("StereoParams"), std::string::npos);
}

}  // namespace
}  // namespace stereoshift::test
