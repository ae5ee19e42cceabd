// ValueNumbers: equal computations get equal numbers across helper calls, opaque values at two
// calls stay apart, and the work is linear in the module however its values share sub-expressions
// or its helpers call each other (counted in visits, not timed).
#include "passes/analysis/value_numbers.h"
#include "passes/ir/disassemble.h"
#include "passes/ir/module.h"
#include "test/unit/pass_fixture.h"
#include "transpiler/frontend/front_end.h"

#include <gtest/gtest.h>

#include <string>

namespace stereoshift::analysis {
namespace {

const char* kTypes = R"(
               OpDecorate %inPos Location 0
               OpDecorate %outA Location 0
               OpDecorate %outB Location 1
       %void = OpTypeVoid
     %fnVoid = OpTypeFunction %void
      %float = OpTypeFloat 32
         %v4 = OpTypeVector %float 4
        %pIn = OpTypePointer Input %v4
       %pOut = OpTypePointer Output %v4
      %pPriv = OpTypePointer Private %v4
       %fnV4 = OpTypeFunction %v4 %v4
     %fnNone = OpTypeFunction %v4
      %inPos = OpVariable %pIn Input
       %outA = OpVariable %pOut Output
       %outB = OpVariable %pOut Output
      %state = OpVariable %pPriv Private
)";

// The module up to its functions; the ids a test asks about are named (OpName) so it can find them.
std::string header(const std::vector<std::string>& named) {
  std::string text = R"(
               OpCapability Shader
               OpMemoryModel Logical GLSL450
               OpEntryPoint Vertex %main "main" %inPos %outA %outB
)";
  for (const auto& name : named) text += "OpName %" + name + " \"" + name + "\"\n";
  return text + kTypes;
}

// `prefix_1 = prefix_0 * prefix_0 + prefix_0`, ... up to prefix_N: each value used twice by the next.
std::string chain(const std::string& prefix, int length) {
  std::string text;
  for (int i = 1; i <= length; ++i) {
    std::string previous = "%" + prefix + "_" + std::to_string(i - 1), name = "%" + prefix + "_" + std::to_string(i);
    text += name + "m = OpFMul %v4 " + previous + " " + previous + "\n";
    text += name + " = OpFAdd %v4 " + name + "m " + previous + "\n";
  }
  return text;
}

spirv::Module parse(const std::string& assembly) {
  auto module = test::assembleModule(assembly);
  return module ? std::move(*module) : spirv::Module{};
}

uint64_t instructionCount(const spirv::Module& module) {
  uint64_t n = 0;
  for (const auto& fn : module.functions)
    for (const auto& block : fn.blocks) n += block.instructions.size();
  return n;
}

// main computes the chain itself (top_N) and calls a helper that computes it from its parameter
// at two call sites (the HLSL shape: the whole entry point inside a helper).
std::string chainThroughAHelper(int length) {
  return header({"top_0", "top_" + std::to_string(length), "callA", "callB"}) + R"(
       %main = OpFunction %void None %fnVoid
      %entry = OpLabel
      %top_0 = OpLoad %v4 %inPos
)" + chain("top", length) + R"(
      %callA = OpFunctionCall %v4 %helper %top_0
      %callB = OpFunctionCall %v4 %helper %top_0
               OpStore %outA %callA
               OpStore %outB %callB
               OpReturn
               OpFunctionEnd
     %helper = OpFunction %v4 None %fnV4
      %arg_0 = OpFunctionParameter %v4
       %body = OpLabel
)" + chain("arg", length) + "OpReturnValue %arg_" + std::to_string(length) + "\nOpFunctionEnd\n";
}

uint32_t idOf(const spirv::Module& module, const std::string& name) {
  for (uint32_t id = 1; id < module.bound(); ++id)
    if (module.name(id) == name) return id;
  ADD_FAILURE() << "no id named " << name;
  return 0;
}

TEST(ValueNumbers, AHelpersLongChainEqualsTheSameChainComputedInMain) {
  for (int length : {1, 16, 200}) {
    spirv::Module module = parse(chainThroughAHelper(length));
    ValueNumbers numbers(module);
    uint32_t top = idOf(module, "top_" + std::to_string(length));
    EXPECT_TRUE(numbers.equal(top, idOf(module, "callA"))) << length;
    EXPECT_TRUE(numbers.equal(idOf(module, "callA"), idOf(module, "callB"))) << length;
    EXPECT_FALSE(numbers.equal(top, idOf(module, "top_0"))) << length;
  }
}

TEST(ValueNumbers, SharedSubExpressionsCostLinearWork) {
  // Each value of the chain is read twice by the next: numbered without memory, the helper's
  // return value alone is 2^length visits.
  uint64_t previousPerInstruction = 0;
  for (int length : {16, 64, 256, 1024}) {
    spirv::Module module = parse(chainThroughAHelper(length));
    ValueNumbers numbers(module);
    uint64_t instructions = instructionCount(module);
    EXPECT_LT(numbers.visits(), numbers.visitBudget()) << length;  // all of it numbered, none cut off
    uint64_t perInstruction = numbers.visits() / instructions;
    EXPECT_LE(perInstruction, 4u) << length << ": " << numbers.visits() << " visits for " << instructions;
    if (previousPerInstruction) EXPECT_LE(perInstruction, previousPerInstruction + 1) << length;
    previousPerInstruction = perInstruction;
  }
}

TEST(ValueNumbers, CallsThatFanOutStayWithinTheBudget) {
  // f_k(x) = f_{k-1}(x) + f_{k-1}(x * x): 2^k call paths for k levels.
  const int levels = 40;
  std::string text = header({"r0"}) + R"(
       %main = OpFunction %void None %fnVoid
      %entry = OpLabel
         %p0 = OpLoad %v4 %inPos
         %r0 = OpFunctionCall %v4 %f)" + std::to_string(levels) + R"( %p0
               OpStore %outA %r0
               OpReturn
               OpFunctionEnd
)";
  for (int k = levels; k >= 1; --k) {
    std::string f = "%f" + std::to_string(k), below = "%f" + std::to_string(k - 1), s = std::to_string(k);
    text += f + " = OpFunction %v4 None %fnV4\n%x" + s + " = OpFunctionParameter %v4\n%b" + s + " = OpLabel\n";
    text += "%sq" + s + " = OpFMul %v4 %x" + s + " %x" + s + "\n";
    text += "%l" + s + " = OpFunctionCall %v4 " + below + " %x" + s + "\n";
    text += "%r" + s + " = OpFunctionCall %v4 " + below + " %sq" + s + "\n";
    text += "%s" + s + " = OpFAdd %v4 %l" + s + " %r" + s + "\nOpReturnValue %s" + s + "\nOpFunctionEnd\n";
  }
  text += "%f0 = OpFunction %v4 None %fnV4\n%x0 = OpFunctionParameter %v4\n%b0 = OpLabel\n"
          "%y0 = OpFAdd %v4 %x0 %x0\nOpReturnValue %y0\nOpFunctionEnd\n";
  spirv::Module module = parse(text);
  ValueNumbers numbers(module);
  EXPECT_LE(numbers.visits(), numbers.visitBudget());
  EXPECT_LE(numbers.visitBudget(), 64 * instructionCount(module) + 65536);
  EXPECT_TRUE(numbers.number(idOf(module, "r0")).has_value());
}

TEST(ValueNumbers, AnOpaqueValueAtTwoCallsIsTwoValues) {
  // The helper reads private memory main writes twice: equal arguments (none), unequal values.
  std::string text = header({"first", "second"}) + R"(
       %main = OpFunction %void None %fnVoid
      %entry = OpLabel
          %p = OpLoad %v4 %inPos
               OpStore %state %p
      %first = OpFunctionCall %v4 %read
         %p2 = OpFMul %v4 %p %p
               OpStore %state %p2
     %second = OpFunctionCall %v4 %read
               OpStore %outA %first
               OpStore %outB %second
               OpReturn
               OpFunctionEnd
       %read = OpFunction %v4 None %fnNone
      %rbody = OpLabel
       %held = OpLoad %v4 %state
     %twice = OpFAdd %v4 %held %held
               OpReturnValue %twice
               OpFunctionEnd
)";
  spirv::Module module = parse(text);
  ValueNumbers numbers(module);
  EXPECT_FALSE(numbers.equal(idOf(module, "first"), idOf(module, "second")));
  EXPECT_TRUE(numbers.equal(idOf(module, "first"), idOf(module, "first")));
}

// A D3D10 effect file of the shape that took minutes and gigabytes: an instanced vertex shader
// whose wind sway is a chain of shared sub-expressions in a helper, a grass geometry shader, two
// techniques. The chain's length is the size axis; the work per instruction must stay flat.
std::string grassEffect(int swayTerms) {
  std::string sway = "float3 sway(float3 p, float t)\n{\n    float s0 = sin(p.x * 0.37 + t) * g_Wind.z;\n";
  for (int i = 1; i <= swayTerms; ++i)
    sway += "    float s" + std::to_string(i) + " = s" + std::to_string(i - 1) + " * s" + std::to_string(i - 1) +
            " + s" + std::to_string(i - 1) + ";\n";
  sway += "    return p + float3(g_Wind.xy, 0) * frac(s" + std::to_string(swayTerms) + ");\n}\n";
  return R"(// grass.fx
cbuffer PerFrame : register(b0)
{
    float4x4 g_ViewProj;
    float4x4 g_LightViewProj;
    float4   g_Wind;
    float3   g_CameraPos;
    float    g_BladeHeight;
};
struct VS_IN { float3 Pos : POSITION; float4 World0 : INSTANCE0; float4 World1 : INSTANCE1; float4 World2 : INSTANCE2; };
struct PS_IN { float4 Pos : SV_Position; float Shade : TEXCOORD0; };
)" + sway + R"(
float3 placed(VS_IN input)
{
    return float3(dot(input.World0, float4(input.Pos, 1)), dot(input.World1, float4(input.Pos, 1)),
                  dot(input.World2, float4(input.Pos, 1)));
}
float4 VS_Shadow(VS_IN input) : SV_Position
{
    return mul(float4(sway(placed(input), g_Wind.w), 1), g_LightViewProj);
}
[maxvertexcount(3)]
void GS_Grass(point float4 root[1] : TEXCOORD0, inout TriangleStream<PS_IN> stream)
{
    PS_IN v;
    v.Shade = 1.0;
    v.Pos = mul(float4(sway(root[0].xyz, g_Wind.w), 1), g_ViewProj);
    stream.Append(v);
    v.Pos = mul(root[0] + float4(0, g_BladeHeight, 0, 0), g_ViewProj);
    stream.Append(v);
    stream.Append(v);
}
technique10 Shadow { pass P0 { SetVertexShader(CompileShader(vs_4_0, VS_Shadow())); SetPixelShader(NULL); } }
technique10 Grass { pass P0 { SetGeometryShader(CompileShader(gs_4_0, GS_Grass())); } }
)";
}

TEST(ValueNumbers, AnEffectFilesSharedSubExpressionsCostLinearWork) {
  for (auto [stage, entry] : {std::pair{Stage::Vertex, "VS_Shadow"}, std::pair{Stage::Geometry, "GS_Grass"}}) {
    for (int terms : {4, 16, 64}) {
      FrontEndOptions options;
      options.stage = stage;
      options.entryPoint = entry;
      Diagnostics diags;
      FrontEndResult parsed = compileToSpirv({"grass.fx", grassEffect(terms)}, options, diags);
      ASSERT_TRUE(parsed.ok) << diags.format();
      std::string error;
      auto module = spirv::Module::parse(parsed.spirv, &error);
      ASSERT_TRUE(module) << error;
      ValueNumbers numbers(*module);
      EXPECT_LT(numbers.visits(), numbers.visitBudget()) << entry << " " << terms;
      EXPECT_LE(numbers.visits(), 4 * instructionCount(*module)) << entry << " " << terms;
    }
  }
}

}  // namespace
}  // namespace stereoshift::analysis
