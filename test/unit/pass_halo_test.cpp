// halo alone (with detection and eye-params): an output that copies the clip position gets the same
// shift; one that does not derive from it is left alone.
#include "test/unit/pass_fixture.h"
#include "transpiler/stereoshift.h"

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

// Halo by value, through the whole driver (GLSL in): outputs equal to the position although
// computed again, or derived from such a recomputation, are shifted; another matrix is not a copy.
nlohmann::json haloOf(const std::string& body) {
  std::string source = R"(#version 450
layout(set = 0, binding = 0) uniform Scene { mat4 mvp; mat4 depthBiasMVP; } scene;
layout(location = 0) in vec3 inPos;
layout(location = 0) out vec4 outA;
layout(location = 1) out vec4 outB;
vec4 project(vec3 p) { return scene.mvp * vec4(p, 1.0); }
void main() {
)" + body + "\n}\n";
  TranspileResult result = transpile({"halo.vert", source}, TranspileOptions{});
  EXPECT_TRUE(result.ok) << result.diagnostics.format();
  return result.report["passes"]["halo"]["shifted_outputs"];
}

TEST(HaloByValue, ShiftsARecomputedPositionAndWhatIsDerivedFromIt) {
  EXPECT_EQ(haloOf("outA = scene.mvp * vec4(inPos, 1.0);\n"
                   "outB = vec4(project(inPos).xy * 0.5, 0.0, 1.0);\n"
                   "gl_Position = scene.mvp * vec4(inPos, 1.0);"),
            nlohmann::json::array({"outA", "outB"}));
}

TEST(HaloByValue, ShiftsAnOutputThePositionIsReadBackFrom) {
  EXPECT_EQ(haloOf("outA = scene.mvp * vec4(inPos, 1.0);\ngl_Position = outA;"), nlohmann::json::array({"outA"}));
}

TEST(HaloByValue, LeavesAProductWithAnotherMatrix) {
  EXPECT_EQ(haloOf("outA = scene.depthBiasMVP * vec4(inPos, 1.0);\n"
                   "outB = scene.mvp * vec4(inPos * 2.0, 1.0);\n"
                   "gl_Position = scene.mvp * vec4(inPos, 1.0);"),
            nlohmann::json::array());
}

}  // namespace
}  // namespace stereoshift::test
