// clip-position-detection alone: it classifies and finds the positions, and never changes the module
// (so its "changed" case is the proof that a perspective shader stays byte for byte as it was).
#include "test/unit/pass_fixture.h"

namespace stereoshift::test {
namespace {

TEST(ClipPositionDetectionPass, PerspectiveShaderIsClassifiedAndLeftAsItIs) {
  std::string before = spirv::disassemble(spirv::assemble(perspectiveVertexShader(false), nullptr));
  SinglePassRun run = runSinglePass(perspectiveVertexShader(false), "clip-position-detection");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Unchanged);
  const auto& report = run.report["passes"]["clip-position-detection"];
  EXPECT_EQ(report["classification"], "perspective");
  EXPECT_EQ(report["positions"], nlohmann::json::array({"gl_PerVertex.gl_Position"}));
  EXPECT_EQ(run.ran, std::vector<std::string>{"clip-position-detection"});
  // Same module apart from the header's version word, which the fixture sets to 1.0.
  EXPECT_EQ(run.disassembly.substr(run.disassembly.find("OpCapability")), before.substr(before.find("OpCapability")));
}

TEST(ClipPositionDetectionPass, LiteralWOneIsTwoDimensional) {
  SinglePassRun run = runSinglePass(flatVertexShader(), "clip-position-detection");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Unchanged);
  EXPECT_EQ(run.report["passes"]["clip-position-detection"]["classification"], "2d-constant-w");
}

TEST(ClipPositionDetectionPass, ShaderWithTheEyeParametersIsAlreadyStereo) {
  std::string shader = perspectiveVertexShader(false);
  // The application declares eyeSign and separation itself: never shifted twice.
  shader.replace(shader.find("OpName %vClip"), 0, "OpName %camera \"eyeSign\"\nOpMemberName %Camera 0 \"separation\"\n");
  SinglePassRun run = runSinglePass(shader, "clip-position-detection");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.report["passes"]["clip-position-detection"]["classification"], "already-stereo");
  EXPECT_NE(run.diagnostics.find("already carries stereo eye parameters"), std::string::npos);
}

}  // namespace
}  // namespace stereoshift::test
