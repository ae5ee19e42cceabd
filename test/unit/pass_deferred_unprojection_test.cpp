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

// The view-ray form (docs/stereo-math.md section 4, view rays):
// layout(set = 0, binding = 0) uniform Camera { mat4 projection; } camera;
// layout(set = 0, binding = 1) uniform sampler2D linearDepth;
// layout(location = 0) in vec2 inUV;
// layout(location = 1) in vec3 inViewRay;
// layout(location = 0) out vec4 outViewPos;
// void main() {
//   vec3 p = inViewRay * texture(linearDepth, inUV).r;
//   outViewPos = vec4(p, camera.projection[0][0]);
// }
const char* kViewRay = R"(
               OpCapability Shader
          %1 = OpExtInstImport "GLSL.std.450"
               OpMemoryModel Logical GLSL450
               OpEntryPoint Fragment %4 "main" %11 %20 %29
               OpExecutionMode %4 OriginUpperLeft
               OpSource GLSL 450
               OpName %4 "main"
               OpName %9 "p"
               OpName %11 "inViewRay"
               OpName %16 "linearDepth"
               OpName %20 "inUV"
               OpName %29 "outViewPos"
               OpName %32 "Camera"
               OpMemberName %32 0 "projection"
               OpName %34 "camera"
               OpDecorate %11 Location 1
               OpDecorate %16 DescriptorSet 0
               OpDecorate %16 Binding 1
               OpDecorate %20 Location 0
               OpDecorate %29 Location 0
               OpMemberDecorate %32 0 ColMajor
               OpMemberDecorate %32 0 Offset 0
               OpMemberDecorate %32 0 MatrixStride 16
               OpDecorate %32 Block
               OpDecorate %34 DescriptorSet 0
               OpDecorate %34 Binding 0
          %2 = OpTypeVoid
          %3 = OpTypeFunction %2
          %6 = OpTypeFloat 32
          %7 = OpTypeVector %6 3
          %8 = OpTypePointer Function %7
         %10 = OpTypePointer Input %7
         %11 = OpVariable %10 Input
         %13 = OpTypeImage %6 2D 0 0 0 1 Unknown
         %14 = OpTypeSampledImage %13
         %15 = OpTypePointer UniformConstant %14
         %16 = OpVariable %15 UniformConstant
         %18 = OpTypeVector %6 2
         %19 = OpTypePointer Input %18
         %20 = OpVariable %19 Input
         %22 = OpTypeVector %6 4
         %24 = OpTypeInt 32 0
         %25 = OpConstant %24 0
         %28 = OpTypePointer Output %22
         %29 = OpVariable %28 Output
         %31 = OpTypeMatrix %22 4
         %32 = OpTypeStruct %31
         %33 = OpTypePointer Uniform %32
         %34 = OpVariable %33 Uniform
         %35 = OpTypeInt 32 1
         %36 = OpConstant %35 0
         %37 = OpTypePointer Uniform %6
          %4 = OpFunction %2 None %3
          %5 = OpLabel
          %9 = OpVariable %8 Function
         %12 = OpLoad %7 %11
         %17 = OpLoad %14 %16
         %21 = OpLoad %18 %20
         %23 = OpImageSampleImplicitLod %22 %17 %21
         %26 = OpCompositeExtract %6 %23 0
         %27 = OpVectorTimesScalar %7 %12 %26
               OpStore %9 %27
         %30 = OpLoad %7 %9
         %38 = OpAccessChain %37 %34 %36 %36 %25
         %39 = OpLoad %6 %38
         %40 = OpCompositeExtract %6 %30 0
         %41 = OpCompositeExtract %6 %30 1
         %42 = OpCompositeExtract %6 %30 2
         %43 = OpCompositeConstruct %22 %40 %41 %42 %39
               OpStore %29 %43
               OpReturn
               OpFunctionEnd
)";

// Not a view ray: an interpolated colour scaled by the fragment's own depth (no texel), in a
// shader that reads projection[0][0] all the same.
// layout(set = 0, binding = 0) uniform Material { mat4 projection; float fogDensity; } material;
// layout(location = 0) in vec3 inColor;
// layout(location = 0) out vec4 outColor;
// void main() {
//   vec3 c = inColor * (gl_FragCoord.z * material.fogDensity);
//   outColor = vec4(c, material.projection[0][0]);
// }
const char* kScaledColour = R"(
               OpCapability Shader
          %1 = OpExtInstImport "GLSL.std.450"
               OpMemoryModel Logical GLSL450
               OpEntryPoint Fragment %4 "main" %11 %15 %33
               OpExecutionMode %4 OriginUpperLeft
               OpSource GLSL 450
               OpName %4 "main"
               OpName %9 "c"
               OpName %11 "inColor"
               OpName %15 "gl_FragCoord"
               OpName %22 "Material"
               OpMemberName %22 0 "projection"
               OpMemberName %22 1 "fogDensity"
               OpName %24 "material"
               OpName %33 "outColor"
               OpDecorate %11 Location 0
               OpDecorate %15 BuiltIn FragCoord
               OpMemberDecorate %22 0 ColMajor
               OpMemberDecorate %22 0 Offset 0
               OpMemberDecorate %22 0 MatrixStride 16
               OpMemberDecorate %22 1 Offset 64
               OpDecorate %22 Block
               OpDecorate %24 DescriptorSet 0
               OpDecorate %24 Binding 0
               OpDecorate %33 Location 0
          %2 = OpTypeVoid
          %3 = OpTypeFunction %2
          %6 = OpTypeFloat 32
          %7 = OpTypeVector %6 3
          %8 = OpTypePointer Function %7
         %10 = OpTypePointer Input %7
         %11 = OpVariable %10 Input
         %13 = OpTypeVector %6 4
         %14 = OpTypePointer Input %13
         %15 = OpVariable %14 Input
         %16 = OpTypeInt 32 0
         %17 = OpConstant %16 2
         %18 = OpTypePointer Input %6
         %21 = OpTypeMatrix %13 4
         %22 = OpTypeStruct %21 %6
         %23 = OpTypePointer Uniform %22
         %24 = OpVariable %23 Uniform
         %25 = OpTypeInt 32 1
         %26 = OpConstant %25 1
         %27 = OpTypePointer Uniform %6
         %32 = OpTypePointer Output %13
         %33 = OpVariable %32 Output
         %35 = OpConstant %25 0
         %36 = OpConstant %16 0
          %4 = OpFunction %2 None %3
          %5 = OpLabel
          %9 = OpVariable %8 Function
         %12 = OpLoad %7 %11
         %19 = OpAccessChain %18 %15 %17
         %20 = OpLoad %6 %19
         %28 = OpAccessChain %27 %24 %26
         %29 = OpLoad %6 %28
         %30 = OpFMul %6 %20 %29
         %31 = OpVectorTimesScalar %7 %12 %30
               OpStore %9 %31
         %34 = OpLoad %7 %9
         %37 = OpAccessChain %27 %24 %35 %35 %36
         %38 = OpLoad %6 %37
         %39 = OpCompositeExtract %6 %34 0
         %40 = OpCompositeExtract %6 %34 1
         %41 = OpCompositeExtract %6 %34 2
         %42 = OpCompositeConstruct %13 %39 %40 %41 %38
               OpStore %33 %42
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

TEST(DeferredUnprojectionPass, CorrectsTheViewXOfAViewRayTimesADepthRead) {
  SinglePassRun run = runSinglePass(kViewRay, "deferred-unprojection");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Changed);
  // p.x - (eyeSign*separation)*(|p.z| - convergence) * (1 / projection[0][0]), selected when
  // eyeSign != 0, and stored where p was.
  EXPECT_TRUE(containsInOrder(run.disassembly, {
      "OpVectorTimesScalar %v3float", "OpAccessChain %_ptr_Uniform_float %camera", "OpLoad %float",
      "OpFDiv %float %float_1", "OpCompositeExtract %float", "OpFNegate %float", "OpFOrdLessThan %bool",
      "OpSelect %float", "OpFSub %float", "OpFMul %float", "OpFMul %float", "OpFMul %float",
      "OpCompositeExtract %float", "OpFSub %float", "OpCompositeInsert %v3float", "OpFUnordNotEqual %bool",
      "OpSelect %v3float", "OpStore %p"}))
      << run.disassembly;
}

TEST(DeferredUnprojectionPass, LeavesAVectorScaledByADepthThatIsNoTexelAlone) {
  SinglePassRun run = runSinglePass(kScaledColour, "deferred-unprojection");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Unchanged);
  EXPECT_EQ(run.disassembly.find("StereoParams"), std::string::npos);
  EXPECT_EQ(run.disassembly.find("OpSelect"), std::string::npos);
}

}  // namespace
}  // namespace stereoshift::test
