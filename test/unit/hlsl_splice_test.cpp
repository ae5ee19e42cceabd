// HLSL source splice (geometry and domain shaders): structure of the output, error locations, and
// every spliced output compiled by glslangValidator to prove it is valid HLSL.
//
// Compile definitions: GLSLANG_VALIDATOR (path of glslangValidator; compile checks are skipped
// without it) and CORPUS_DIR (the repository's corpus/ folder; corpus tests skipped without it).
#include "transpiler/backend/hlsl_splice.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#endif

using stereoshift::HlslSpliceOptions;
using stereoshift::HlslSpliceResult;
using stereoshift::spliceHlslStereo;

namespace {

int countOf(const std::string& haystack, const std::string& needle) {
  int n = 0;
  for (size_t p = haystack.find(needle); p != std::string::npos; p = haystack.find(needle, p + needle.size())) ++n;
  return n;
}

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

HlslSpliceOptions geomOptions(const std::string& entry = "GSMain") {
  HlslSpliceOptions o;
  o.entryPoint = entry;
  o.geometry = true;
  o.cbufferRegister = 5;
  return o;
}

HlslSpliceOptions domainOptions(const std::string& entry = "DSMain") {
  HlslSpliceOptions o = geomOptions(entry);
  o.geometry = false;
  return o;
}

struct CompileResult {
  bool ran = false;  // false: no validator configured
  bool ok = false;
  std::string log;
};

// Compiles `hlsl` with glslangValidator (-D: HLSL, -V: SPIR-V) for `stage` ("geom", "tese").
CompileResult compileHlsl(const std::string& hlsl, const std::string& stage, const std::string& entry,
                          const std::string& extraArgs = "") {
  CompileResult r;
#ifdef GLSLANG_VALIDATOR
  static std::atomic<int> counter{0};
  std::string validator = GLSLANG_VALIDATOR;
  if (!std::filesystem::exists(validator)) {
    r.ran = true;
    r.log = "glslangValidator not found at " + validator;
    return r;
  }
  long pid = 0;
#if defined(__unix__) || defined(__APPLE__)
  pid = static_cast<long>(::getpid());
#endif
  auto dir = std::filesystem::temp_directory_path();
  std::string stem = "stereoshift_hlsl_splice_" + std::to_string(pid) + "_" + std::to_string(counter++);
  auto file = dir / (stem + ".hlsl");
  auto log = dir / (stem + ".log");
  {
    std::ofstream out(file, std::ios::binary);
    out << hlsl;
  }
  std::string cmd = "\"" + validator + "\" -D -V -S " + stage + " -e " + entry + " " + extraArgs + " -o " +
#ifdef _WIN32
                    "NUL"
#else
                    "/dev/null"
#endif
                    + " \"" + file.string() + "\" > \"" + log.string() + "\" 2>&1";
  int rc = std::system(cmd.c_str());
  r.ran = true;
  r.ok = rc == 0;
  r.log = readFile(log) + "\n--- source ---\n" + hlsl;
  std::error_code ec;
  std::filesystem::remove(file, ec);
  std::filesystem::remove(log, ec);
#else
  (void)hlsl, (void)stage, (void)entry, (void)extraArgs;
#endif
  return r;
}

#define EXPECT_COMPILES(hlsl, stage, entry, ...)                                   \
  do {                                                                             \
    CompileResult cr_ = compileHlsl((hlsl), (stage), (entry) __VA_OPT__(, ) __VA_ARGS__); \
    if (cr_.ran) {                                                                 \
      EXPECT_TRUE(cr_.ok) << "glslangValidator rejected:\n" << cr_.log;             \
    }                                                                              \
  } while (0)

// Three Append calls: one in a helper that takes the stream under another name, two in the entry.
const char* kGeometry = R"(// test geometry shader
cbuffer Camera : register(b0)
{
    float4x4 ViewProj;
};

struct VSOut
{
    float4 pos : SV_Position;
    float3 world : TEXCOORD0;
};

struct GSOut
{
    float2 uv : TEXCOORD0;
    float4 clip : SV_POSITION;
};

// Emits one vertex; comment mentions os.Append(v) { and must stay untouched.
void EmitVertex(inout TriangleStream<GSOut> os, float3 world, float2 uv)
{
    GSOut v;
    v.uv = uv; /* } os.Append(v); */
    v.clip = mul(ViewProj, float4(world, 1.0));
    os.Append(v);
}

[maxvertexcount(4)]
void GSMain(triangle VSOut input[3], inout TriangleStream<GSOut> stream)
{
    GSOut o;
    o.uv = float2(0, 0);
    o.clip = input[0].pos;
    stream.Append(o);
    o.clip = input[1].pos;
    stream.Append((GSOut)o);
    EmitVertex(stream, input[2].world, float2(1, 1));
    stream.RestartStrip();
}
)";

const char* kDomain = R"(cbuffer Camera : register(b0)
{
    float4x4 ViewProj;
};

struct HSControlPoint
{
    float3 pos : POSITION;
};

struct PatchTess
{
    float edges[3] : SV_TessFactor;
    float inside : SV_InsideTessFactor;
};

struct DSOut
{
    precise float4 position : SV_Position;
    float3 color : COLOR0;
};

[domain("tri")]
DSOut DSMain(PatchTess tess, float3 bary : SV_DomainLocation, const OutputPatch<HSControlPoint, 3> patch)
{
    DSOut o;
    float3 p = patch[0].pos * bary.x + patch[1].pos * bary.y + patch[2].pos * bary.z;
    o.position = mul(ViewProj, float4(p, 1.0));
    o.color = bary;
    return o;
}
)";

// ------------------------------------------------------------------------------------------------

TEST(HlslSplice, GeometryWrapsEveryAppendIncludingHelperFunctions) {
  HlslSpliceResult r = spliceHlslStereo(kGeometry, geomOptions());
  ASSERT_TRUE(r.ok) << r.line << ":" << r.column << ": " << r.error;
  EXPECT_EQ(r.sites, 3);
  EXPECT_NE(r.text.find("GSOut stereoshift_shift_GSOut(GSOut "), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("os.Append(stereoshift_shift_GSOut(v));"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("stream.Append(stereoshift_shift_GSOut(o));"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("stream.Append(stereoshift_shift_GSOut((GSOut)o));"), std::string::npos) << r.text;
  EXPECT_EQ(countOf(r.text, ".Append(stereoshift_shift_GSOut("), 3);
  // Comments are left alone.
  EXPECT_NE(r.text.find("comment mentions os.Append(v) {"), std::string::npos);
  EXPECT_NE(r.text.find("/* } os.Append(v); */"), std::string::npos);
  // The cbuffer and the helper: once, after struct GSOut, before the first function that appends,
  // and above the comment attached to that function.
  EXPECT_EQ(countOf(r.text, "cbuffer StereoParams : register(b5)"), 1);
  size_t cb = r.text.find("cbuffer StereoParams");
  EXPECT_LT(r.text.find("struct GSOut"), cb);
  EXPECT_LT(cb, r.text.find("// Emits one vertex"));
  EXPECT_LT(r.text.find("stereoshift_shift_GSOut(GSOut "), r.text.find("void EmitVertex"));
  // The shift uses the SV_POSITION member (case-insensitive semantic) and the exact formula.
  EXPECT_NE(r.text.find("if (eyeSign != 0.0f && abs(stereoshift_v.clip.w - 1.0f) > 9.99999975e-06f && !isinf(stereoshift_v.clip.w))"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("precise float stereoshift_x = stereoshift_v.clip.x + (eyeSign * separation) * "
                        "(stereoshift_v.clip.w - convergence);"),
            std::string::npos)
      << r.text;
  EXPECT_COMPILES(r.text, "geom", "GSMain");
}

TEST(HlslSplice, GeometryPreservesEverythingElseByteForByte) {
  HlslSpliceResult r = spliceHlslStereo(kGeometry, geomOptions());
  ASSERT_TRUE(r.ok) << r.error;
  std::string undone = r.text;
  size_t b = undone.find("// ---- stereoshift:");
  size_t e = undone.find("// ---- end stereoshift ----\n");
  ASSERT_NE(b, std::string::npos);
  ASSERT_NE(e, std::string::npos);
  undone.erase(b, e + std::string("// ---- end stereoshift ----\n\n").size() - b);
  for (const char* arg : {"v", "o", "(GSOut)o"}) {
    std::string wrapped = std::string("stereoshift_shift_GSOut(") + arg + ")";
    for (size_t p; (p = undone.find(wrapped)) != std::string::npos;) undone.replace(p, wrapped.size(), arg);
  }
  EXPECT_EQ(undone, kGeometry);
}

TEST(HlslSplice, CrlfLineEndingsArePreserved) {
  std::string crlf;
  for (char c : std::string(kGeometry)) {
    if (c == '\n') crlf += '\r';
    crlf += c;
  }
  HlslSpliceResult r = spliceHlslStereo(crlf, geomOptions());
  ASSERT_TRUE(r.ok) << r.error;
  for (size_t i = 0; i < r.text.size(); ++i) {
    if (r.text[i] == '\n') {
      ASSERT_TRUE(i > 0 && r.text[i - 1] == '\r') << "bare LF at offset " << i;
    }
  }
  EXPECT_EQ(r.sites, 3);
  EXPECT_COMPILES(r.text, "geom", "GSMain");
}

TEST(HlslSplice, DomainWrapperCarriesTheAttributesAndShiftsTheResult) {
  HlslSpliceResult r = spliceHlslStereo(kDomain, domainOptions());
  ASSERT_TRUE(r.ok) << r.line << ":" << r.column << ": " << r.error;
  EXPECT_EQ(r.sites, 1);
  // The mono function keeps its body under the new name; its attribute is commented out.
  EXPECT_NE(r.text.find("/* stereoshift: moved to the wrapper: [domain(\"tri\")] */\nDSOut DSMain_stereoshift_mono(PatchTess tess, float3 bary : "
                        "SV_DomainLocation, const OutputPatch<HSControlPoint, 3> patch)\n{\n    DSOut o;"),
            std::string::npos)
      << r.text;
  // The wrapper: same attribute, return type, verbatim parameter list; after the mono body.
  std::string wrapper =
      "[domain(\"tri\")]\nDSOut DSMain(PatchTess tess, float3 bary : SV_DomainLocation, const "
      "OutputPatch<HSControlPoint, 3> patch)\n{\n    return stereoshift_shift_DSOut(DSMain_stereoshift_mono(tess, "
      "bary, patch));\n}\n";
  size_t w = r.text.find(wrapper);
  ASSERT_NE(w, std::string::npos) << r.text;
  EXPECT_LT(r.text.find("return o;\n}"), w);
  EXPECT_EQ(countOf(r.text, "[domain(\"tri\")]"), 2);  // the wrapper's and the comment's
  EXPECT_EQ(countOf(r.text, "/* stereoshift: moved to the wrapper: [domain(\"tri\")] */"), 1);
  EXPECT_NE(r.text.find("stereoshift_v.position.x + (eyeSign * separation) * (stereoshift_v.position.w - "
                        "convergence)"),
            std::string::npos);
  EXPECT_COMPILES(r.text, "tese", "DSMain");
}

TEST(HlslSplice, DomainReturningFloat4WithSvPosition) {
  const char* src = R"(struct CP { float3 p : POSITION; };
struct PC { float e[4] : SV_TessFactor; float i[2] : SV_InsideTessFactor; };
[domain("quad")]
float4 main(PC pc, float2 uv : SV_DomainLocation, const OutputPatch<CP, 4> q) : SV_Position
{
    return float4(lerp(lerp(q[0].p, q[1].p, uv.x), lerp(q[2].p, q[3].p, uv.x), uv.y), 2.0);
})";  // no newline at the end of the file
  HlslSpliceResult r = spliceHlslStereo(src, domainOptions("main"));
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.sites, 1);
  EXPECT_NE(r.text.find("float4 stereoshift_shift_position(float4 stereoshift_v)"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("float4 main(PC pc, float2 uv : SV_DomainLocation, const OutputPatch<CP, 4> q) : "
                        "SV_Position\n{\n    return stereoshift_shift_position(main_stereoshift_mono(pc, uv, q));"),
            std::string::npos)
      << r.text;
  EXPECT_NE(r.text.find("float4 main_stereoshift_mono(PC pc"), std::string::npos);
  EXPECT_COMPILES(r.text, "tese", "main");
}

TEST(HlslSplice, DomainWithOutParameter) {
  const char* src = R"(struct CP { float3 p : POSITION; };
struct PC { float e[3] : SV_TessFactor; float i : SV_InsideTessFactor; };
struct DSOut { float4 pos : SV_Position; float2 uv : TEXCOORD0; };
[domain("tri")]
void DSMain(PC pc, float3 b : SV_DomainLocation, const OutputPatch<CP, 3> patch, out DSOut o)
{
    o.pos = float4(patch[0].p * b.x + patch[1].p * b.y + patch[2].p * b.z, 3.0);
    o.uv = b.xy;
}
)";
  HlslSpliceResult r = spliceHlslStereo(src, domainOptions());
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.sites, 1);
  EXPECT_NE(r.text.find("    DSMain_stereoshift_mono(pc, b, patch, o);\n    o = stereoshift_shift_DSOut(o);\n}"),
            std::string::npos)
      << r.text;
  EXPECT_COMPILES(r.text, "tese", "DSMain");
}

TEST(HlslSplice, CutoffModesAndPrecision) {
  HlslSpliceOptions o = geomOptions();
  o.cutoff = HlslSpliceOptions::Cutoff::Exact;
  HlslSpliceResult exact = spliceHlslStereo(kGeometry, o);
  ASSERT_TRUE(exact.ok) << exact.error;
  EXPECT_NE(exact.text.find("if (eyeSign != 0.0f && stereoshift_v.clip.w != 1.0f && !isinf(stereoshift_v.clip.w))"), std::string::npos) << exact.text;
  EXPECT_EQ(exact.text.find("abs("), std::string::npos);
  EXPECT_COMPILES(exact.text, "geom", "GSMain");

  o.cutoff = HlslSpliceOptions::Cutoff::None;
  o.precise = false;
  HlslSpliceResult none = spliceHlslStereo(kGeometry, o);
  ASSERT_TRUE(none.ok) << none.error;
  EXPECT_EQ(none.text.find("stereoshift_v.clip.w != 1.0f"), std::string::npos);
  EXPECT_EQ(none.text.find("if (abs("), std::string::npos);
  EXPECT_EQ(none.text.find("precise float"), std::string::npos);
  EXPECT_NE(none.text.find("    if (eyeSign != 0.0f)\n    {\n        stereoshift_v.clip.x = stereoshift_v.clip.x + "
                           "(eyeSign * separation) * (stereoshift_v.clip.w - convergence);\n    }\n    return stereoshift_v;"),
            std::string::npos)
      << none.text;
  EXPECT_COMPILES(none.text, "geom", "GSMain");

  o.cutoff = HlslSpliceOptions::Cutoff::Epsilon;
  o.epsilon = 1.0f;
  HlslSpliceResult one = spliceHlslStereo(kGeometry, o);
  ASSERT_TRUE(one.ok);
  EXPECT_NE(one.text.find("> 1.0f && !isinf("), std::string::npos) << one.text;
  o.epsilon = 2e-3f;
  HlslSpliceResult half = spliceHlslStereo(kGeometry, o);
  ASSERT_TRUE(half.ok);
  EXPECT_NE(half.text.find("> 0.00200000009f && !isinf("), std::string::npos) << half.text;
  EXPECT_COMPILES(half.text, "geom", "GSMain");

  o.epsilon = -1.0f;
  EXPECT_FALSE(spliceHlslStereo(kGeometry, o).ok);
}

TEST(HlslSplice, CustomNamesAndRegister) {
  HlslSpliceOptions o = geomOptions();
  o.cbufferName = "EyeCB";
  o.cbufferRegister = 12;
  o.eyeSignName = "gEye";
  o.separationName = "gSep";
  o.convergenceName = "gConv";
  HlslSpliceResult r = spliceHlslStereo(kGeometry, o);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_NE(r.text.find("cbuffer EyeCB : register(b12)\n{\n    float gEye;\n    float gSep;\n    float gConv;\n};"),
            std::string::npos)
      << r.text;
  EXPECT_NE(r.text.find("(gEye * gSep) * (stereoshift_v.clip.w - gConv)"), std::string::npos);
  EXPECT_COMPILES(r.text, "geom", "GSMain");
}

TEST(HlslSplice, AppendInsideMacroAndConditionalHelper) {
  const char* src = R"(struct GSOut { float4 p : SV_Position; };
#define EMIT(s, v) s.Append(v)
#ifdef USE_HELPER
void Emit(inout PointStream<GSOut> s, float4 p) { GSOut o; o.p = p; EMIT(s, o); }
#else
void Emit(inout PointStream<GSOut> s, float4 p) { GSOut o; o.p = p * 2.0; s.Append(o); }
#endif
[maxvertexcount(2)]
void main(point float4 input[1] : SV_Position, inout PointStream<GSOut> stream)
{
    Emit(stream, input[0]);
    Emit(stream, input[0] + 1.0);
}
)";
  HlslSpliceResult r = spliceHlslStereo(src, geomOptions("main"));
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.sites, 2);
  EXPECT_NE(r.text.find("#define EMIT(s, v) s.Append(stereoshift_shift_GSOut(v))"), std::string::npos) << r.text;
  // The helper is declared before the #ifdef so that both branches see it.
  EXPECT_LT(r.text.find("stereoshift_shift_GSOut(GSOut"), r.text.find("#ifdef USE_HELPER"));
  EXPECT_COMPILES(r.text, "geom", "main");
  EXPECT_COMPILES(r.text, "geom", "main", "-DUSE_HELPER");
}

TEST(HlslSplice, AppendStructuredBufferIsNotAStream) {
  const char* src = R"(struct GSOut { float4 p : SV_Position; };
struct Rec { float4 p; };
AppendStructuredBuffer<Rec> records : register(u1);
[maxvertexcount(1)]
void GSMain(point float4 input[1] : SV_Position, inout PointStream<GSOut> stream)
{
    GSOut o;
    o.p = input[0];
    stream.Append(o);
}
void Log(float4 p) { Rec r; r.p = p; records.Append(r); }
)";
  HlslSpliceResult r = spliceHlslStereo(src, geomOptions());
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.sites, 1);
  EXPECT_NE(r.text.find("records.Append(r);"), std::string::npos);
  EXPECT_NE(r.text.find("stream.Append(stereoshift_shift_GSOut(o));"), std::string::npos);
}

// ------------------------------------------------------------------------------------------------ errors

TEST(HlslSplice, ErrorEntryPointNotFound) {
  HlslSpliceResult r = spliceHlslStereo(kGeometry, geomOptions("NoSuchMain"));
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("entry point 'NoSuchMain' not found"), std::string::npos) << r.error;
  EXPECT_EQ(r.line, 0);  // nothing to point at
  EXPECT_EQ(r.sites, 0);
  EXPECT_TRUE(r.text.empty());
  EXPECT_FALSE(spliceHlslStereo(kDomain, domainOptions("GSMain")).ok);
}

TEST(HlslSplice, ErrorNoSvPositionMember) {
  std::string src = kGeometry;
  src.replace(src.find("SV_POSITION"), 11, "TEXCOORD1");
  HlslSpliceResult r = spliceHlslStereo(src, geomOptions());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("SV_Position"), std::string::npos) << r.error;
  EXPECT_EQ(r.line, 13);  // `struct GSOut`
  EXPECT_EQ(r.column, 8);

  std::string dom = kDomain;
  dom.replace(dom.find("SV_Position"), 11, "POSITION1");
  HlslSpliceResult d = spliceHlslStereo(dom, domainOptions());
  EXPECT_FALSE(d.ok);
  EXPECT_NE(d.error.find("SV_Position"), std::string::npos) << d.error;
  EXPECT_EQ(d.line, 24);  // the entry point's name
  EXPECT_EQ(d.column, 7);
}

TEST(HlslSplice, ErrorNoAppendInGeometryShader) {
  const char* src = R"(struct GSOut { float4 p : SV_Position; };
[maxvertexcount(1)]
void GSMain(point float4 input[1] : SV_Position, inout PointStream<GSOut> stream)
{
    // stream.Append(o);  commented out
    stream.RestartStrip();
}
)";
  HlslSpliceResult r = spliceHlslStereo(src, geomOptions());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("no Append"), std::string::npos) << r.error;
  EXPECT_EQ(r.line, 3);
  EXPECT_EQ(r.column, 6);
}

TEST(HlslSplice, ErrorUnbalancedBraces) {
  std::string missing = kGeometry;
  missing.replace(missing.find("    stream.RestartStrip();\n}"), 28, "    stream.RestartStrip();\n");
  HlslSpliceResult r = spliceHlslStereo(missing, geomOptions());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("unbalanced '{'"), std::string::npos) << r.error;
  EXPECT_EQ(r.line, 30);  // the body of GSMain is never closed
  EXPECT_EQ(r.column, 1);

  std::string extra = std::string(kGeometry) + "}\n";
  HlslSpliceResult x = spliceHlslStereo(extra, geomOptions());
  EXPECT_FALSE(x.ok);
  EXPECT_NE(x.error.find("unbalanced '}'"), std::string::npos) << x.error;
  EXPECT_EQ(x.line, 40);  // kGeometry has 39 lines
  EXPECT_EQ(x.column, 1);

  HlslSpliceResult c = spliceHlslStereo("struct A { float4 p : SV_Position; };\n/* open", geomOptions());
  EXPECT_FALSE(c.ok);
  EXPECT_EQ(c.line, 2);
  EXPECT_EQ(c.column, 1);
}

TEST(HlslSplice, ErrorStreamsOfDifferentElementTypes) {
  const char* src = R"(struct A { float4 p : SV_Position; };
struct B { float4 p : SV_Position; float x : X; };
void Other(inout PointStream<B> s2) { B b; b.p = 0; b.x = 0; s2.Append(b); }
[maxvertexcount(1)]
void GSMain(point float4 input[1] : SV_Position, inout PointStream<A> s)
{
    A a;
    a.p = input[0];
    s.Append(a);
}
)";
  HlslSpliceResult r = spliceHlslStereo(src, geomOptions());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("different element types"), std::string::npos) << r.error;
  EXPECT_EQ(r.line, 3);
}

TEST(HlslSplice, ErrorAlreadyInjectedOrRegisterTaken) {
  HlslSpliceResult once = spliceHlslStereo(kGeometry, geomOptions());
  ASSERT_TRUE(once.ok);
  HlslSpliceOptions other = geomOptions();
  other.cbufferRegister = 9;
  HlslSpliceResult twice = spliceHlslStereo(once.text, other);
  EXPECT_FALSE(twice.ok);
  EXPECT_NE(twice.error.find("StereoParams"), std::string::npos) << twice.error;

  HlslSpliceOptions taken = geomOptions();
  taken.cbufferRegister = 0;  // cbuffer Camera : register(b0)
  HlslSpliceResult r = spliceHlslStereo(kGeometry, taken);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("register(b0)"), std::string::npos) << r.error;
  EXPECT_EQ(r.line, 2);
  EXPECT_EQ(r.column, 27);  // `b0` in `cbuffer Camera : register(b0)`
}

// The compile check itself must be able to fail, or the tests above prove nothing.
TEST(HlslSplice, CompileCheckRejectsInvalidHlsl) {
  std::string broken = kGeometry;
  broken.replace(broken.find("stream.Append(o);"), 17, "stream.Append(stereoshift_shift_GSOut(o));");
  CompileResult cr = compileHlsl(broken, "geom", "GSMain");
  if (!cr.ran) GTEST_SKIP() << "GLSLANG_VALIDATOR not defined";
  EXPECT_FALSE(cr.ok) << "an undeclared helper should not compile";
  CompileResult good = compileHlsl(kGeometry, "geom", "GSMain");
  EXPECT_TRUE(good.ok) << good.log;
}

// ------------------------------------------------------------------------------------------------ corpus

#ifdef CORPUS_DIR
TEST(HlslSplice, CorpusExplodeGeometry) {
  std::string src = readFile(std::filesystem::path(CORPUS_DIR) / "hlsl" / "explode.geom.hlsl");
  ASSERT_FALSE(src.empty());
  HlslSpliceResult r = spliceHlslStereo(src, geomOptions());
  ASSERT_TRUE(r.ok) << r.line << ":" << r.column << ": " << r.error;
  EXPECT_EQ(r.sites, 1);  // the only Append is in EmitShardVertex, called six times
  EXPECT_NE(r.text.find("stream.Append(stereoshift_shift_GSOutput(v));"), std::string::npos);
  EXPECT_LT(r.text.find("struct GSOutput"), r.text.find("cbuffer StereoParams"));
  EXPECT_LT(r.text.find("stereoshift_shift_GSOutput(GSOutput"), r.text.find("void EmitShardVertex"));
  EXPECT_NE(r.text.find("stereoshift_v.Position.x + (eyeSign * separation)"), std::string::npos);
  EXPECT_COMPILES(r.text, "geom", "GSMain");
}

TEST(HlslSplice, CorpusPnTrianglesDomain) {
  std::string src = readFile(std::filesystem::path(CORPUS_DIR) / "hlsl" / "pn_triangles.tese.hlsl");
  ASSERT_FALSE(src.empty());
  HlslSpliceResult r = spliceHlslStereo(src, domainOptions());
  ASSERT_TRUE(r.ok) << r.line << ":" << r.column << ": " << r.error;
  EXPECT_EQ(r.sites, 1);
  EXPECT_NE(r.text.find("DSOutput DSMain_stereoshift_mono(PatchConstants pc"), std::string::npos);
  EXPECT_NE(r.text.find("[domain(\"tri\")]\nDSOutput DSMain(PatchConstants pc, float3 bary : SV_DomainLocation, "
                        "const OutputPatch<DSInput, 3> patch)\n{\n    return "
                        "stereoshift_shift_DSOutput(DSMain_stereoshift_mono(pc, bary, patch));"),
            std::string::npos)
      << r.text;
  EXPECT_COMPILES(r.text, "tese", "DSMain");
}
#endif

// ---- vertex shaders ----

HlslSpliceOptions vertexOptions(std::vector<stereoshift::HlslSplicedEntry> entries) {
  HlslSpliceOptions o;
  o.vertex = true;
  o.vertexEntries = std::move(entries);
  o.cbufferRegister = 1;
  return o;
}

const char* kTwoVertexShaders = R"(cbuffer Camera : register(b0) { float4x4 ViewProj; };
struct VSOut
{
    float2 uv : TEXCOORD0;
    float4 pos : SV_Position;
    float4 copy : TEXCOORD1;
};
VSOut MeshVS(float3 p : POSITION, float2 uv : TEXCOORD0)
{
    VSOut o;
    o.uv = uv;
    o.pos = mul(ViewProj, float4(p, 1.0));
    o.copy = o.pos;
    if (uv.x < 0.0)
        return o;
    return o;
}
float4 SkyVS(float3 p : POSITION) : SV_Position { return mul(ViewProj, float4(p, 1.0)).xyww; }
float4 MeshPS(VSOut i) : SV_Target { return i.copy; }
)";

// Every return of every entry point is shifted; the struct, its member order and the pixel shader
// stay byte for byte; each entry point of the result compiles.
TEST(HlslSplice, VertexShiftsEveryReturnOfEachEntryPoint) {
  HlslSpliceResult r = spliceHlslStereo(kTwoVertexShaders, vertexOptions({{"MeshVS", {".copy"}}, {"SkyVS", {}}}));
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.sites, 3);
  EXPECT_EQ(countOf(r.text, "return stereoshift_shift_VSOut(o);"), 2) << r.text;
  EXPECT_NE(r.text.find("{ return stereoshift_shift_position(mul(ViewProj, float4(p, 1.0)).xyww); }"), std::string::npos);
  EXPECT_NE(r.text.find("struct VSOut\n{\n    float2 uv : TEXCOORD0;\n    float4 pos : SV_Position;\n    float4 copy : "
                        "TEXCOORD1;\n};\n"),
            std::string::npos);
  EXPECT_NE(r.text.find("stereoshift_v.copy.x = stereoshift_x1;"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("float4 MeshPS(VSOut i) : SV_Target { return i.copy; }"), std::string::npos);
  EXPECT_EQ(countOf(r.text, "cbuffer StereoParams : register(b1)"), 1);
  for (const char* entry : {"MeshVS", "SkyVS"}) {
    CompileResult c = compileHlsl(r.text, "vert", entry);
    if (c.ran) EXPECT_TRUE(c.ok) << entry << "\n" << c.log << r.text;
  }
  CompileResult ps = compileHlsl(r.text, "frag", "MeshPS");
  if (ps.ran) EXPECT_TRUE(ps.ok) << ps.log;
}

// `out` parameters are shifted before every return and where the body falls off its end.
TEST(HlslSplice, VertexShiftsOutParametersBeforeEachReturnAndAtTheEnd) {
  const char* src = R"(cbuffer Camera : register(b0) { float4x4 ViewProj; };
void VSMain(float3 p : POSITION, out float4 oPos : SV_POSITION, out float2 oUV : TEXCOORD0)
{
    oUV = p.xy;
    oPos = mul(ViewProj, float4(p, 1.0));
    if (p.z > 100.0)
        return;
}
)";
  HlslSpliceResult r = spliceHlslStereo(src, vertexOptions({{"VSMain", {}}}));
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.sites, 2);
  EXPECT_NE(r.text.find("        { oPos = stereoshift_shift_position(oPos); return; }\n"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("    oPos = stereoshift_shift_position(oPos);\n}\n"), std::string::npos) << r.text;
  CompileResult c = compileHlsl(r.text, "vert", "VSMain");
  if (c.ran) EXPECT_TRUE(c.ok) << c.log << r.text;
}

// A halo copy the text cannot place, and a name the source already declares: errors with their
// place, the second one marked as a clash (no route resolves it).
TEST(HlslSplice, VertexErrorsSayWhereAndWhetherTheyClash) {
  HlslSpliceResult notMember = spliceHlslStereo(kTwoVertexShaders, vertexOptions({{"MeshVS", {".missing"}}}));
  ASSERT_FALSE(notMember.ok);
  EXPECT_FALSE(notMember.clash);
  EXPECT_NE(notMember.error.find("'missing'"), std::string::npos) << notMember.error;
  EXPECT_EQ(notMember.line, 8);

  std::string clashing = std::string(kTwoVertexShaders) + "float stereoshift_shift_VSOut;\n";
  HlslSpliceResult clash = spliceHlslStereo(clashing, vertexOptions({{"MeshVS", {}}}));
  ASSERT_FALSE(clash.ok);
  EXPECT_TRUE(clash.clash) << clash.error;

  HlslSpliceResult noPosition = spliceHlslStereo(kTwoVertexShaders, vertexOptions({{"MeshPS", {}}}));
  ASSERT_FALSE(noPosition.ok);
  EXPECT_NE(noPosition.error.find("has no SV_Position output"), std::string::npos) << noPosition.error;
}

// Entry points come from the techniques (with their profile's stage) and from signatures; a
// function another one calls is a helper, not an entry point.
TEST(HlslSplice, FindsEntryPointsByTechniqueAndSignature) {
  const char* src = R"(struct VSOut { float4 pos : SV_Position; };
VSOut transform(float3 p) { VSOut o; o.pos = float4(p, 1.0); return o; }
VSOut SceneVS(float3 p : POSITION) { return transform(p); }
float4 ScenePS(VSOut i) : SV_Target { return 1.0; }
[numthreads(8, 8, 1)] void Blur(uint3 id : SV_DispatchThreadID) {}
float4 Plain(float4 c : COLOR) : COLOR { return c; }
technique11 T { pass P { SetPixelShader(CompileShader(ps_5_0, Plain())); } }
)";
  auto found = stereoshift::findHlslEntryPoints(src);
  ASSERT_EQ(found.size(), 4u);
  EXPECT_EQ(found[0].name, "SceneVS");
  EXPECT_EQ(found[0].stage, stereoshift::Stage::Vertex);
  EXPECT_EQ(found[1].name, "ScenePS");
  EXPECT_EQ(found[1].stage, stereoshift::Stage::Fragment);
  EXPECT_EQ(found[2].stage, stereoshift::Stage::Compute);
  EXPECT_EQ(found[3].name, "Plain");
  EXPECT_EQ(found[3].foundBy, "technique");
}

}  // namespace
