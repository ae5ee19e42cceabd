// deferred-unprojection alone: `q = InvViewProj * vec4(ndc, depth, 1)` with the NDC from
// gl_FragCoord and the depth sampled from a texture becomes the per-eye reconstruction; a plain
// `model * vec4(inPos, 1)` is no unprojection and stays as it is. The modules were made once with
// glslangValidator -V from the GLSL in the comments.
#include "test/unit/pass_fixture.h"

namespace stereoshift::test {
namespace {

// layout(set = 0, binding = 0) uniform Frame { mat4 invViewProj; vec2 texel; } frame;
// layout(set = 0, binding = 1) uniform sampler2D depthTex;
// layout(location = 0) out vec4 outWorld;
// void main() {
//   vec2 uv = gl_FragCoord.xy * frame.texel;
//   float depth = texture(depthTex, uv).r;
//   vec4 q = frame.invViewProj * vec4(uv * 2.0 - 1.0, depth, 1.0);
//   outWorld = q / q.w;
// }
const char* kUnprojection = R"(
               OpCapability Shader
          %1 = OpExtInstImport "GLSL.std.450"
               OpMemoryModel Logical GLSL450
               OpEntryPoint Fragment %4 "main" %12 %55
               OpExecutionMode %4 OriginUpperLeft
               OpName %4 "main"
               OpName %9 "uv"
               OpName %12 "gl_FragCoord"
               OpName %16 "Frame"
               OpMemberName %16 0 "invViewProj"
               OpMemberName %16 1 "texel"
               OpName %18 "frame"
               OpName %26 "depth"
               OpName %30 "depthTex"
               OpName %38 "q"
               OpName %55 "outWorld"
               OpDecorate %12 BuiltIn FragCoord
               OpMemberDecorate %16 0 ColMajor
               OpMemberDecorate %16 0 Offset 0
               OpMemberDecorate %16 0 MatrixStride 16
               OpMemberDecorate %16 1 Offset 64
               OpDecorate %16 Block
               OpDecorate %18 DescriptorSet 0
               OpDecorate %18 Binding 0
               OpDecorate %30 DescriptorSet 0
               OpDecorate %30 Binding 1
               OpDecorate %55 Location 0
          %2 = OpTypeVoid
          %3 = OpTypeFunction %2
          %6 = OpTypeFloat 32
          %7 = OpTypeVector %6 2
          %8 = OpTypePointer Function %7
         %10 = OpTypeVector %6 4
         %11 = OpTypePointer Input %10
         %12 = OpVariable %11 Input
         %15 = OpTypeMatrix %10 4
         %16 = OpTypeStruct %15 %7
         %17 = OpTypePointer Uniform %16
         %18 = OpVariable %17 Uniform
         %19 = OpTypeInt 32 1
         %20 = OpConstant %19 1
         %21 = OpTypePointer Uniform %7
         %25 = OpTypePointer Function %6
         %27 = OpTypeImage %6 2D 0 0 0 1 Unknown
         %28 = OpTypeSampledImage %27
         %29 = OpTypePointer UniformConstant %28
         %30 = OpVariable %29 UniformConstant
         %34 = OpTypeInt 32 0
         %35 = OpConstant %34 0
         %37 = OpTypePointer Function %10
         %39 = OpConstant %19 0
         %40 = OpTypePointer Uniform %15
         %44 = OpConstant %6 2
         %46 = OpConstant %6 1
         %54 = OpTypePointer Output %10
         %55 = OpVariable %54 Output
         %57 = OpConstant %34 3
          %4 = OpFunction %2 None %3
          %5 = OpLabel
          %9 = OpVariable %8 Function
         %26 = OpVariable %25 Function
         %38 = OpVariable %37 Function
         %13 = OpLoad %10 %12
         %14 = OpVectorShuffle %7 %13 %13 0 1
         %22 = OpAccessChain %21 %18 %20
         %23 = OpLoad %7 %22
         %24 = OpFMul %7 %14 %23
               OpStore %9 %24
         %31 = OpLoad %28 %30
         %32 = OpLoad %7 %9
         %33 = OpImageSampleImplicitLod %10 %31 %32
         %36 = OpCompositeExtract %6 %33 0
               OpStore %26 %36
         %41 = OpAccessChain %40 %18 %39
         %42 = OpLoad %15 %41
         %43 = OpLoad %7 %9
         %45 = OpVectorTimesScalar %7 %43 %44
         %47 = OpCompositeConstruct %7 %46 %46
         %48 = OpFSub %7 %45 %47
         %49 = OpLoad %6 %26
         %50 = OpCompositeExtract %6 %48 0
         %51 = OpCompositeExtract %6 %48 1
         %52 = OpCompositeConstruct %10 %50 %51 %49 %46
         %53 = OpMatrixTimesVector %10 %42 %52
               OpStore %38 %53
         %56 = OpLoad %10 %38
         %58 = OpAccessChain %25 %38 %57
         %59 = OpLoad %6 %58
         %60 = OpCompositeConstruct %10 %59 %59 %59 %59
         %61 = OpFDiv %10 %56 %60
               OpStore %55 %61
               OpReturn
               OpFunctionEnd
)";

// layout(set = 0, binding = 0) uniform Frame { mat4 model; } frame;
// layout(location = 0) in vec3 inPos;
// layout(location = 0) out vec4 outWorld;
// void main() { outWorld = frame.model * vec4(inPos, 1.0); }
const char* kModelTransform = R"(
               OpCapability Shader
          %1 = OpExtInstImport "GLSL.std.450"
               OpMemoryModel Logical GLSL450
               OpEntryPoint Fragment %4 "main" %9 %21
               OpExecutionMode %4 OriginUpperLeft
               OpName %4 "main"
               OpName %9 "outWorld"
               OpName %11 "Frame"
               OpMemberName %11 0 "model"
               OpName %13 "frame"
               OpName %21 "inPos"
               OpDecorate %9 Location 0
               OpMemberDecorate %11 0 ColMajor
               OpMemberDecorate %11 0 Offset 0
               OpMemberDecorate %11 0 MatrixStride 16
               OpDecorate %11 Block
               OpDecorate %13 DescriptorSet 0
               OpDecorate %13 Binding 0
               OpDecorate %21 Location 0
          %2 = OpTypeVoid
          %3 = OpTypeFunction %2
          %6 = OpTypeFloat 32
          %7 = OpTypeVector %6 4
          %8 = OpTypePointer Output %7
          %9 = OpVariable %8 Output
         %10 = OpTypeMatrix %7 4
         %11 = OpTypeStruct %10
         %12 = OpTypePointer Uniform %11
         %13 = OpVariable %12 Uniform
         %14 = OpTypeInt 32 1
         %15 = OpConstant %14 0
         %16 = OpTypePointer Uniform %10
         %19 = OpTypeVector %6 3
         %20 = OpTypePointer Input %19
         %21 = OpVariable %20 Input
         %23 = OpConstant %6 1
          %4 = OpFunction %2 None %3
          %5 = OpLabel
         %17 = OpAccessChain %16 %13 %15
         %18 = OpLoad %10 %17
         %22 = OpLoad %19 %21
         %24 = OpCompositeExtract %6 %22 0
         %25 = OpCompositeExtract %6 %22 1
         %26 = OpCompositeExtract %6 %22 2
         %27 = OpCompositeConstruct %7 %24 %25 %26 %23
         %28 = OpMatrixTimesVector %7 %18 %27
               OpStore %9 %28
               OpReturn
               OpFunctionEnd
)";

TEST(DeferredUnprojectionPass, MakesTheReconstructionPerEye) {
  SinglePassRun run = runSinglePass(kUnprojection, "deferred-unprojection");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Changed);
  EXPECT_EQ(run.ran, std::vector<std::string>{"deferred-unprojection"});
  // q - InvViewProj[0] * (eyeSign*separation)*(1 - convergence*q.w), selected when eyeSign != 0.
  EXPECT_TRUE(containsInOrder(run.disassembly, {
      "OpMemberName %StereoParams 0 \"eyeSign\"", "OpDecorate %stereo Binding 2", "OpMatrixTimesVector %v4float",
      "OpCompositeExtract %v4float", "OpFMul %float", "OpFSub %float %float_1", "OpFMul %float", "OpFMul %float",
      "OpVectorTimesScalar %v4float", "OpFSub %v4float", "OpFUnordNotEqual %bool", "OpSelect %v4float",
      "OpStore %q"}));
}

TEST(DeferredUnprojectionPass, LeavesAModelTransformAlone) {
  SinglePassRun run = runSinglePass(kModelTransform, "deferred-unprojection");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Unchanged);
  EXPECT_EQ(run.disassembly.find("StereoParams"), std::string::npos);
  EXPECT_EQ(run.disassembly.find("OpSelect"), std::string::npos);
}

}  // namespace
}  // namespace stereoshift::test
