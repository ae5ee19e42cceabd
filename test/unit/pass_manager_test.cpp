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

// Runs `--pass names` on `assembly` and returns which analyses the manager holds afterwards.
AnalysisSet cachedAfter(const std::string& assembly, std::vector<std::string> names) {
  std::vector<uint32_t> words = spirv::assemble(assembly, nullptr);
  words[1] = 0x00010000;
  auto module = spirv::Module::parse(words, nullptr);
  TranspileOptions options = singlePassOptions();
  options.onlyPasses = std::move(names);
  SourceInfo source;
  source.language = SourceLanguage::Spirv;
  Diagnostics diags;
  AnalysisManager analyses(*module, source, "test.spv");
  PassContext context{*module, options, source, diags, "test.spv", analyses};
  bool changed = false;
  EXPECT_TRUE(runPassPipeline(context, &changed, nullptr)) << diags.format();
  return analyses.cached();
}

TEST(AnalysisManager, KeptByPassesThatPreserveThemDroppedByOthers) {
  // Detection makes the clip-position analysis (and the folded copy only where it cannot decide
  // without); eye-params changes the module but preserves it.
  EXPECT_EQ(cachedAfter(perspectiveVertexShader(false), {"eye-params"}), kClipPositionAnalysis);
  EXPECT_EQ(cachedAfter(flatVertexShader(), {"eye-params"}), kClipPositionAnalysis);
  // stereo-shift adds loads of and chains to the position: the clip-position analysis is dropped.
  EXPECT_EQ(cachedAfter(perspectiveVertexShader(false), {"stereo-shift"}) & kClipPositionAnalysis, kNoAnalyses);
  // halo numbers the module's values and then rewrites stores: the value numbers go with it.
  EXPECT_EQ(cachedAfter(perspectiveVertexShader(true), {"halo"}) & kValueNumberAnalysis, kNoAnalyses);
}

struct ManagedModule {
  explicit ManagedModule(const std::string& assembly) {
    if (auto parsed = assembleModule(assembly)) module = std::move(*parsed);
    source.language = SourceLanguage::Spirv;
  }
  spirv::Module module;
  SourceInfo source;
};

TEST(AnalysisManager, ComputedOnceAndInvalidatedOnRequest) {
  ManagedModule m(perspectiveVertexShader(true));
  AnalysisManager analyses(m.module, m.source, "test.spv");
  EXPECT_EQ(analyses.cached(), kNoAnalyses);
  const ClipPositionAnalysis* first = &analyses.clipPositions();
  EXPECT_EQ(&analyses.clipPositions(), first);
  const spirv::Module* folded = analyses.foldedCopy();
  ASSERT_NE(folded, nullptr);
  EXPECT_EQ(analyses.foldedCopy(), folded);
  EXPECT_EQ(&analyses.valueFlow(), &analyses.valueFlow());
  EXPECT_EQ(&analyses.valueNumbers(), &analyses.valueNumbers());
  const NextStageFacts* inputs = &analyses.stageInputUses();
  EXPECT_EQ(&analyses.stageInputUses(), inputs);
  EXPECT_EQ(analyses.cached(), kAllAnalyses);
  analyses.invalidate(kFoldedCopyAnalysis | kValueFlowAnalysis);
  EXPECT_EQ(analyses.cached(), kFoldedCopyAnalysis | kValueFlowAnalysis);
  EXPECT_EQ(analyses.foldedCopy(), folded);  // kept: the very same copy
  analyses.invalidate(kNoAnalyses);
  EXPECT_EQ(analyses.cached(), kNoAnalyses);
  EXPECT_NE(analyses.foldedCopy(), nullptr);  // made again on the next request
  EXPECT_EQ(analyses.cached(), kFoldedCopyAnalysis);
}

TEST(AnalysisManager, ViewVectorFlowLivesAndDiesWithTheFoldedCopy) {
  ManagedModule m(perspectiveVertexShader(false));
  AnalysisManager analyses(m.module, m.source, "test.spv");
  analysis::ViewVectorFlow* flow = analyses.foldedViewVectorFlow();
  ASSERT_NE(flow, nullptr);
  EXPECT_EQ(&flow->module(), analyses.foldedCopy());
  EXPECT_EQ(analyses.foldedViewVectorFlow(), flow);
  analyses.invalidate(kAllAnalyses & ~kFoldedCopyAnalysis);
  EXPECT_EQ(analyses.cached() & kFoldedCopyAnalysis, kNoAnalyses);
  EXPECT_NE(analyses.foldedViewVectorFlow(), nullptr);
}

// HLSL's entry point is a helper the wrapper calls: the folded copy inlines it and keeps only the
// entry point (a dead copy of the helper beside it made SPIRV-Tools' SSA rewrite quadratic in the
// helper's statements), and keeps it names its values by.
TEST(AnalysisManager, TheFoldedCopyKeepsOnlyWhatTheEntryPointReaches) {
  ManagedModule m(R"(
               OpCapability Shader
               OpMemoryModel Logical GLSL450
               OpEntryPoint Vertex %main "main" %inPos %outPos
               OpName %helper "@main("
               OpName %local "x"
               OpName %kept "kept"
               OpDecorate %inPos Location 0
               OpDecorate %outPos BuiltIn Position
               OpDecorate %local RelaxedPrecision
       %void = OpTypeVoid
     %fnVoid = OpTypeFunction %void
      %float = OpTypeFloat 32
         %v4 = OpTypeVector %float 4
        %pIn = OpTypePointer Input %v4
       %pOut = OpTypePointer Output %v4
       %pFun = OpTypePointer Function %v4
       %fnV4 = OpTypeFunction %v4
      %inPos = OpVariable %pIn Input
     %outPos = OpVariable %pOut Output
       %main = OpFunction %void None %fnVoid
      %entry = OpLabel
       %kept = OpFunctionCall %v4 %helper
               OpStore %outPos %kept
               OpReturn
               OpFunctionEnd
     %helper = OpFunction %v4 None %fnV4
       %body = OpLabel
      %local = OpVariable %pFun Function
          %p = OpLoad %v4 %inPos
               OpStore %local %p
          %q = OpLoad %v4 %local
         %pq = OpFAdd %v4 %q %p
               OpStore %local %pq
          %r = OpLoad %v4 %local
               OpReturnValue %r
               OpFunctionEnd
)");
  AnalysisManager analyses(m.module, m.source, "test.vert.hlsl");
  const spirv::Module* folded = analyses.foldedCopy();
  ASSERT_NE(folded, nullptr);
  ASSERT_EQ(folded->functions.size(), 1u);
  EXPECT_EQ(folded->functions[0].id(), m.module.entryPoints[0].operand(1));
  for (const auto& name : folded->debugNames) EXPECT_NE(name.stringOperand(1), "@main(");
  std::string text = spirv::disassemble(folded->encode());
  EXPECT_EQ(text.find("OpLoad %v4float %x"), std::string::npos) << text;  // the local is SSA values now
  EXPECT_NE(text.find("OpFAdd"), std::string::npos) << text;
}

// --validate-each checks every claim a pass makes about what it preserved.
TEST(AnalysisManager, CheckPreservedCatchesEachStaleAnalysis) {
  ManagedModule m(perspectiveVertexShader(true));
  AnalysisManager analyses(m.module, m.source, "test.spv");
  analyses.clipPositions();
  analyses.foldedCopy();
  analyses.valueFlow();
  analyses.stageInputUses();
  EXPECT_EQ(analyses.checkPreserved(kAllAnalyses), "");
  // One more chain to the position: a different clip-position analysis, and new instructions the
  // value-flow index does not hold.
  auto& block = m.module.functions[0].blocks[0].instructions;
  uint32_t v4Pointer = m.module.typePointer(spv::StorageClassOutput, m.module.typeVector(m.module.typeFloat(32), 4));
  block.insert(block.begin(), spirv::Instruction(spv::OpAccessChain, v4Pointer, m.module.takeId(),
                                                 {analyses.clipPositions().outputs()[0].variable, m.module.constantInt(0)}));
  m.module.invalidateDefinitions();
  EXPECT_EQ(analyses.checkPreserved(kClipPositionAnalysis), "clip-positions");
  EXPECT_EQ(analyses.checkPreserved(kValueFlowAnalysis), "value-flow");
  EXPECT_EQ(analyses.checkPreserved(kFoldedCopyAnalysis), "");  // every global the copy names is still there
  // A global the copy names removed: the copy no longer answers for this module.
  ManagedModule n(perspectiveVertexShader(false));
  AnalysisManager other(n.module, n.source, "test.spv");
  ASSERT_NE(other.foldedCopy(), nullptr);
  for (auto& inst : n.module.typesValues)
    if (inst.opcode == spv::OpVariable && inst.operand(0) == spv::StorageClassUniform) inst.resultId = n.module.takeId();
  n.module.invalidateDefinitions();
  EXPECT_EQ(other.checkPreserved(kFoldedCopyAnalysis), "folded-copy");
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
