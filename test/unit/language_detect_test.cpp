// Language detection (transpiler/frontend/language_detect): HLSL in files named by stage only is
// found by its content; GLSL with or without #version (ESSL 100, desktop 110) stays GLSL; -x and a
// language extension win over the content.
#include "transpiler/frontend/language_detect.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace stereoshift;

namespace {

SourceLanguage detected(const std::string& text, const std::string& path = "shaders/x.vert") {
  return decideLanguage(path, text, std::nullopt).language;
}

bool hasSign(const std::vector<std::string>& signs, const std::string& sign) {
  return std::find(signs.begin(), signs.end(), sign) != signs.end();
}

// ---- HLSL the way Vulkan sample collections keep it: stage-named files, vk attributes ----------

const char* kVulkanHlslVertex = R"(// Textured mesh, Vulkan HLSL.
struct VSInput
{
[[vk::location(0)]] float3 Pos : POSITION0;
[[vk::location(1)]] float2 UV : TEXCOORD0;
};

struct UBO
{
  float4x4 projection;
  float4x4 model;
};
cbuffer ubo : register(b0) { UBO ubo; }

struct VSOutput
{
  float4 Pos : SV_POSITION;
[[vk::location(0)]] float2 UV : TEXCOORD0;
};

VSOutput main(VSInput input)
{
  VSOutput output = (VSOutput)0;
  output.UV = input.UV;
  output.Pos = mul(ubo.projection, mul(ubo.model, float4(input.Pos.xyz, 1.0)));
  return output;
}
)";

TEST(LanguageDetect, VulkanHlslVertexIsHlsl) {
  LanguageDecision d = decideLanguage("shaders/hlsl/texture/texture.vert", kVulkanHlslVertex, std::nullopt);
  EXPECT_EQ(d.language, SourceLanguage::Hlsl);
  EXPECT_EQ(d.source, LanguageSource::Content);
  EXPECT_NE(d.reason.find("HLSL constructs"), std::string::npos) << d.reason;
  LanguageEvidence e = scoreLanguage(kVulkanHlslVertex);
  EXPECT_FALSE(e.hasVersion);
  EXPECT_TRUE(hasSign(e.hlslSigns, "[[vk::location]]"));
  EXPECT_TRUE(hasSign(e.hlslSigns, "cbuffer"));
  EXPECT_TRUE(hasSign(e.hlslSigns, ": register("));
  EXPECT_TRUE(hasSign(e.hlslSigns, ": SV_POSITION"));
  EXPECT_TRUE(hasSign(e.hlslSigns, ": TEXCOORD0"));
  EXPECT_TRUE(hasSign(e.hlslSigns, "float4x4"));
  EXPECT_EQ(e.glslScore, 0);
}

TEST(LanguageDetect, HlslPixelShaderWithBindingsIsHlsl) {
  const char* text = R"(
Texture2D textureColor : register(t1);
SamplerState samplerColor : register(s1);

float4 main([[vk::location(0)]] float2 inUV : TEXCOORD0) : SV_TARGET
{
  return textureColor.Sample(samplerColor, inUV);
}
)";
  EXPECT_EQ(detected(text, "hlsl/texture.frag"), SourceLanguage::Hlsl);
  LanguageEvidence e = scoreLanguage(text);
  EXPECT_TRUE(hasSign(e.hlslSigns, "Texture2D"));
  EXPECT_TRUE(hasSign(e.hlslSigns, "SamplerState"));
  EXPECT_TRUE(hasSign(e.hlslSigns, ".Sample("));
  EXPECT_TRUE(hasSign(e.hlslSigns, ": SV_TARGET"));
}

TEST(LanguageDetect, MinimalHlslWithOnlySemanticsIsHlsl) {
  // No cbuffer, no attribute: the semantics alone say it.
  EXPECT_EQ(detected("float4 main(float3 p : POSITION) : SV_Position { return float4(p, 1); }"),
            SourceLanguage::Hlsl);
}

TEST(LanguageDetect, HlslGeometryAndComputeAttributesCount) {
  const char* geometry = R"(
struct GSOutput { float4 Pos : SV_POSITION; };
[maxvertexcount(3)]
void main(triangle float4 input[3] : SV_POSITION, inout TriangleStream<GSOutput> outStream)
{
  for (int i = 0; i < 3; i++) { GSOutput o; o.Pos = input[i]; outStream.Append(o); }
  outStream.RestartStrip();
}
)";
  LanguageEvidence g = scoreLanguage(geometry);
  EXPECT_TRUE(hasSign(g.hlslSigns, "[maxvertexcount]"));
  EXPECT_TRUE(hasSign(g.hlslSigns, "TriangleStream"));
  EXPECT_TRUE(hasSign(g.hlslSigns, ".Append("));
  EXPECT_EQ(detected(geometry, "x.geom"), SourceLanguage::Hlsl);

  const char* compute = R"(
RWTexture2D<float4> resultImage : register(u0);
[numthreads(16, 16, 1)]
void main(uint3 id : SV_DispatchThreadID) { resultImage[id.xy] = float4(0, 0, 0, 1); }
)";
  EXPECT_EQ(detected(compute, "x.comp"), SourceLanguage::Hlsl);
  EXPECT_TRUE(hasSign(scoreLanguage(compute).hlslSigns, "[numthreads]"));
}

// ---- GLSL without #version must stay GLSL ---------------------------------------------------------

TEST(LanguageDetect, Essl100WithoutVersionIsGlsl) {
  const char* vertex = R"(
attribute vec3 aVertexPosition;
attribute vec2 aTextureCoord;
uniform mat4 uMVMatrix;
uniform mat4 uPMatrix;
varying highp vec2 vTextureCoord;
void main(void) {
  gl_Position = uPMatrix * uMVMatrix * vec4(aVertexPosition, 1.0);
  vTextureCoord = aTextureCoord;
}
)";
  const char* fragment = R"(
precision mediump float;
varying vec2 vTextureCoord;
uniform sampler2D uSampler;
void main(void) {
  gl_FragColor = texture2D(uSampler, vec2(vTextureCoord.s, vTextureCoord.t));
}
)";
  EXPECT_EQ(detected(vertex, "webgl/lesson.vert"), SourceLanguage::Glsl);
  EXPECT_EQ(detected(fragment, "webgl/lesson.frag"), SourceLanguage::Glsl);
  EXPECT_EQ(scoreLanguage(vertex).hlslScore, 0);
  EXPECT_EQ(scoreLanguage(fragment).hlslScore, 0);
  EXPECT_TRUE(hasSign(scoreLanguage(fragment).glslSigns, "precision"));
}

TEST(LanguageDetect, Desktop110WithoutVersionIsGlsl) {
  const char* text = R"(
// Per-vertex lighting, fixed-function style.
varying vec4 diffuse;
void main()
{
  vec3 normal = normalize(gl_NormalMatrix * gl_Normal);
  vec3 lightDir = normalize(vec3(gl_LightSource[0].position));
  float NdotL = max(dot(normal, lightDir), 0.0);
  diffuse = gl_FrontMaterial.diffuse * gl_LightSource[0].diffuse * NdotL;
  gl_TexCoord[0] = gl_MultiTexCoord0;
  gl_Position = ftransform();
}
)";
  EXPECT_EQ(detected(text), SourceLanguage::Glsl);
  EXPECT_EQ(scoreLanguage(text).hlslScore, 0);
}

TEST(LanguageDetect, GlslHelpersNamedLikeHlslIntrinsicsStayGlsl) {
  // WebGL shaders often define saturate()/lerp() themselves, use `a ? b : C` and switch labels.
  const char* text = R"(
precision highp float;
#define LIGHT_COUNT 4
#define float4 vec4
float saturate(float x) { return clamp(x, 0.0, 1.0); }
vec3 lerp(vec3 a, vec3 b, float t) { return mix(a, b, t); }
uniform int mode;
varying vec2 uv;
void main() {
  float k = uv.x > 0.5 ? saturate(uv.y) : LIGHT_COUNT;
  float4 c = float4(lerp(vec3(0.0), vec3(1.0), k), 1.0);
  gl_FragColor = c;
}
)";
  LanguageEvidence e = scoreLanguage(text);
  EXPECT_EQ(e.hlslScore, 0) << "signs counted: " << (e.hlslSigns.empty() ? "" : e.hlslSigns[0]);
  EXPECT_EQ(detected(text, "x.frag"), SourceLanguage::Glsl);
}

TEST(LanguageDetect, SwitchLabelsAndTernariesAreNotSemantics) {
  const char* text = R"(
uniform int mode;
void main() {
  vec4 c;
  switch (mode) {
    case MODE_A: c = vec4(1.0); break;
    default: c = vec4(0.0);
  }
  c.x = mode == 1 ? POSITION : TEXCOORD;
  gl_FragColor = c;
}
)";
  EXPECT_EQ(scoreLanguage(text).hlslScore, 0);
}

TEST(LanguageDetect, CommentsAndStringsAreNoEvidence) {
  const char* text = R"(
// HLSL original: cbuffer Frame : register(b0) { float4x4 ViewProj; };
/* float4 main(float3 p : POSITION) : SV_Position
   { return mul(ViewProj, float4(p, 1)); } */
uniform mat4 uViewProj;
attribute vec3 aPos;
void main() { gl_Position = uViewProj * vec4(aPos, 1.0); }
)";
  EXPECT_EQ(scoreLanguage(text).hlslScore, 0);
  EXPECT_EQ(detected(text), SourceLanguage::Glsl);
}

TEST(LanguageDetect, VersionDirectiveAlwaysMeansGlsl) {
  // Even with HLSL-looking names in it, a #version file is GLSL.
  const char* text = "#version 450\n#define float4 vec4\nlayout(location = 0) out float4 color;\n"
                     "void main() { color = float4(1.0); }\n";
  LanguageDecision d = decideLanguage("x.frag", text, std::nullopt);
  EXPECT_EQ(d.language, SourceLanguage::Glsl);
  EXPECT_EQ(d.source, LanguageSource::Content);
  EXPECT_EQ(d.reason, "#version directive");
}

// Read through the lexer: a byte order mark before `#version` does not hide it (the old tokenizer
// took the mark for code, and the `#` after it for no directive).
TEST(LanguageDetect, VersionAfterAByteOrderMark) {
  LanguageDecision d = decideLanguage("x.frag", "\xEF\xBB\xBF#version 450\nvoid main() {}\n", std::nullopt);
  EXPECT_EQ(d.language, SourceLanguage::Glsl);
  EXPECT_EQ(d.reason, "#version directive");
}

TEST(LanguageDetect, DefineNamesAMacroNotEvidence) {
  // `#define float4 vec4`: float4 is the file's own macro; the `::` of a vk attribute is one token.
  LanguageEvidence e = scoreLanguage("#define float4 vec4\nfloat4 c;\n[[vk::binding(0)]] cbuffer B { float x; };\n");
  EXPECT_FALSE(hasSign(e.hlslSigns, "float4"));
  EXPECT_TRUE(hasSign(e.hlslSigns, "[[vk::binding]]"));
  EXPECT_TRUE(hasSign(e.hlslSigns, "cbuffer"));
}

TEST(LanguageDetect, OneWeakHintIsNotEnough) {
  // A lone intrinsic name (here a call into a function defined elsewhere) stays below the threshold.
  EXPECT_EQ(detected("void main() { gl_FragColor = lerp(a, b, t); }"), SourceLanguage::Glsl);
  EXPECT_EQ(detected("void main() { x = lerp(a, b, t); }"), SourceLanguage::Glsl);
}

TEST(LanguageDetect, EmptyTextIsGlslByDefault) {
  LanguageDecision d = decideLanguage("x.vert", "", std::nullopt);
  EXPECT_EQ(d.language, SourceLanguage::Glsl);
  EXPECT_NE(d.reason.find("GLSL by default"), std::string::npos) << d.reason;
}

// ---- flag and file name -----------------------------------------------------------------------------

TEST(LanguageDetect, FlagOverridesNameAndContent) {
  LanguageDecision d = decideLanguage("x.vert.hlsl", kVulkanHlslVertex, SourceLanguage::Glsl);
  EXPECT_EQ(d.language, SourceLanguage::Glsl);
  EXPECT_EQ(d.source, LanguageSource::Flag);
  d = decideLanguage("x.vert", "#version 450\nvoid main() {}\n", SourceLanguage::Hlsl);
  EXPECT_EQ(d.language, SourceLanguage::Hlsl);
  EXPECT_EQ(d.source, LanguageSource::Flag);
  EXPECT_EQ(d.reason, "-x hlsl");
}

TEST(LanguageDetect, LanguageExtensionOverridesContent) {
  EXPECT_EQ(languageFromFileName("a/b.vert.hlsl"), SourceLanguage::Hlsl);
  EXPECT_EQ(languageFromFileName("a/B.PS.HLSL"), SourceLanguage::Hlsl);
  EXPECT_EQ(languageFromFileName("effects/water.fx"), SourceLanguage::Hlsl);
  EXPECT_EQ(languageFromFileName("common.hlsli"), SourceLanguage::Hlsl);
  EXPECT_EQ(languageFromFileName("lit.frag.glsl"), SourceLanguage::Glsl);
  EXPECT_EQ(languageFromFileName("hlsl/lit.frag"), std::nullopt);  // a directory name says nothing
  LanguageDecision d = decideLanguage("x.frag.glsl", kVulkanHlslVertex, std::nullopt);
  EXPECT_EQ(d.language, SourceLanguage::Glsl);
  EXPECT_EQ(d.source, LanguageSource::Extension);
  EXPECT_EQ(d.reason, "file extension .glsl");
}

TEST(LanguageDetect, SourceNames) {
  EXPECT_STREQ(languageSourceName(LanguageSource::Extension), "extension");
  EXPECT_STREQ(languageSourceName(LanguageSource::Flag), "flag");
  EXPECT_STREQ(languageSourceName(LanguageSource::Content), "content");
}

}  // namespace
