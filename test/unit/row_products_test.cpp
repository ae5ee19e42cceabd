// The decompiled-HLSL forms of deferred-unprojection (passes/deferred_unprojection/row_products.h) on
// pixel shaders written here in 3Dmigoto's decompiler conventions and compiled by the front end with
// source lines: the cbuffer-row product found with the line and lanes of each component, the
// per-component view ray with its depth's line; a texture transform that is not a rebuild from depth
// found as nothing; and the work both do (lanes decomposed, factors visited) linear in chains of
// shared sub-expressions (`r1.x = r1.x + r1.x` / `r1.y = r1.y * r1.y` repeated), counted, not timed:
// a sum of a value with itself doubles a naive linear form at every step.
#include "passes/analysis_manager.h"
#include "passes/deferred_unprojection/row_products.h"
#include "transpiler/frontend/front_end.h"

#include <gtest/gtest.h>

#include <array>
#include <string>

namespace stereoshift::test {
namespace {

const char* kName = "0123456789abcdef-ps_replace.txt";

std::string dump(const std::string& body) {
  return "cbuffer cb1 : register(b1)\n{\n  float4 cb1[30];\n}\n\ncbuffer cb0 : register(b0)\n{\n  float4 cb0[4];\n}\n\n"
         "SamplerState s0_s : register(s0);\nTexture2D<float4> t0 : register(t0);\n\n#define cmp -\n\n"
         "void main(\n  float4 v0 : SV_POSITION0,\n  float2 v1 : TEXCOORD0,\n  out float4 o0 : SV_Target0)\n{\n"
         "  float4 r0,r1,r2;\n" +
         body + "  return;\n}\n";
}

// Lines 1-21 are the prologue above: the body starts at line 22.
constexpr uint32_t kFirstBodyLine = 22;

const char* kMadChain =
    "  r0.xy = v0.xy * cb0[2].zw;\n"                      // 22
    "  r0.z = t0.Sample(s0_s, r0.xy).x;\n"                // 23
    "  r0.xy = r0.xy * float2(2,-2) + float2(-1,1);\n"    // 24
    "  r1.xyzw = cb1[21].xyzw * r0.yyyy;\n"               // 25
    "  r1.xyzw = r0.xxxx * cb1[20].xyzw + r1.xyzw;\n"     // 26
    "  r1.xyzw = r0.zzzz * cb1[22].xyzw + r1.xyzw;\n"     // 27
    "  r1.xyzw = cb1[23].xyzw + r1.xyzw;\n"               // 28
    "  o0.xyzw = r1.xyzw / r1.wwww;\n";                   // 29

struct Compiled {
  std::unique_ptr<spirv::Module> module;
  std::unique_ptr<AnalysisManager> analyses;
  const spirv::Module* registers = nullptr;
};

Compiled compile(const std::string& text) {
  FrontEndOptions options;
  options.sourceLines = true;
  Diagnostics diags;
  FrontEndResult front = compileToSpirv(SourceFile{kName, text}, options, diags);
  EXPECT_TRUE(front.ok) << diags.format();
  Compiled c;
  std::string error;
  auto parsed = spirv::Module::parse(front.spirv, &error);
  EXPECT_TRUE(parsed) << error;
  if (!parsed) return c;
  c.module = std::make_unique<spirv::Module>(std::move(*parsed));
  c.analyses = std::make_unique<AnalysisManager>(*c.module, front.info, kName);
  c.registers = c.analyses->registerSsaCopy();
  EXPECT_NE(c.registers, nullptr);
  return c;
}

TEST(RowProducts, FindsTheMadChainWithTheLineOfEachComponent) {
  Compiled c = compile(dump(kMadChain));
  ASSERT_TRUE(c.registers);
  EXPECT_TRUE(deferred::hasCbufferRows(*c.module));
  auto forms = deferred::findDecompiledForms(*c.registers, true, kName);
  const auto& found = forms.products;
  ASSERT_EQ(found.size(), 1u);
  const auto& fix = found[0].fix;
  EXPECT_TRUE(found[0].reason.empty()) << found[0].reason;
  EXPECT_EQ(fix.afterLine, kFirstBodyLine + 6);
  for (uint32_t i = 0; i < 4; ++i) {
    EXPECT_EQ(fix.lines[i], kFirstBodyLine + 6) << i;
    EXPECT_EQ(fix.lanes[i], i);
    EXPECT_EQ(fix.column[i], std::string("cb1[20].") + "xyzw"[i]);
  }
  EXPECT_EQ(found[0].rows, "cb1[20], cb1[21], cb1[22], cb1[23]");
  EXPECT_TRUE(forms.rays.empty());
}

// The unchanged case: the same chain over an interpolated texture coordinate and no depth is a
// texture transform.
TEST(RowProducts, ATransformOfInterpolatedValuesIsNoRebuild) {
  std::string body = kMadChain;
  body.replace(body.find("t0.Sample(s0_s, r0.xy).x"), std::string("t0.Sample(s0_s, r0.xy).x").size(), "v1.y");
  Compiled c = compile(dump(body));
  ASSERT_TRUE(c.registers);
  EXPECT_TRUE(deferred::findDecompiledForms(*c.registers, true, kName).products.empty());
}

TEST(RowProducts, FindsThePerComponentViewRayWithItsDepthLine) {
  const char* body =
      "  r0.x = t0.Sample(s0_s, v1.xy).x;\n"                // 22
      "  r0.z = 1 / r0.x;\n"                                // 23
      "  r0.xy = v1.xy * float2(2,-2) + float2(-1,1);\n"    // 24
      "  r0.xy = r0.xy * r0.zz;\n"                          // 25
      "  r1.x = r0.x / cb1[6].x;\n"                         // 26
      "  r1.y = r0.y / cb1[6].y;\n"                         // 27
      "  o0.xyzw = r1.xyxy;\n";                             // 28
  Compiled c = compile(dump(body));
  ASSERT_TRUE(c.registers);
  auto rays = deferred::findDecompiledForms(*c.registers, true, kName).rays;
  ASSERT_EQ(rays.size(), 1u);
  EXPECT_EQ(rays[0].fix.line, kFirstBodyLine + 4);
  EXPECT_EQ(rays[0].fix.depthLine, kFirstBodyLine + 1);
  EXPECT_EQ(rays[0].fix.scale, "(1 / cb1[6].x)");
  // Without its y (the pixel's y times the same depth), the x is not taken.
  std::string noY = body;
  noY.replace(noY.find("r1.y = r0.y / cb1[6].y;"), std::string("r1.y = r0.y / cb1[6].y;").size(), "r1.y = v1.y;");
  Compiled d = compile(dump(noY));
  ASSERT_TRUE(d.registers);
  EXPECT_TRUE(deferred::findDecompiledForms(*d.registers, true, kName).rays.empty());
}

// SSAO's sample as a decompiler writes it: the mad chain's point, divided by its w, moved by a kernel
// offset, projected back through cb1[0..3] and read at in the depth texture again (lines 29-36).
std::string withASampleProjectedBack(const std::string& texture) {
  std::string body = kMadChain;
  body.replace(body.find("  o0.xyzw = r1.xyzw / r1.wwww;\n"), std::string("  o0.xyzw = r1.xyzw / r1.wwww;\n").size(),
               "  r1.xyz = r1.xyz / r1.www;\n"                            // 29
               "  r1.xyz = cb1[25].xyz * cb1[24].www + r1.xyz;\n"         // 30
               "  r2.xyzw = cb1[1].xyzw * r1.yyyy;\n"                     // 31
               "  r2.xyzw = r1.xxxx * cb1[0].xyzw + r2.xyzw;\n"           // 32
               "  r2.xyzw = r1.zzzz * cb1[2].xyzw + r2.xyzw;\n"           // 33
               "  r2.xyzw = cb1[3].xyzw + r2.xyzw;\n"                     // 34
               "  r2.xy = r2.xy / r2.ww;\n"                               // 35
               "  r2.xy = r2.xy * float2(0.5,-0.5) + float2(0.5,0.5);\n"  // 36
               "  r2.z = " + texture + ".Sample(s0_s, r2.xy).x;\n"
               "  o0.xyzw = r2.zzzz - r1.zzzz;\n");
  return body;
}

// The changed case: the point projected back through a matrix is read at in the depth texture again,
// so its clip x is this eye's: found with the lines of clip x and w, VP's row of x and the rebuild's
// column of NDC x.
TEST(RowProducts, FindsTheReprojectionReadAtInTheDepthTexture) {
  Compiled c = compile(dump(withASampleProjectedBack("t0")));
  ASSERT_TRUE(c.registers);
  auto forms = deferred::findDecompiledForms(*c.registers, true, kName);
  ASSERT_EQ(forms.products.size(), 1u);
  ASSERT_EQ(forms.reprojections.size(), 1u);
  const auto& r = forms.reprojections[0];
  EXPECT_TRUE(r.reason.empty()) << r.reason;
  EXPECT_EQ(r.texture, "t0");
  EXPECT_EQ(r.rows, "cb1[0], cb1[1], cb1[2], cb1[3]");
  EXPECT_EQ(r.fix.lines[0], kFirstBodyLine + 12);
  EXPECT_EQ(r.fix.lines[1], kFirstBodyLine + 12);
  EXPECT_EQ(r.fix.lanes[0], 0u);
  EXPECT_EQ(r.fix.lanes[1], 3u);
  EXPECT_EQ(r.fix.afterLine, kFirstBodyLine + 12);
  EXPECT_EQ(r.fix.rowX, (std::array<std::string, 3>{"cb1[0].x", "cb1[1].x", "cb1[2].x"}));
  EXPECT_EQ(r.fix.column, (std::array<std::string, 3>{"cb1[20].x", "cb1[20].y", "cb1[20].z"}));
}

// The unchanged cases: the same transform read at in another texture (a shadow map, drawn once for
// both eyes) is no re-projection into this eye's image; nor is one of a point not computed from the
// rebuild (an interpolated one), read at in the depth texture.
TEST(RowProducts, ATransformReadAtInAnotherTextureIsNoReprojection) {
  std::string text = dump(withASampleProjectedBack("t1"));
  const std::string t0 = "Texture2D<float4> t0 : register(t0);\n";
  text.replace(text.find(t0), t0.size(), "Texture2D<float4> t0 : register(t0); Texture2D<float4> t1 : register(t1);\n");
  Compiled c = compile(text);
  ASSERT_TRUE(c.registers);
  auto forms = deferred::findDecompiledForms(*c.registers, true, kName);
  EXPECT_EQ(forms.products.size(), 1u);
  EXPECT_TRUE(forms.reprojections.empty());

  std::string interpolated = withASampleProjectedBack("t0");
  const std::string offset = "  r1.xyz = cb1[25].xyz * cb1[24].www + r1.xyz;\n";
  interpolated.replace(interpolated.find(offset), offset.size(), "  r1.xyz = float3(v1.xy, v0.w);\n");
  Compiled d = compile(dump(interpolated));
  ASSERT_TRUE(d.registers);
  EXPECT_TRUE(deferred::findDecompiledForms(*d.registers, true, kName).reprojections.empty());
}

// Work of both finders for a shader with `steps` statements of shared sub-expression chains.
size_t workFor(int steps) {
  std::string body = kMadChain;
  body += "  r2.x = r1.x;\n  r2.y = r1.y;\n";
  for (int k = 0; k < steps; ++k) body += "  r2.x = r2.x + r2.x;\n  r2.y = r2.y * r2.y;\n";
  body += "  o0.xy = r2.xy;\n";
  Compiled c = compile(dump(body));
  if (!c.registers) return 0;
  auto forms = deferred::findDecompiledForms(*c.registers, true, kName);
  EXPECT_EQ(forms.products.size(), 1u);
  return forms.work;
}

TEST(RowProducts, WorkIsLinearInChainsOfSharedSubExpressions) {
  size_t small = workFor(4), large = workFor(16);
  ASSERT_GT(small, 0u);
  // Four times the chain: at most about four times the work (the shader's other statements are
  // the same), where a form that doubled its parts per step, or a product tree walked once per
  // path, would be 2^12 times it.
  EXPECT_LE(large, small * 4) << "work " << small << " at 4 steps, " << large << " at 16";
}

}  // namespace
}  // namespace stereoshift::test
