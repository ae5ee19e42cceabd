// single-pass-stereo alone (with clip-position detection, which it requires): in the single-pass
// modes it changes the shaders that need it and leaves the others as they are; by default it does
// nothing at all.
#include "test/unit/pass_fixture.h"

namespace stereoshift::test {
namespace {

TranspileOptions singlePass(EyeSelect select) {
  TranspileOptions options = singlePassOptions();
  options.eye.select = select;
  return options;
}

// A vertex shader that reads the instance index: `vInstance = gl_InstanceIndex` beside a perspective position.
std::string instancedVertexShader() {
  return R"(
               OpCapability Shader
               OpMemoryModel Logical GLSL450
               OpEntryPoint Vertex %main "main" %pos %inPosition %instanceIndex %vInstance
               OpName %main "main"
               OpName %pos "pos"
               OpName %Camera "Camera"
               OpMemberName %Camera 0 "viewProj"
               OpName %camera "camera"
               OpName %inPosition "inPosition"
               OpName %instanceIndex "instanceIndex"
               OpName %vInstance "vInstance"
               OpName %read "read"
               OpDecorate %pos BuiltIn Position
               OpMemberDecorate %Camera 0 ColMajor
               OpMemberDecorate %Camera 0 Offset 0
               OpMemberDecorate %Camera 0 MatrixStride 16
               OpDecorate %Camera Block
               OpDecorate %camera DescriptorSet 0
               OpDecorate %camera Binding 0
               OpDecorate %inPosition Location 0
               OpDecorate %instanceIndex BuiltIn InstanceIndex
               OpDecorate %vInstance Location 0
               OpDecorate %vInstance Flat
       %void = OpTypeVoid
         %fn = OpTypeFunction %void
      %float = OpTypeFloat 32
        %int = OpTypeInt 32 1
    %v4float = OpTypeVector %float 4
%mat4v4float = OpTypeMatrix %v4float 4
     %Camera = OpTypeStruct %mat4v4float
  %ptrCamera = OpTypePointer Uniform %Camera
     %camera = OpVariable %ptrCamera Uniform
    %ptrMat4 = OpTypePointer Uniform %mat4v4float
      %int_0 = OpConstant %int 0
   %ptrInVec = OpTypePointer Input %v4float
 %inPosition = OpVariable %ptrInVec Input
  %ptrOutVec = OpTypePointer Output %v4float
        %pos = OpVariable %ptrOutVec Output
   %ptrInInt = OpTypePointer Input %int
%instanceIndex = OpVariable %ptrInInt Input
  %ptrOutInt = OpTypePointer Output %int
  %vInstance = OpVariable %ptrOutInt Output
       %main = OpFunction %void None %fn
      %entry = OpLabel
    %mptr = OpAccessChain %ptrMat4 %camera %int_0
    %m = OpLoad %mat4v4float %mptr
    %p = OpLoad %v4float %inPosition
    %clip = OpMatrixTimesVector %v4float %m %p
               OpStore %pos %clip
       %read = OpLoad %int %instanceIndex
               OpStore %vInstance %read
               OpReturn
               OpFunctionEnd
)";
}

TEST(SinglePassStereoPass, DoesNotRunWithoutASinglePassMode) {
  SinglePassRun run = runSinglePass(perspectiveVertexShader(false), "single-pass-stereo");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Unchanged);
  EXPECT_EQ(run.disassembly.find("ViewIndex"), std::string::npos);
}

TEST(SinglePassStereoPass, MultiviewDeclaresTheViewIndexOfAPerspectiveShader) {
  SinglePassRun run = runSinglePass(perspectiveVertexShader(false), "single-pass-stereo", singlePass(EyeSelect::ViewIndex));
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Changed);
  EXPECT_TRUE(containsInOrder(run.disassembly, {"OpCapability MultiView", "OpExtension \"SPV_KHR_multiview\"",
                                                "OpDecorate %gl_ViewIndex BuiltIn ViewIndex"}));
  EXPECT_EQ(run.report["passes"]["single-pass-stereo"]["mode"], "multiview");
}

TEST(SinglePassStereoPass, MultiviewLeavesATwoDimensionalShaderAlone) {
  SinglePassRun run = runSinglePass(flatVertexShader(), "single-pass-stereo", singlePass(EyeSelect::ViewIndex));
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Unchanged);
  EXPECT_EQ(run.disassembly.find("ViewIndex"), std::string::npos);
}

TEST(SinglePassStereoPass, InstancedGivesTheShaderTheOriginalInstanceAndRoutesTheEye) {
  SinglePassRun run = runSinglePass(instancedVertexShader(), "single-pass-stereo", singlePass(EyeSelect::InstanceIndex));
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Changed);
  // The eye (instance & 1) goes to the layer and the stereoEye varying first; the application's
  // own read now sees instance >> 1.
  EXPECT_TRUE(containsInOrder(run.disassembly, {
      "OpDecorate %stereoEye Location 15", "OpDecorate %gl_Layer BuiltIn Layer",
      "= OpBitwiseAnd %int", "OpStore %gl_Layer", "OpStore %stereoEye",
      "%read = OpLoad %int %instanceIndex", "= OpShiftRightArithmetic %int %read %int_1"}));
  EXPECT_EQ(run.disassembly.find("OpStore %vInstance %read"), std::string::npos) << run.disassembly;
  EXPECT_EQ(run.report["passes"]["single-pass-stereo"]["instance_reads_rewritten"], 1);
}

TEST(SinglePassStereoPass, InstancedRoutesTwoDimensionalShadersToo) {
  // A HUD drawn with the doubled instance count must land in both layers, shifted or not.
  SinglePassRun run = runSinglePass(flatVertexShader(), "single-pass-stereo", singlePass(EyeSelect::InstanceIndex));
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Changed);
  EXPECT_NE(run.disassembly.find("BuiltIn Layer"), std::string::npos);
}

TEST(SinglePassStereoPass, InstancedRefusesAnEyeVaryingLocationInUse) {
  TranspileOptions options = singlePass(EyeSelect::InstanceIndex);
  options.eye.eyeVaryingLocation = 0;  // vInstance's
  SinglePassRun run = runSinglePass(instancedVertexShader(), "single-pass-stereo", options);
  EXPECT_FALSE(run.ok);
  EXPECT_NE(run.diagnostics.find("output location 0 of the eye varying 'stereoEye' is taken by 'vInstance'"),
            std::string::npos) << run.diagnostics;
}

// A tessellation control shader that passes nothing on yet (its own outputs do not matter here).
std::string tessControlShader() {
  return R"(
               OpCapability Tessellation
               OpMemoryModel Logical GLSL450
               OpEntryPoint TessellationControl %main "main"
               OpExecutionMode %main OutputVertices 3
               OpName %main "main"
       %void = OpTypeVoid
         %fn = OpTypeFunction %void
       %main = OpFunction %void None %fn
      %entry = OpLabel
               OpReturn
               OpFunctionEnd
)";
}

TEST(SinglePassStereoPass, InstancedVertexStageBeforeAnotherHandsTheEyeOnWithoutALayer) {
  // A vertex stage followed by a geometry or tessellation stage (shiftThisStage false): the original
  // instance for the shader, the eye to `stereoEyeStage` for the next stage, no layer (it does not
  // rasterize).
  TranspileOptions options = singlePass(EyeSelect::InstanceIndex);
  options.shiftThisStage = false;
  SinglePassRun run = runSinglePass(instancedVertexShader(), "single-pass-stereo", options);
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Changed);
  EXPECT_TRUE(containsInOrder(run.disassembly, {"OpDecorate %stereoEyeStage Location 15", "= OpBitwiseAnd %int",
                                                "OpStore %stereoEyeStage", "= OpShiftRightArithmetic %int %read %int_1"}))
      << run.disassembly;
  EXPECT_EQ(run.disassembly.find("BuiltIn Layer"), std::string::npos) << run.disassembly;
  EXPECT_EQ(run.report["passes"]["single-pass-stereo"]["eye_handed_on"], true);
}

TEST(SinglePassStereoPass, InstancedTessellationControlHandsTheEyeOnPerPatch) {
  SinglePassRun run = runSinglePass(tessControlShader(), "single-pass-stereo", singlePass(EyeSelect::InstanceIndex));
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Changed);
  // Element 0 of the per-vertex input (every vertex of a patch comes from one instance) into a
  // patch output.
  EXPECT_TRUE(containsInOrder(run.disassembly, {"OpDecorate %stereoEyePatch Patch", "OpDecorate %stereoEyeStage Location 15",
                                                "%_arr_int_uint_32 = OpTypeArray %int %uint_32", "OpAccessChain %_ptr_Input_int %stereoEyeStage %int_0",
                                                "OpStore %stereoEyePatch"}))
      << run.disassembly;
}

TEST(SinglePassStereoPass, MultiviewLeavesTessellationControlAlone) {
  // Every stage reads gl_ViewIndex itself in multiview: nothing to hand on.
  SinglePassRun run = runSinglePass(tessControlShader(), "single-pass-stereo", singlePass(EyeSelect::ViewIndex));
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Unchanged);
}

}  // namespace
}  // namespace stereoshift::test
