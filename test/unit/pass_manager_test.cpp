// The registry, --pass selection, and the context's cached analyses (computed once, dropped after a
// pass that changed the module without preserving them).
#include "passes/pass_manager.h"
#include "passes/pass_registry.h"
#include "test/unit/pass_fixture.h"

namespace stereoshift::test {
namespace {

TEST(PassRegistry, NamesAreTheFlagsAndRequirementsComeEarlier) {
  const auto& registry = passRegistry();
  ASSERT_EQ(registry.size(), 8u);
  for (size_t i = 0; i < registry.size(); ++i) {
    EXPECT_STREQ(registry[i].create()->name(), registry[i].name);
    EXPECT_EQ(findPass(registry[i].name), &registry[i]);
    for (const char* required : registry[i].requiredPasses) {
      const PassInfo* info = findPass(required);
      ASSERT_NE(info, nullptr) << registry[i].name << " requires unknown " << required;
      EXPECT_LT(info, &registry[i]) << registry[i].name << " requires " << required << ", which runs later";
    }
  }
  EXPECT_EQ(passNameList(), "clip-position-detection, hud-at-depth, single-pass-stereo, eye-params, halo, stereo-shift, "
                            "per-eye-view, deferred-unprojection");
}

TEST(PassRegistry, UnknownPassNamesTheValidOnes) {
  EXPECT_FALSE(checkPassNames({"halo", "stereo-shift"}));
  auto error = checkPassNames({"halo", "bogus"});
  ASSERT_TRUE(error);
  EXPECT_EQ(*error, "unknown --pass 'bogus' (valid: " + passNameList() + ")");
}

TEST(PassRegistry, HelpTextIsMadeFromTheEntries) {
  std::string help = passHelpText();
  for (const auto& info : passRegistry()) EXPECT_NE(help.find(std::string(info.name) + ": " + info.description), std::string::npos);
  EXPECT_NE(help.find("stereo-shift: shifts"), std::string::npos);
  EXPECT_NE(help.find("(requires clip-position-detection, eye-params)"), std::string::npos);
}

TEST(PassSelection, PullsInRequiredPassesInPipelineOrder) {
  std::vector<std::string> requiredBy;
  auto passes = selectPasses({"stereo-shift", "deferred-unprojection"}, &requiredBy);
  std::vector<std::string> names;
  for (const auto* info : passes) names.push_back(info->name);
  EXPECT_EQ(names, (std::vector<std::string>{"clip-position-detection", "eye-params", "stereo-shift",
                                              "deferred-unprojection"}));
  EXPECT_EQ(requiredBy, (std::vector<std::string>{"stereo-shift", "stereo-shift", "", ""}));
  // A pass both named and required counts as named.
  selectPasses({"halo", "eye-params"}, &requiredBy);
  EXPECT_EQ(requiredBy, (std::vector<std::string>{"halo", "", ""}));
}

// Runs `--pass names` on `assembly` and returns which analyses the context holds afterwards.
AnalysisSet cachedAfter(const std::string& assembly, std::vector<std::string> names, const ClipPositionAnalysis** seen = nullptr) {
  std::vector<uint32_t> words = spirv::assemble(assembly, nullptr);
  words[1] = 0x00010000;
  auto module = spirv::Module::parse(words, nullptr);
  TranspileOptions options = singlePassOptions();
  options.onlyPasses = std::move(names);
  SourceInfo source;
  source.language = SourceLanguage::Spirv;
  Diagnostics diags;
  nlohmann::json report;
  PassContext context{*module, options, source, diags, "test.spv", report};
  bool changed = false;
  EXPECT_TRUE(runPassPipeline(context, &changed, nullptr)) << diags.format();
  if (seen) *seen = context.clipPositionCache ? &*context.clipPositionCache : nullptr;
  return context.cachedAnalyses();
}

TEST(AnalysisCache, KeptByPassesThatPreserveThemDroppedByOthers) {
  // Detection makes the clip-position analysis (and the folded copy only where it cannot decide
  // without); eye-params changes the module but preserves it.
  EXPECT_EQ(cachedAfter(perspectiveVertexShader(false), {"eye-params"}), kClipPositionAnalysis);
  EXPECT_EQ(cachedAfter(flatVertexShader(), {"eye-params"}), kClipPositionAnalysis);
  // stereo-shift adds loads of and chains to the position: the clip-position analysis is dropped.
  EXPECT_EQ(cachedAfter(perspectiveVertexShader(false), {"stereo-shift"}) & kClipPositionAnalysis, kNoAnalyses);
}

TEST(AnalysisCache, ComputedOnceAndInvalidatedOnRequest) {
  std::vector<uint32_t> words = spirv::assemble(perspectiveVertexShader(true), nullptr);
  words[1] = 0x00010000;  // the optimizer behind the folded copy takes SPIR-V 1.0
  auto module = spirv::Module::parse(words, nullptr);
  TranspileOptions options;
  SourceInfo source;
  Diagnostics diags;
  nlohmann::json report;
  PassContext context{*module, options, source, diags, "test.spv", report};
  EXPECT_EQ(context.cachedAnalyses(), kNoAnalyses);
  const ClipPositionAnalysis* first = &clipPositions(context);
  EXPECT_EQ(&clipPositions(context), first);
  EXPECT_EQ(context.positions, first->outputs());
  ASSERT_NE(foldedCopy(context), nullptr);
  EXPECT_EQ(context.cachedAnalyses(), kAllAnalyses);
  context.invalidateAnalyses(kFoldedCopyAnalysis);
  EXPECT_EQ(context.cachedAnalyses(), kFoldedCopyAnalysis);
  context.invalidateAnalyses(kNoAnalyses);
  EXPECT_EQ(context.cachedAnalyses(), kNoAnalyses);
}

TEST(ClipPositionAnalysis, PointersAndMonoValues) {
  std::vector<uint32_t> words = spirv::assemble(perspectiveVertexShader(true), nullptr);
  auto module = spirv::Module::parse(words, nullptr);
  ClipPositionAnalysis analysis(*module);
  ASSERT_EQ(analysis.outputs().size(), 1u);
  EXPECT_TRUE(analysis.outputs()[0].isMember);
  EXPECT_EQ(analysis.outputs()[0].description, "gl_PerVertex.gl_Position");
  // %posptr and %copyptr both address gl_Position; the block variable itself does not.
  EXPECT_EQ(analysis.wholePointers(0).size(), 2u);
  EXPECT_FALSE(analysis.addressesWholePosition(analysis.outputs()[0].variable));
  EXPECT_TRUE(analysis.componentPointers(0).empty());
  // The stored %clip and the loaded %copy.
  EXPECT_EQ(analysis.monoValues().size(), 2u);

  // A change the analysis sees: one more chain to the position makes a different analysis (what
  // --validate-each compares after a pass that claims to preserve it).
  uint32_t v4Pointer = module->typePointer(spv::StorageClassOutput, module->typeVector(module->typeFloat(32), 4));
  module->functions[0].blocks[0].instructions.insert(
      module->functions[0].blocks[0].instructions.begin(),
      spirv::Instruction(spv::OpAccessChain, v4Pointer, module->takeId(),
                         {analysis.outputs()[0].variable, module->constantInt(0)}));
  module->invalidateDefinitions();
  EXPECT_FALSE(ClipPositionAnalysis(*module) == analysis);
}

TEST(NextStageFacts, OnlyWorthComputingForAStageWithAVectorSubtraction) {
  std::vector<uint32_t> words = spirv::assemble(perspectiveVertexShader(false), nullptr);
  auto module = spirv::Module::parse(words, nullptr);
  TranspileOptions options;
  EXPECT_FALSE(nextStageFactsMatter(*module, options));
  options.cameraUniform = "camera.position";
  EXPECT_TRUE(nextStageFactsMatter(*module, options));
  options.perEyeView = false;
  EXPECT_FALSE(nextStageFactsMatter(*module, options));
}

}  // namespace
}  // namespace stereoshift::test
