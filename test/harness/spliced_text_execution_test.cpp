// Accuracy by execution of the GLSL source-splice routes: the *text* a user gets back (the original
// with `main` renamed and the shifting `main` appended, or a geometry shader's emits wrapped) is
// compiled again by stereoshift's own front end, as an application's driver would get it, and run
// on lavapipe against the original, with eyeSign = 0 (bit-exact mono identity), -1 and +1 (stereo
// error against the double reference). `stereoshift verify` and execution.corpus check the SPIR-V
// route; this checks the spliced text itself, for every corpus pipeline whose stages are all
// spliced or copied (legacy GLSL 1xx / ESSL 100, GLSL 330, ESSL 300, Vulkan GLSL, the relief
// tutorials, the file-naming conventions). Each stereo run is also held, output by output and bit
// for bit, to the SPIR-V route's conversion of the shifted stage: the text carries what the IR does,
// outputs derived from the position (halo) included.
#include "transpiler/frontend/front_end.h"
#include "transpiler/stereoshift.h"
#include "transpiler/verify/stereo_verify.h"
#include "test/harness/vulkan_suite.h"
#include "transpiler/source/file_io.h"
#include "transpiler/source/stage_rules.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

namespace fs = std::filesystem;
using namespace stereoshift;
using namespace stereoshift::harness;

namespace {

struct PipelineCase {
  std::string name;
  std::vector<fs::path> stages;  // pre-rasterization stages, in pipeline order
  EyeSource eyeSource = EyeSource::Auto;  // --eye-source of the conversion
  EyeSelect select = EyeSelect::Parameter;  // --eye-source multiview: the eye from the view index
};

std::vector<PipelineCase> glslPipelines(const fs::path& root) {
  std::map<std::string, std::vector<fs::path>> groups;
  for (auto& e : fs::recursive_directory_iterator(root)) {
    if (!e.is_regular_file()) continue;
    std::string rel = fs::relative(e.path(), root).string();
    if (rel.find("hlsl") != std::string::npos || rel.find("d3d") != std::string::npos ||
        rel.find("include") != std::string::npos)
      continue;
    auto stage = stageFromPath(e.path().string());
    if (!stage || !isPreRasterization(*stage)) continue;
    groups[pipelineKey(e.path().string())].push_back(e.path());
  }
  auto order = [](const fs::path& p) { return static_cast<int>(*stageFromPath(p.string())); };
  std::vector<PipelineCase> cases;
  for (auto& [key, stages] : groups) {
    std::sort(stages.begin(), stages.end(), [&](auto& a, auto& b) { return order(a) < order(b); });
    cases.push_back({fs::relative(key, root).string(), stages});
  }
  return cases;
}

VkShaderStageFlagBits vkStage(Stage stage) {
  switch (stage) {
    case Stage::TessControl: return VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
    case Stage::TessEvaluation: return VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
    case Stage::Geometry: return VK_SHADER_STAGE_GEOMETRY_BIT;
    default: return VK_SHADER_STAGE_VERTEX_BIT;
  }
}

class SplicedTextExecution : public VulkanSuite<::testing::TestWithParam<PipelineCase>> {};

TEST_P(SplicedTextExecution, SplicedTextMatchesReference) {
  ASSERT_TRUE(context_) << "no Vulkan device: " << setupError_;
  const PipelineCase& c = GetParam();
  std::vector<StageModules> stages;
  bool spliced = false;
  // Converted as one pipeline, as `build` converts it (the eye parameters at a binding no stage uses).
  std::vector<SourceFile> inputs;
  for (const auto& path : c.stages) {
    inputs.push_back({path.string(), {}});
    ASSERT_TRUE(readFile(path.string(), &inputs.back().contents));
  }
  TranspileOptions pipelineOptions;
  pipelineOptions.eye.source = c.eyeSource;
  pipelineOptions.eye.select = c.select;
  pipelineOptions.includeDirs = {(c.stages.front().parent_path() / "include").string()};
  std::vector<TranspileResult> all = transpilePipeline(inputs, pipelineOptions);
  TranspileOptions viaIr = pipelineOptions;
  viaIr.target = TargetLanguage::Spirv;
  std::vector<TranspileResult> allViaIr = transpilePipeline(inputs, viaIr);
  ASSERT_EQ(all.size(), c.stages.size());
  ASSERT_EQ(allViaIr.size(), c.stages.size());
  for (size_t i = 0; i < c.stages.size(); ++i) {
    const SourceFile& input = inputs[i];
    TranspileOptions options = pipelineOptions;
    options.shiftThisStage = i + 1 == c.stages.size();
    TranspileResult& converted = all[i];
    ASSERT_TRUE(converted.ok) << converted.diagnostics.format();
    std::string route = converted.report.value("route", "");
    bool copied = converted.report.value("output", "") == "copied";
    if (options.shiftThisStage) {
      if (converted.report.value("classification", "") != "perspective") GTEST_SKIP() << "needs no shift";
      if (route != "glsl-source-splice") GTEST_SKIP() << "re-emitted (execution.corpus runs that route)";
      spliced = true;
    } else if (!copied && route != "glsl-source-splice") {
      GTEST_SKIP() << c.stages[i].filename() << " re-emitted (execution.corpus runs that route)";
    }
    // The emitted text, through the front end as an application's driver would get it.
    Diagnostics diags;
    FrontEndResult stereo = compileToSpirv(SourceFile{input.path, converted.output}, options, diags);
    ASSERT_TRUE(stereo.ok) << diags.format();
    StageModules stage;
    stage.stage = vkStage(stereo.info.stage);
    stage.original = converted.originalSpirv;
    stage.transpiled = stereo.spirv;
    for (const auto& n : converted.report.value("halo_copies", nlohmann::json::array()))
      stage.haloOutputs.push_back(n.get<std::string>());
    // Outputs computed from the position move with it (verify's own rule); what they move to is
    // held to the SPIR-V route's conversion of the same stage, bit for bit (`agreeing`).
    if (converted.report.contains("passes") && converted.report["passes"].contains("halo"))
      for (const auto& n : converted.report["passes"]["halo"].value("shifted_outputs", nlohmann::json::array()))
        stage.haloOutputs.push_back(n.get<std::string>());
    if (options.shiftThisStage) {
      const TranspileResult& ir = allViaIr[i];
      ASSERT_TRUE(ir.ok) << ir.diagnostics.format();
      stage.agreeing.resize(ir.output.size() / 4);
      std::memcpy(stage.agreeing.data(), ir.output.data(), stage.agreeing.size() * 4);
    }
    // Outputs made from the per-eye camera differ between the eyes by design (relief view vectors;
    // their images are checked in relief_render_test.cpp); mono must still be bit for bit.
    if (converted.report.contains("passes") && converted.report["passes"].contains("per-eye-view"))
      for (const auto& n : converted.report["passes"]["per-eye-view"].value("per_eye_outputs", nlohmann::json::array()))
        stage.haloOutputs.push_back(n.get<std::string>());
    stages.push_back(std::move(stage));
  }
  ASSERT_TRUE(spliced);
  VerifySettings settings;
  settings.eyeSource = c.select;
  VerifyResult r = verifyStereo(*context_, stages, settings);
  if (!r.error.empty() && r.error.find("harness cannot") != std::string::npos) GTEST_SKIP() << r.error;
  ASSERT_TRUE(r.error.empty()) << r.error;
  std::cout << "[verify] " << c.name << ": vertices " << r.vertices << ", mono identical " << r.monoIdentical
            << ", max stereo error " << r.maxStereoUlps << " ULP, cutoff vertices " << r.cutoffVertices << "\n";
  EXPECT_GT(r.vertices, 0u);
  EXPECT_TRUE(r.otherOutputsUnchanged) << (r.problems.empty() ? "" : r.problems.front());
  EXPECT_LE(r.maxStereoUlps, settings.maxUlps);
  EXPECT_TRUE(r.problems.empty()) << r.problems.front();
  if (c.select == EyeSelect::Parameter) {
    EXPECT_TRUE(r.monoIdentical);
    // The agreement with the SPIR-V route runs with the two-pass draws.
    EXPECT_GT(r.agreementComponentsCompared, 0u);
    EXPECT_EQ(r.disagreeingComponents, 0u) << (r.problems.empty() ? "" : r.problems.front());
  } else {
    EXPECT_TRUE(r.eyeSignIgnored);  // a multiview shader no longer reads eyeSign
    EXPECT_TRUE(r.ok) << (r.problems.empty() ? "" : r.problems.front());
  }
}

std::string caseName(const ::testing::TestParamInfo<PipelineCase>& info) {
  std::string n = info.param.name;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Corpus, SplicedTextExecution, ::testing::ValuesIn(glslPipelines(CORPUS_DIR)), caseName);
// The harness's own splice cases (shaders/splice/): halo outputs derived from the position in the
// legacy dialects and through a local, which the corpus does not write.
INSTANTIATE_TEST_SUITE_P(Harness, SplicedTextExecution, ::testing::ValuesIn(glslPipelines(SPLICE_SHADER_DIR)),
                         caseName);
// --eye-source push-constant on shaders with their own push-constant block: the splice inserts the
// eye parameters into that block (the corpus's Vulkan shaders that have one, and the harness's own).
INSTANTIATE_TEST_SUITE_P(
    PushConstants, SplicedTextExecution,
    ::testing::Values(
        PipelineCase{"vk450_push_constants", {fs::path(SPLICE_SHADER_DIR) / "vk450_push_constants.vert"}, EyeSource::PushConstant},
        PipelineCase{"vk450_forward_pbr", {fs::path(CORPUS_DIR) / "vk450/forward_pbr.vert"}, EyeSource::PushConstant},
        PipelineCase{"vk450_shadow_cascade", {fs::path(CORPUS_DIR) / "vk450/shadow_cascade.vert"}, EyeSource::PushConstant}),
    caseName);
// --eye-source multiview on Vulkan GLSL: the spliced text takes the eye from gl_ViewIndex
// (GL_EXT_multiview); each view against the exact shift, the other outputs as the original's.
INSTANTIATE_TEST_SUITE_P(
    Multiview, SplicedTextExecution,
    ::testing::Values(PipelineCase{"vk450_forward_pbr", {fs::path(CORPUS_DIR) / "vk450/forward_pbr.vert"},
                                   EyeSource::Auto, EyeSelect::ViewIndex},
                      PipelineCase{"vk450_push_constants", {fs::path(SPLICE_SHADER_DIR) / "vk450_push_constants.vert"},
                                   EyeSource::PushConstant, EyeSelect::ViewIndex}),
    caseName);

// 3Dmigoto dumps spliced with --eye-source 3dmigoto: the spliced text (the dump's `#define cmp -`
// and SV_POSITION0 kept) compiled again, run against the original with StereoParams texel 0 set
// as 3Dmigoto sets it (x = eyeSign * separation, y = convergence): separation 0 is mono, bit for
// bit; each eye within the bound of the exact shift.
// The vertex stage of a converted dump as the harness runs it: the original's SPIR-V, and the
// spliced text compiled again by the front end (as the game's D3D compiler would get it); empty with
// the front end's messages in `why` when the text does not compile.
std::optional<StageModules> splicedVertexStage(const SourceFile& input, const TranspileResult& converted,
                                               const TranspileOptions& options, std::string* why) {
  Diagnostics diags;
  FrontEndResult stereo = compileToSpirv(SourceFile{input.path, converted.output}, options, diags);
  if (!stereo.ok) {
    *why = diags.format();
    return std::nullopt;
  }
  StageModules stage;
  stage.stage = VK_SHADER_STAGE_VERTEX_BIT;
  stage.original = converted.originalSpirv;
  stage.transpiled = stereo.spirv;
  return stage;
}

class MigotoDumpExecution : public VulkanSuite<> {};

TEST_F(MigotoDumpExecution, SplicedDumpMatchesReference) {
  ASSERT_TRUE(context_) << "no Vulkan device: " << setupError_;
  for (const char* dump : {"skinned-vs_replace.txt"}) {
    for (auto [declared, textOnly] : {std::pair{true, false}, std::pair{false, false}, std::pair{true, true}}) {
      SourceFile input{"0f1e2d3c4b5a6978-vs_replace.txt", {}};
      ASSERT_TRUE(readFile(std::string(MIGOTO_DUMP_DIR) + "/" + dump, &input.contents));
      if (!declared) {  // without its 3Dmigoto declarations: the splice declares the texture
        std::string kept;
        size_t at = 0;
        while (at < input.contents.size()) {
          size_t end = input.contents.find('\n', at);
          std::string line = input.contents.substr(at, end == std::string::npos ? std::string::npos : end + 1 - at);
          if (line.find("StereoParams") == std::string::npos && line.find("IniParams") == std::string::npos) kept += line;
          at = end == std::string::npos ? input.contents.size() : end + 1;
        }
        input.contents = kept;
      }
      TranspileOptions options;
      options.eyeFrom3DMigoto = true;
      options.eye.source = EyeSource::UniformBlock;
      options.eye.blockName = "stereoshift_StereoParams";
      // The text-only route, as after a glslang crash: the front end is not run for the conversion.
      options.glslangCrashed = textOnly;
      TranspileResult converted = transpile(input, options);
      ASSERT_TRUE(converted.ok) << converted.diagnostics.format();
      ASSERT_EQ(converted.report.value("route", ""), textOnly ? "hlsl-text-only" : "hlsl-source-splice");
      options.glslangCrashed = false;
      if (textOnly) {  // the original for the comparison, parsed here (this dump does not crash glslang)
        Diagnostics originalDiags;
        FrontEndResult original = compileToSpirv(input, options, originalDiags);
        ASSERT_TRUE(original.ok) << originalDiags.format();
        converted.originalSpirv = original.spirv;
      }
      ASSERT_NE(converted.output.find("StereoParams.Load(int3(0, 0, 0))"), std::string::npos) << converted.output;
      std::string why;
      std::optional<StageModules> stage = splicedVertexStage(input, converted, options, &why);
      ASSERT_TRUE(stage) << why;
      VerifySettings settings;
      VerifyResult r = verifyStereo(*context_, {*stage}, settings);
      ASSERT_TRUE(r.error.empty()) << r.error;
      std::cout << "[verify] 3dmigoto " << dump << (declared ? "" : " (texture declared by the splice)")
                << (textOnly ? " (text-only route)" : "") << ": vertices "
                << r.vertices << ", mono identical " << r.monoIdentical << ", max stereo error " << r.maxStereoUlps
                << " ULP, cutoff vertices " << r.cutoffVertices << "\n";
      EXPECT_GT(r.vertices, 0u);
      EXPECT_TRUE(r.monoIdentical);
      EXPECT_TRUE(r.otherOutputsUnchanged) << (r.problems.empty() ? "" : r.problems.front());
      EXPECT_LE(r.maxStereoUlps, settings.maxUlps);
    }
  }
}

}  // namespace

namespace {

// A vertex dump that hands the pixel shader its screen position computed through registers (Unity's
// ComputeScreenPos: `r0.xz = float2(0.5,0.5) * r1.xw; o3.xy = r0.xw + r0.zz;`, read by soft
// particles, water and refraction): its x must move with the position, by half the shift, or the
// pixel shader samples the screen where the mono image was (a halo). The expectation is the test's
// own (o3.x moves by 0.5 times the shift of x, nothing else moves): the spliced text compiled again
// and run on lavapipe, o3.x held to mono + 0.5 * (reference x - x) within kMovedLaneUlps; o4 (x
// times a cbuffer element) and o5 (x squared) are left mono, unchanged, as the analysis says.
TEST_F(MigotoDumpExecution, ScreenPositionLaneMovesWithTheShift) {
  ASSERT_TRUE(context_) << "no Vulkan device: " << setupError_;
  SourceFile input{"5a5b5c5d6e6f7a7b-vs_replace.txt", {}};
  ASSERT_TRUE(readFile(std::string(MIGOTO_DUMP_DIR) + "/screen-pos-vs_replace.txt", &input.contents));
  TranspileOptions options;
  readEyeParamsFrom3DMigoto(options);
  options.eye.blockName = "stereoshift_StereoParams";
  TranspileResult converted = transpile(input, options);
  ASSERT_TRUE(converted.ok) << converted.diagnostics.format();
  ASSERT_EQ(converted.report.value("route", ""), "hlsl-source-splice");
  std::string why;
  std::optional<StageModules> stage = splicedVertexStage(input, converted, options, &why);
  ASSERT_TRUE(stage) << why;
  stage->movedLanes = {{"o3", 0, 0.5f}};
  VerifySettings settings;
  VerifyResult r = verifyStereo(*context_, {*stage}, settings);
  ASSERT_TRUE(r.error.empty()) << r.error;
  std::cout << "[verify] 3dmigoto screen-pos-vs_replace.txt: vertices " << r.vertices << ", max stereo error "
            << r.maxStereoUlps << " ULP, o3.x against mono + 0.5 * shift: " << r.maxMovedLaneUlps << " ULP over "
            << r.movedLaneComponents << " components\n";
  EXPECT_TRUE(r.monoIdentical);
  EXPECT_TRUE(r.otherOutputsUnchanged) << (r.problems.empty() ? "" : r.problems.front());
  EXPECT_LE(r.maxStereoUlps, settings.maxUlps);
  EXPECT_GT(r.movedLaneComponents, 0u);
  EXPECT_GT(r.haloComponentsChanged, 0u);
  EXPECT_LE(r.maxMovedLaneUlps, kMovedLaneUlps);
}

}  // namespace
