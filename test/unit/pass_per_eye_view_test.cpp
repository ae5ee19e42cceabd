// per-eye-view alone (with detection, whose classification it reads): a view vector `camera - P`
// that steps texture coordinates gets the per-eye camera; one that only feeds shading stays mono.
#include "test/unit/pass_fixture.h"
#include "transpiler/stereoshift.h"

namespace stereoshift::test {
namespace {

// dir = normalize(camera.position - inWorldPos); outColor = texture(heightMap, 0.5 - dir.xy) * camera.position.x
// (texture coordinates moved along the view direction: a parallax offset)
const std::string kReliefMapping = R"(
               OpCapability Shader
          %1 = OpExtInstImport "GLSL.std.450"
               OpMemoryModel Logical GLSL450
               OpEntryPoint Fragment %main "main" %inWorldPos %outColor %inUV
               OpExecutionMode %main OriginUpperLeft
               OpName %main "main"
               OpName %Camera "Camera"
               OpMemberName %Camera 0 "position"
               OpName %camera "camera"
               OpName %camPtr "camPtr"
               OpName %camXPtr "camXPtr"
               OpName %inWorldPos "inWorldPos"
               OpName %inUV "inUV"
               OpName %outColor "outColor"
               OpName %heightMap "heightMap"
               OpMemberDecorate %Camera 0 Offset 0
               OpDecorate %Camera Block
               OpDecorate %camera DescriptorSet 0
               OpDecorate %camera Binding 0
               OpDecorate %heightMap DescriptorSet 0
               OpDecorate %heightMap Binding 1
               OpDecorate %inWorldPos Location 0
               OpDecorate %inUV Location 1
               OpDecorate %outColor Location 0
       %void = OpTypeVoid
     %fnvoid = OpTypeFunction %void
      %float = OpTypeFloat 32
    %v2float = OpTypeVector %float 2
    %v3float = OpTypeVector %float 3
    %v4float = OpTypeVector %float 4
        %int = OpTypeInt 32 1
      %int_0 = OpConstant %int 0
 %float_half = OpConstant %float 0.5
     %v2half = OpConstantComposite %v2float %float_half %float_half
     %Camera = OpTypeStruct %v3float
%_ptr_Uniform_Camera = OpTypePointer Uniform %Camera
     %camera = OpVariable %_ptr_Uniform_Camera Uniform
%_ptr_Uniform_v3float = OpTypePointer Uniform %v3float
%_ptr_Uniform_float = OpTypePointer Uniform %float
%_ptr_Input_v3float = OpTypePointer Input %v3float
 %inWorldPos = OpVariable %_ptr_Input_v3float Input
%_ptr_Input_v2float = OpTypePointer Input %v2float
       %inUV = OpVariable %_ptr_Input_v2float Input
%_ptr_Output_v4float = OpTypePointer Output %v4float
   %outColor = OpVariable %_ptr_Output_v4float Output
      %image = OpTypeImage %float 2D 0 0 0 1 Unknown
    %sampled = OpTypeSampledImage %image
%_ptr_UniformConstant_sampled = OpTypePointer UniformConstant %sampled
  %heightMap = OpVariable %_ptr_UniformConstant_sampled UniformConstant
       %main = OpFunction %void None %fnvoid
      %entry = OpLabel
     %camPtr = OpAccessChain %_ptr_Uniform_v3float %camera %int_0
        %cam = OpLoad %v3float %camPtr
      %world = OpLoad %v3float %inWorldPos
       %view = OpFSub %v3float %cam %world
        %dir = OpExtInst %v3float %1 Normalize %view
      %slope = OpVectorShuffle %v2float %dir %dir 0 1
     %baseUV = OpLoad %v2float %inUV
         %uv = OpFSub %v2float %baseUV %slope
        %tex = OpLoad %sampled %heightMap
      %texel = OpImageSampleImplicitLod %v4float %tex %uv
    %camXPtr = OpAccessChain %_ptr_Uniform_float %camera %int_0 %int_0
       %camX = OpLoad %float %camXPtr
     %scaled = OpVectorTimesScalar %v4float %texel %camX
               OpStore %outColor %scaled
               OpReturn
               OpFunctionEnd
)";

TEST(PerEyeViewPass, UsesThePerEyeCameraWhereTheViewVectorOffsetsTextureCoordinates) {
  SinglePassRun run = runSinglePass(kReliefMapping, "per-eye-view");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Changed);
  EXPECT_EQ(run.ran, (std::vector<std::string>{"clip-position-detection", "per-eye-view"}));
  EXPECT_TRUE(containsInOrder(run.disassembly, {
      "OpMemberName %StereoParams 4 \"eyeOffsetX\"", "OpMemberName %StereoParams 6 \"eyeOffsetZ\"",
      "OpLoad %v3float %camPtr", "OpAccessChain %_ptr_Uniform_float %stereo %int_4",
      "OpAccessChain %_ptr_Uniform_float %stereo %int_6", "OpCompositeConstruct %v3float",
      "OpFAdd %v3float", "OpFSub %v3float", "Normalize"}));
}

TEST(PerEyeViewPass, LeavesALookupAtAFunctionOfTheViewVectorMono) {
  // An area-light (LTC) or BRDF table read at `f(V) * scale + bias`: the coordinate is computed from
  // the view vector, no per-pixel coordinate is moved along it. Shading, mono (a false per-eye
  // camera before the moved coordinate had to be per pixel).
  std::string table = kReliefMapping;
  table.replace(table.find("%uv = OpFSub %v2float %baseUV %slope"),
                std::string("%uv = OpFSub %v2float %baseUV %slope").size(), "%uv = OpFAdd %v2float %slope %v2half");
  SinglePassRun run = runSinglePass(table, "per-eye-view");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Unchanged);
  EXPECT_EQ(run.disassembly.find("eyeOffsetX"), std::string::npos);
}

TEST(PerEyeViewPass, LeavesAViewVectorThatOnlyFeedsShading) {
  // The same shader with the texture lookup at a fixed coordinate: the view vector is only shading.
  std::string shading = kReliefMapping;
  shading.replace(shading.find("%texel = OpImageSampleImplicitLod %v4float %tex %uv"),
                  std::string("%texel = OpImageSampleImplicitLod %v4float %tex %uv").size(),
                  "%texel = OpVectorShuffle %v4float %dir %dir 0 1 2 2");
  SinglePassRun run = runSinglePass(shading, "per-eye-view");
  ASSERT_TRUE(run.ok) << run.diagnostics;
  EXPECT_EQ(run.result, PassResult::Unchanged);
  EXPECT_EQ(run.disassembly.find("eyeOffsetX"), std::string::npos);
}

TEST(PerEyeViewPass, LeavesALookupAlongTheViewVectorMonoUnlessPerEyeSpecular) {
  // The texture is read *at* the direction (a reflection / BRDF-table lookup), not at texture
  // coordinates moved along it: shading, mono by default, no new application parameters.
  std::string lookup = kReliefMapping;
  lookup.replace(lookup.find("%texel = OpImageSampleImplicitLod %v4float %tex %uv"),
                 std::string("%texel = OpImageSampleImplicitLod %v4float %tex %uv").size(),
                 "%texel = OpImageSampleImplicitLod %v4float %tex %slope");
  SinglePassRun mono = runSinglePass(lookup, "per-eye-view");
  ASSERT_TRUE(mono.ok) << mono.diagnostics;
  EXPECT_EQ(mono.result, PassResult::Unchanged);
  EXPECT_EQ(mono.disassembly.find("eyeOffsetX"), std::string::npos);
  ASSERT_TRUE(mono.report["passes"]["per-eye-view"].contains("left_alone")) << mono.report.dump(1);
  EXPECT_NE(mono.report["passes"]["per-eye-view"]["left_alone"][0]["reason"].get<std::string>().find("--per-eye-specular"),
            std::string::npos);

  TranspileOptions options = singlePassOptions();
  options.perEyeSpecular = true;
  SinglePassRun perEye = runSinglePass(lookup, "per-eye-view", options);
  ASSERT_TRUE(perEye.ok) << perEye.diagnostics;
  EXPECT_EQ(perEye.result, PassResult::Changed);
  EXPECT_NE(perEye.disassembly.find("eyeOffsetX"), std::string::npos);
}

// The tutorial form: the vertex shader passes the camera itself to tangent space; only the
// fragment stage subtracts. Converted as a pipeline, the camera is per eye where the fragment stage
// moves texture coordinates along the difference, and stays mono where it only shades.
const char* kTutorialVertex = R"(#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
layout (location = 2) in vec3 aTangent;
layout (location = 3) in vec2 aUV;
out VS_OUT { vec2 uv; vec3 tangentEye; vec3 tangentPos; } vs_out;
uniform mat4 projection;
uniform mat4 view;
uniform mat4 model;
uniform vec3 eyeWorld;
void main() {
  vec3 world = vec3(model * vec4(aPos, 1.0));
  vec3 n = normalize(mat3(model) * aNormal);
  vec3 t = normalize(mat3(model) * aTangent);
  mat3 tbn = transpose(mat3(t, cross(n, t), n));
  vs_out.uv = aUV;
  vs_out.tangentEye = tbn * eyeWorld;
  vs_out.tangentPos = tbn * world;
  gl_Position = projection * view * vec4(world, 1.0);
}
)";

std::string tutorialFragment(const std::string& use) {
  return std::string(R"(#version 330 core
in VS_OUT { vec2 uv; vec3 tangentEye; vec3 tangentPos; } fs_in;
out vec4 color;
uniform sampler2D heightMap;
void main() {
  vec3 v = normalize(fs_in.tangentEye - fs_in.tangentPos);
)") + use + "\n}\n";
}

std::vector<TranspileResult> convertTutorialPipeline(const std::string& fragment) {
  return transpilePipeline({{"relief.vert", kTutorialVertex}, {"relief.frag", fragment}}, TranspileOptions{});
}

TEST(PerEyeViewPipeline, CameraPassedToTheNextStageIsPerEyeWhereTheFragmentStageOffsetsTextureCoordinates) {
  auto results = convertTutorialPipeline(
      tutorialFragment("  color = texture(heightMap, fs_in.uv - v.xy / v.z * texture(heightMap, fs_in.uv).r * 0.05);"));
  ASSERT_EQ(results.size(), 2u);
  ASSERT_TRUE(results[0].ok) << results[0].diagnostics.format();
  const auto& pass = results[0].report["passes"]["per-eye-view"];
  ASSERT_TRUE(pass.contains("fixed")) << pass.dump(1);
  EXPECT_EQ(pass["fixed"][0]["uniform"], "eyeWorld");
  // The eye centre from the matrices that take the written world point to the clip position.
  EXPECT_NE(pass["fixed"][0]["eye_centre"].get<std::string>().find("inverse(projection * view)"), std::string::npos);
  EXPECT_FALSE(pass.contains("application"));  // nothing for the application to fill
  // Spliced into the vertex shader's own text: the camera's reads go through the per-eye helper.
  EXPECT_NE(results[0].output.find("stereoshift_eye_eyeWorld(eyeWorld)"), std::string::npos) << results[0].output;
  EXPECT_NE(results[0].output.find("return stereoshift_camera + (inverse(projection * view)"), std::string::npos)
      << results[0].output;
  EXPECT_TRUE(results[1].copiedThrough);  // the fragment shader is not touched
}

TEST(PerEyeViewPipeline, CameraPassedToTheNextStageStaysMonoWhereItOnlyShades) {
  auto results = convertTutorialPipeline(tutorialFragment("  color = texture(heightMap, fs_in.uv) * pow(max(v.z, 0.0), 8.0);"));
  ASSERT_EQ(results.size(), 2u);
  ASSERT_TRUE(results[0].ok) << results[0].diagnostics.format();
  const auto& pass = results[0].report["passes"]["per-eye-view"];
  EXPECT_FALSE(pass.contains("fixed")) << pass.dump(1);
  EXPECT_EQ(results[0].output.find("eyeOffset"), std::string::npos);
  EXPECT_EQ(results[0].output.find("inverse(projection"), std::string::npos);
}

TEST(PerEyeViewPipeline, ALookupAtTheViewVectorIsNotAnOffset) {
  // vec2(dot(n, v), roughness): a coordinate computed from V, not uv moved along it.
  auto results = convertTutorialPipeline(tutorialFragment("  color = texture(heightMap, vec2(max(v.z, 0.0), 0.5));"));
  ASSERT_EQ(results.size(), 2u);
  ASSERT_TRUE(results[0].ok) << results[0].diagnostics.format();
  EXPECT_FALSE(results[0].report["passes"]["per-eye-view"].contains("fixed"));
}

}  // namespace
}  // namespace stereoshift::test
