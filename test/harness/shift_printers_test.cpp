// One table of shift specs run through the four printers of the shift (core/shift_spec.h): the
// SPIR-V emitter, the GLSL source splice, the HLSL source splice and the D3D-assembly splice. Each
// printer's output is executed against the exact stereo reference under the spec's own cutoff
// (cutoffKeepsMono), not compared as text: the three that become SPIR-V run on lavapipe from a
// pass-through shader (gl_Position = the attribute, so the table's w values reach the guard as they
// are), the assembly on the project's interpreter. Mono must be bit for bit, the vertices the
// cutoff keeps unchanged in both eyes, each eye within the bound of its arithmetic. A printer that
// has no spelling of a form declines (the GLSL splice has no compensated form) instead of writing
// another arithmetic. Each printer's check is shown to fail on a shader shifted under another cutoff.
#include "transpiler/d3dasm/asm_verify.h"
#include "transpiler/frontend/front_end.h"
#include "transpiler/verify/stereo_verify.h"
#include "test/harness/vulkan_suite.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <iostream>

using namespace stereoshift;
using namespace stereoshift::harness;

namespace {

const char* kGlslPassThrough = R"(#version 450
layout(location = 0) in vec4 inClip;
void main()
{
    gl_Position = inClip;
}
)";

const char* kHlslPassThrough = R"(float4 main(float4 clip : POSITION) : SV_Position
{
    return clip;
}
)";

const char* kAssemblyPassThrough = R"(vs_5_0
dcl_globalFlags refactoringAllowed
dcl_input v0.xyzw
dcl_output_siv o0.xyzw, position
mov o0.xyzw, v0.xyzw
ret
)";

struct SpecCase {
  const char* name;
  CutoffMode cutoff;
  float epsilon;
  ShiftForm form;
  bool fused;
  bool compensated;
};

// The table: every cutoff, both forms, the three arithmetics.
const SpecCase kSpecs[] = {
    {"epsilon-branch", CutoffMode::Epsilon, 1e-5f, ShiftForm::Branch, false, false},
    {"exact-select", CutoffMode::Exact, 1e-5f, ShiftForm::Select, false, false},
    {"zero-epsilon-is-exact", CutoffMode::Epsilon, 0.0f, ShiftForm::Branch, false, false},
    {"wide-epsilon-select", CutoffMode::Epsilon, 1e-2f, ShiftForm::Select, false, false},
    {"no-cutoff", CutoffMode::None, 1e-5f, ShiftForm::Branch, false, false},
    {"fused", CutoffMode::Epsilon, 1e-5f, ShiftForm::Branch, true, false},
    {"compensated-select", CutoffMode::Epsilon, 1e-5f, ShiftForm::Select, false, true},
};

TranspileOptions optionsOf(const SpecCase& spec) {
  TranspileOptions o;
  o.cutoff = spec.cutoff;
  o.cutoffEpsilon = spec.epsilon;
  o.shiftForm = spec.form;
  o.fusedShift = spec.fused;
  o.compensatedShift = spec.compensated;
  return o;
}

// w over the regimes the guard tells apart: exactly 1, one ULP either side, inside and outside the
// wide epsilon, far and near planes; x inside and outside the frustum.
std::vector<std::array<float, 4>> tableVertices() {
  std::vector<std::array<float, 4>> v;
  for (float w : {1.0f, std::nextafter(1.0f, 0.0f), std::nextafter(1.0f, 2.0f), 1.000004f, 0.999996f, 1.00002f,
                  0.99998f, 1.005f, 0.995f, 1.02f, 0.98f, 0.01f, 0.5f, 3.0f, 10.0f, 250.0f, 1e5f})
    for (float x : {0.37f, -1.9f, 0.0f}) v.push_back({x * w, -0.2f * w, 0.5f * w, w});
  return v;
}

// How many table vertices the spec's cutoff keeps: what a stereo run must leave in place.
uint32_t keptByCutoff(CutoffMode cutoff, float epsilon) {
  uint32_t kept = 0;
  for (const auto& v : tableVertices()) kept += cutoffKeepsMono(cutoff, epsilon, v[3]);
  return kept;
}

class ShiftPrinters : public VulkanSuite<::testing::TestWithParam<SpecCase>> {
 protected:
  // The original and the converted text of `source`, both compiled to SPIR-V as a driver would get them.
  std::optional<StageModules> spliced(const char* path, const char* source, const TranspileOptions& options,
                                      const char* route) {
    TranspileResult converted = transpile(SourceFile{path, source}, options);
    EXPECT_TRUE(converted.ok) << converted.diagnostics.format();
    if (converted.record.emit.route != route) {
      ADD_FAILURE() << path << ": route " << converted.record.emit.route << ", not " << route;
      return std::nullopt;
    }
    Diagnostics diags;
    FrontEndResult stereo = compileToSpirv(SourceFile{path, converted.output}, options, diags);
    EXPECT_TRUE(stereo.ok) << diags.format() << converted.output;
    if (!stereo.ok) return std::nullopt;
    StageModules stage;
    stage.original = converted.originalSpirv;
    stage.transpiled = stereo.spirv;
    return stage;
  }

  // Runs the table's vertices; `verifiedAs` is the cutoff the check expects (the conversion's own,
  // or another to show the check fails).
  VerifyResult run(const StageModules& stage, const SpecCase& verifiedAs) {
    VerifySettings s;
    s.cutoff = verifiedAs.cutoff;
    s.cutoffEpsilon = verifiedAs.epsilon;
    if (verifiedAs.compensated) s.maxUlps = 1.0;
    const auto vertices = tableVertices();
    s.vertices = clipVertices(vertices);
    s.vertexCount = static_cast<uint32_t>(vertices.size());
    return verifyStereo(*context_, {stage}, s);
  }

  void expectVerified(const VerifyResult& r, const SpecCase& spec, const char* printer) {
    ASSERT_TRUE(r.error.empty()) << printer << ": " << r.error;
    std::cout << "[shift-printers] " << spec.name << " / " << printer << ": max stereo error " << r.maxStereoUlps
              << " ULP, cutoff vertices " << r.cutoffVertices << "\n";
    EXPECT_TRUE(r.monoIdentical) << printer << ": " << (r.problems.empty() ? "" : r.problems.front());
    EXPECT_TRUE(r.otherOutputsUnchanged) << printer;
    EXPECT_EQ(r.newNaNs, 0u) << printer;
    EXPECT_EQ(r.cutoffVertices, keptByCutoff(spec.cutoff, spec.epsilon)) << printer;
    EXPECT_LE(r.maxStereoUlps, spec.compensated ? 1.0 : 2.5) << printer;
  }
};

TEST_P(ShiftPrinters, SpirvPrinter) {
  ASSERT_TRUE(context_) << "no Vulkan device: " << setupError_;
  const SpecCase& spec = GetParam();
  std::vector<StageModules> stages;
  std::string classification;
  Diagnostics diags;
  ASSERT_TRUE(buildStageModules({{"table.vert", kGlslPassThrough}}, optionsOf(spec), &stages, &classification, diags))
      << diags.format();
  ASSERT_EQ(stages.size(), 1u);
  expectVerified(run(stages[0], spec), spec, "spirv");
}

TEST_P(ShiftPrinters, GlslPrinter) {
  ASSERT_TRUE(context_) << "no Vulkan device: " << setupError_;
  const SpecCase& spec = GetParam();
  TranspileOptions options = optionsOf(spec);
  if (spec.compensated) {
    // No compensated spelling in the GLSL splice: it declines, and the re-emit carries the IR's.
    TranspileResult converted = transpile(SourceFile{"table.vert", kGlslPassThrough}, options);
    ASSERT_TRUE(converted.ok) << converted.diagnostics.format();
    EXPECT_NE(converted.record.emit.route, "glsl-source-splice");
    EXPECT_NE(converted.diagnostics.format().find("compensated"), std::string::npos) << converted.diagnostics.format();
    return;
  }
  auto stage = spliced("table.vert", kGlslPassThrough, options, "glsl-source-splice");
  ASSERT_TRUE(stage);
  expectVerified(run(*stage, spec), spec, "glsl");
}

TEST_P(ShiftPrinters, HlslPrinter) {
  ASSERT_TRUE(context_) << "no Vulkan device: " << setupError_;
  const SpecCase& spec = GetParam();
  auto stage = spliced("table.vert.hlsl", kHlslPassThrough, optionsOf(spec), "hlsl-source-splice");
  ASSERT_TRUE(stage);
  expectVerified(run(*stage, spec), spec, "hlsl");
}

// The assembly check on the interpreter, with the table's vertices as v0 (each eye of each vertex
// a run).
d3dasm::AsmVerifyResult runAssembly(const std::string& converted, const SpecCase& verifiedAs) {
  d3dasm::AsmVerifyOptions check;
  check.firstInputValues = tableVertices();
  check.samples = static_cast<int>(check.firstInputValues.size());
  check.cutoff = verifiedAs.cutoff;
  check.cutoffEpsilon = verifiedAs.epsilon;
  return d3dasm::verifyAssemblyConversion(kAssemblyPassThrough, converted, check);
}

// The assembly printer renders the cutoff; its arithmetic is always one `mad` under `movc`.
TEST_P(ShiftPrinters, AssemblyPrinter) {
  const SpecCase& spec = GetParam();
  TranspileOptions options = optionsOf(spec);
  TranspileResult converted = transpile(SourceFile{"0123456789abcdef-vs.txt", kAssemblyPassThrough}, options);
  ASSERT_TRUE(converted.ok) << converted.diagnostics.format();
  ASSERT_EQ(converted.record.emit.route, "d3d-asm-splice");
  d3dasm::AsmVerifyResult r = runAssembly(converted.output, spec);
  ASSERT_TRUE(r.ran) << r.error;
  std::cout << "[shift-printers] " << spec.name << " / d3d-asm: " << r.shiftedRuns << " shifted runs, "
            << r.cutoffRuns << " kept by the cutoff\n";
  EXPECT_TRUE(r.ok) << r.firstFailure;
  EXPECT_EQ(r.monoMismatches, 0);
  // Both eyes of every vertex the cutoff keeps.
  EXPECT_EQ(r.cutoffRuns, 2 * static_cast<int>(keptByCutoff(spec.cutoff, spec.epsilon)));
}

INSTANTIATE_TEST_SUITE_P(Table, ShiftPrinters, ::testing::ValuesIn(kSpecs),
                         [](const ::testing::TestParamInfo<SpecCase>& info) {
                           std::string n = info.param.name;
                           for (char& ch : n)
                             if (ch == '-') ch = '_';
                           return n;
                         });

// The checks above can fail: a shader shifted without a cutoff, checked as one with the wide
// epsilon, moves vertices that should have stayed, in every printer's output.
class ShiftPrinterChecks : public VulkanSuite<> {};

TEST_F(ShiftPrinterChecks, AnotherCutoffIsCaughtInEveryPrinter) {
  ASSERT_TRUE(context_) << "no Vulkan device: " << setupError_;
  const SpecCase shifted = kSpecs[4];       // no cutoff
  const SpecCase expected = kSpecs[3];      // the wide epsilon
  ASSERT_EQ(shifted.cutoff, CutoffMode::None);
  ASSERT_EQ(expected.epsilon, 1e-2f);
  const TranspileOptions options = optionsOf(shifted);
  std::vector<StageModules> stages;
  std::string classification;
  Diagnostics diags;
  ASSERT_TRUE(buildStageModules({{"table.vert", kGlslPassThrough}}, options, &stages, &classification, diags));
  for (const auto& [path, source, route] :
       {std::tuple{"table.vert", kGlslPassThrough, "glsl-source-splice"},
        std::tuple{"table.vert.hlsl", kHlslPassThrough, "hlsl-source-splice"}}) {
    TranspileResult converted = transpile(SourceFile{path, source}, options);
    ASSERT_EQ(converted.record.emit.route, route);
    Diagnostics d;
    FrontEndResult stereo = compileToSpirv(SourceFile{path, converted.output}, options, d);
    ASSERT_TRUE(stereo.ok) << d.format();
    StageModules stage;
    stage.original = converted.originalSpirv;
    stage.transpiled = stereo.spirv;
    stages.push_back(std::move(stage));
  }
  for (const StageModules& stage : stages) {
    VerifySettings s;
    s.cutoff = expected.cutoff;
    s.cutoffEpsilon = expected.epsilon;
    const auto vertices = tableVertices();
    s.vertices = clipVertices(vertices);
    s.vertexCount = static_cast<uint32_t>(vertices.size());
    VerifyResult r = verifyStereo(*context_, {stage}, s);
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_TRUE(r.monoIdentical);
    EXPECT_GT(r.maxStereoUlps, s.maxUlps) << "a vertex the wide epsilon keeps was shifted and not caught";
  }
  // Assembly: shifted without a cutoff, checked with the wide epsilon: the kept vertices moved.
  TranspileResult converted = transpile(SourceFile{"0123456789abcdef-vs.txt", kAssemblyPassThrough}, options);
  ASSERT_TRUE(converted.ok);
  d3dasm::AsmVerifyResult r = runAssembly(converted.output, expected);
  ASSERT_TRUE(r.ran) << r.error;
  EXPECT_FALSE(r.ok);
  EXPECT_GT(r.cutoffMismatches, 0);
}

}  // namespace
