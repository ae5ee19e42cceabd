// halo alone (with detection and eye-params): an output that copies the clip position gets the same
// shift; one that does not derive from it is left alone.
#include "test/unit/pass_fixture.h"

namespace stereoshift::test {
namespace {

TEST(HaloPass, ShiftsAnOutputCopiedFromThePosition) {
  SinglePassRun run = runSinglePass(perspectiveVertexShader(true), "halo");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Changed);
  EXPECT_EQ(run.ran, (std::vector<std::string>{"clip-position-detection", "eye-params", "halo"}));
  EXPECT_EQ(run.report["passes"]["halo"]["shifted_outputs"], nlohmann::json::array({"vClip"}));
  // Branch-free: x and w of the copy, the shift, the cutoff, a select, the insert, the store.
  EXPECT_TRUE(containsInOrder(run.disassembly, {
      "OpStore %posptr %clip", "%copy = OpLoad %v4float %copyptr", "OpCompositeExtract %float %copy 0",
      "OpCompositeExtract %float %copy 3", "OpFSub %float", "OpFAdd %float", "OpFUnordNotEqual %bool",
      "OpSelect %float", "OpCompositeInsert %v4float", "OpStore %vClip"}));
  // The position itself is stereo-shift's: no branch here.
  EXPECT_EQ(run.disassembly.find("OpSelectionMerge"), std::string::npos);
}

TEST(HaloPass, LeavesAnOutputNotDerivedFromThePosition) {
  SinglePassRun run = runSinglePass(perspectiveVertexShader(false), "halo");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Unchanged);
  EXPECT_EQ(run.report["passes"]["halo"]["shifted_outputs"], nlohmann::json::array());
  EXPECT_EQ(run.disassembly.find("OpSelect "), std::string::npos);
  EXPECT_TRUE(containsInOrder(run.disassembly, {"OpStore %posptr %clip", "OpStore %vClip %local", "OpReturn"}));
}

}  // namespace
}  // namespace stereoshift::test
