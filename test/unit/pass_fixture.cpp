// See pass_fixture.h.
#include "test/unit/pass_fixture.h"

#include "passes/pass_manager.h"
#include "transpiler/report.h"

namespace stereoshift::test {

TranspileOptions singlePassOptions() {
  TranspileOptions options;
  options.validateEach = true;
  return options;
}

std::optional<spirv::Module> assembleModule(const std::string& assembly, uint32_t spirvVersion) {
  std::string error;
  std::vector<uint32_t> words = spirv::assemble(assembly, &error);
  if (words.size() < 5) {
    ADD_FAILURE() << "the test's SPIR-V does not assemble:\n" << error;
    return std::nullopt;
  }
  words[1] = spirvVersion;  // the assembler writes its own environment's version
  auto parsed = spirv::Module::parse(words, &error);
  if (!parsed) ADD_FAILURE() << "the test's SPIR-V does not parse: " << error;
  return parsed;
}

SinglePassRun runSinglePass(const std::string& assembly, const std::string& pass, TranspileOptions options,
                            uint32_t spirvVersion) {
  SinglePassRun run;
  auto parsed = assembleModule(assembly, spirvVersion);
  if (!parsed) return run;
  spirv::Module module = std::move(*parsed);
  SourceInfo source;
  source.language = SourceLanguage::Spirv;
  source.vulkan = true;
  source.entryPoint = module.entryPointName();
  Diagnostics diags;
  options.onlyPasses = {pass};
  AnalysisManager analyses(module, source, "test.spv");
  PassContext context{module, options, source, diags, "test.spv", analyses};
  bool changed = false;
  run.ok = runPassPipeline(context, &changed, nullptr);
  run.disassembly = spirv::disassemble(module.encode());
  run.record = context.record;
  run.report["passes"] = renderPassReport(context.record);
  run.diagnostics = diags.format();
  for (const auto& status : context.record.passes) run.ran.push_back(status.name);
  if (const PassStatus* status = context.record.status(pass)) run.result = status->result;
  return run;
}

std::string perspectiveVertexShader(bool withCopy) {
  std::string text = R"(
               OpCapability Shader
               OpMemoryModel Logical GLSL450
               OpEntryPoint Vertex %main "main" %pv %inPosition %vClip
               OpName %main "main"
               OpName %gl_PerVertex "gl_PerVertex"
               OpMemberName %gl_PerVertex 0 "gl_Position"
               OpName %pv "pv"
               OpName %Camera "Camera"
               OpMemberName %Camera 0 "viewProj"
               OpName %camera "camera"
               OpName %inPosition "inPosition"
               OpName %vClip "vClip"
               OpName %local "local"
               OpName %clip "clip"
               OpName %posptr "posptr"
               OpMemberDecorate %gl_PerVertex 0 BuiltIn Position
               OpDecorate %gl_PerVertex Block
               OpMemberDecorate %Camera 0 ColMajor
               OpMemberDecorate %Camera 0 Offset 0
               OpMemberDecorate %Camera 0 MatrixStride 16
               OpDecorate %Camera Block
               OpDecorate %camera DescriptorSet 0
               OpDecorate %camera Binding 0
               OpDecorate %inPosition Location 0
               OpDecorate %vClip Location 0
       %void = OpTypeVoid
     %fnvoid = OpTypeFunction %void
      %float = OpTypeFloat 32
    %v3float = OpTypeVector %float 3
    %v4float = OpTypeVector %float 4
%mat4v4float = OpTypeMatrix %v4float 4
        %int = OpTypeInt 32 1
      %int_0 = OpConstant %int 0
    %float_1 = OpConstant %float 1
%gl_PerVertex = OpTypeStruct %v4float
%_ptr_Output_gl_PerVertex = OpTypePointer Output %gl_PerVertex
         %pv = OpVariable %_ptr_Output_gl_PerVertex Output
     %Camera = OpTypeStruct %mat4v4float
%_ptr_Uniform_Camera = OpTypePointer Uniform %Camera
     %camera = OpVariable %_ptr_Uniform_Camera Uniform
%_ptr_Uniform_mat4v4float = OpTypePointer Uniform %mat4v4float
%_ptr_Input_v3float = OpTypePointer Input %v3float
 %inPosition = OpVariable %_ptr_Input_v3float Input
%_ptr_Output_v4float = OpTypePointer Output %v4float
      %vClip = OpVariable %_ptr_Output_v4float Output
       %main = OpFunction %void None %fnvoid
      %entry = OpLabel
      %vpptr = OpAccessChain %_ptr_Uniform_mat4v4float %camera %int_0
         %vp = OpLoad %mat4v4float %vpptr
         %in = OpLoad %v3float %inPosition
      %local = OpCompositeConstruct %v4float %in %float_1
       %clip = OpMatrixTimesVector %v4float %vp %local
     %posptr = OpAccessChain %_ptr_Output_v4float %pv %int_0
               OpStore %posptr %clip
)";
  if (withCopy) {
    text.insert(text.find("OpMemberDecorate %gl_PerVertex"), "OpName %copyptr \"copyptr\"\nOpName %copy \"copy\"\n");
    text += R"(
    %copyptr = OpAccessChain %_ptr_Output_v4float %pv %int_0
       %copy = OpLoad %v4float %copyptr
               OpStore %vClip %copy
)";
  } else {
    text += R"(
               OpStore %vClip %local
)";
  }
  return text + R"(
               OpReturn
               OpFunctionEnd
)";
}

std::string flatVertexShader() {
  return R"(
               OpCapability Shader
               OpMemoryModel Logical GLSL450
               OpEntryPoint Vertex %main "main" %pv %inPosition
               OpName %main "main"
               OpName %gl_PerVertex "gl_PerVertex"
               OpMemberName %gl_PerVertex 0 "gl_Position"
               OpName %pv "pv"
               OpName %inPosition "inPosition"
               OpName %clip "clip"
               OpName %posptr "posptr"
               OpMemberDecorate %gl_PerVertex 0 BuiltIn Position
               OpDecorate %gl_PerVertex Block
               OpDecorate %inPosition Location 0
       %void = OpTypeVoid
     %fnvoid = OpTypeFunction %void
      %float = OpTypeFloat 32
    %v2float = OpTypeVector %float 2
    %v4float = OpTypeVector %float 4
        %int = OpTypeInt 32 1
      %int_0 = OpConstant %int 0
    %float_0 = OpConstant %float 0
    %float_1 = OpConstant %float 1
%gl_PerVertex = OpTypeStruct %v4float
%_ptr_Output_gl_PerVertex = OpTypePointer Output %gl_PerVertex
         %pv = OpVariable %_ptr_Output_gl_PerVertex Output
%_ptr_Input_v2float = OpTypePointer Input %v2float
 %inPosition = OpVariable %_ptr_Input_v2float Input
%_ptr_Output_v4float = OpTypePointer Output %v4float
       %main = OpFunction %void None %fnvoid
      %entry = OpLabel
         %in = OpLoad %v2float %inPosition
       %clip = OpCompositeConstruct %v4float %in %float_0 %float_1
     %posptr = OpAccessChain %_ptr_Output_v4float %pv %int_0
               OpStore %posptr %clip
               OpReturn
               OpFunctionEnd
)";
}

::testing::AssertionResult containsInOrder(const std::string& text, const std::vector<std::string>& lines) {
  size_t at = 0;
  for (const auto& line : lines) {
    size_t found = text.find(line, at);
    if (found == std::string::npos)
      return ::testing::AssertionFailure() << "'" << line << "' not found"
                                           << (at ? " after the previous match" : "") << " in:\n" << text;
    at = found + line.size();
  }
  return ::testing::AssertionSuccess();
}

}  // namespace stereoshift::test
