// Each back-end route's answer to "do you take this stage?" and why not (backend/route.h): the
// driver asks them in order, so a route that takes too much (or too little) sends a stage down
// the wrong road. The stages here are made by hand: a context with the facts each rule reads.
#include "transpiler/backend/route.h"
#include "passes/pass_registry.h"

#include "test/unit/pass_fixture.h"

#include <gtest/gtest.h>

namespace stereoshift::test {
namespace {

const BackEndRoute& route(const std::string& name) {
  for (const auto& r : routes())
    if (name == r->name()) return *r;
  ADD_FAILURE() << "no route " << name;
  return *routes().back();
}

// A stage with the facts the routes read: its language, stage, version, the eye source its
// passes chose, and which passes changed the module.
struct Stage_ {
  explicit Stage_(SourceLanguage language, Stage stage = Stage::Vertex, int version = 0, bool es = false) {
    std::vector<uint32_t> words = spirv::assemble(flatVertexShader(), nullptr);
    module = *spirv::Module::parse(words, nullptr);
    info.language = language;
    info.stage = stage;
    info.version = version;
    info.es = es;
    analyses = std::make_unique<AnalysisManager>(module, info, "t");
    context = std::make_unique<PassContext>(module, options, info, diags, "t", *analyses);
    context->eye.source = EyeSource::UniformBlock;
  }
  // As the pass manager records it: the pass's status with the kinds of edit its registry entry declares.
  void changedBy(const std::string& pass) {
    context->record.passes.push_back({pass, PassResult::Changed, "", findPass(pass)->edits});
  }
  RouteDecision ask(const std::string& name, TargetLanguage target, bool changed = true) {
    EmitRequest request{input, *context, options, target, changed};
    request.inheritedInvalid = inheritedInvalid;
    return route(name).accepts(request);
  }
  spirv::Module module;
  SourceInfo info;
  TranspileOptions options;
  Diagnostics diags;
  SourceFile input{"t", "text"};
  std::string inheritedInvalid;
  std::unique_ptr<AnalysisManager> analyses;
  std::unique_ptr<PassContext> context;
};

TEST(BackEndRoutes, AskedInThisOrderWithTheReemitLast) {
  std::vector<std::string> names;
  for (const auto& r : routes()) names.push_back(r->name());
  EXPECT_EQ(names, (std::vector<std::string>{"copy-through", "spirv", "spirv-asm", "hlsl-source-splice",
                                              "hlsl-pixel-splice", "hlsl-pixel-source-splice", "legacy-glsl-source-splice",
                                              "glsl-source-splice", "spirv-cross"}));
  EXPECT_FALSE(route("hlsl-pixel-splice").needsValidModule());
  EXPECT_FALSE(route("copy-through").needsValidModule());
  EXPECT_TRUE(route("spirv").needsValidModule());
  EXPECT_TRUE(route("hlsl-source-splice").needsOtherEntryPoints());
}

TEST(BackEndRoutes, CopyThroughOnlyWhatNeedsNothingInItsOwnLanguage) {
  Stage_ s(SourceLanguage::Glsl, Stage::Vertex, 450);
  EXPECT_EQ(s.ask("copy-through", TargetLanguage::Glsl, false).kind, RouteDecision::Accept);
  EXPECT_EQ(s.ask("copy-through", TargetLanguage::Glsl, true).kind, RouteDecision::Decline);
  EXPECT_EQ(s.ask("copy-through", TargetLanguage::Hlsl, false).kind, RouteDecision::Decline);
  s.options.targetVersion = 330;  // another version of the same language is a translation
  EXPECT_EQ(s.ask("copy-through", TargetLanguage::Glsl, false).kind, RouteDecision::Decline);
  s.options.targetVersion.reset();
  s.options.forceReemit = true;
  EXPECT_EQ(s.ask("copy-through", TargetLanguage::Glsl, false).kind, RouteDecision::Decline);
}

TEST(BackEndRoutes, SpirvRefusesAModuleTheFrontEndMadeInvalid) {
  Stage_ s(SourceLanguage::Glsl, Stage::Vertex, 330);
  EXPECT_EQ(s.ask("spirv", TargetLanguage::Glsl).kind, RouteDecision::Decline);
  EXPECT_EQ(s.ask("spirv", TargetLanguage::Spirv).kind, RouteDecision::Accept);
  EXPECT_EQ(s.ask("spirv-asm", TargetLanguage::Spirv).kind, RouteDecision::Decline);
  s.inheritedInvalid = "OpTypeBool stored";
  RouteDecision refused = s.ask("spirv-asm", TargetLanguage::SpirvAsm);
  EXPECT_EQ(refused.kind, RouteDecision::Refuse);
  EXPECT_NE(refused.why.find("does not validate (OpTypeBool stored)"), std::string::npos) << refused.why;
  // verify's harness repairs its own copy (convertOpenGLForVulkan), so only verify gets it written.
  s.options.spirvForHarness = true;
  EXPECT_EQ(s.ask("spirv-asm", TargetLanguage::SpirvAsm).kind, RouteDecision::Accept);
  EXPECT_EQ(s.ask("spirv", TargetLanguage::Spirv).kind, RouteDecision::Accept);
}

TEST(BackEndRoutes, HlslSpliceTakesVertexGeometryDomainKeptAsHlsl) {
  EXPECT_EQ(Stage_(SourceLanguage::Glsl, Stage::Vertex, 450).ask("hlsl-source-splice", TargetLanguage::Hlsl).kind,
            RouteDecision::Decline);
  EXPECT_EQ(Stage_(SourceLanguage::Hlsl, Stage::Fragment).ask("hlsl-source-splice", TargetLanguage::Hlsl).kind,
            RouteDecision::Decline);
  EXPECT_EQ(Stage_(SourceLanguage::Hlsl).ask("hlsl-source-splice", TargetLanguage::Glsl).kind, RouteDecision::Decline);
  for (Stage stage : {Stage::Vertex, Stage::Geometry, Stage::TessEvaluation})
    EXPECT_EQ(Stage_(SourceLanguage::Hlsl, stage).ask("hlsl-source-splice", TargetLanguage::Hlsl).kind, RouteDecision::Accept);
}

TEST(BackEndRoutes, HlslVertexFallsBackWithANoteGeometryIsRefused) {
  Stage_ vertex(SourceLanguage::Hlsl), geometry(SourceLanguage::Hlsl, Stage::Geometry);
  for (Stage_* s : {&vertex, &geometry}) s->context->eye.source = EyeSource::PushConstant;
  RouteDecision v = vertex.ask("hlsl-source-splice", TargetLanguage::Hlsl);
  EXPECT_EQ(v.kind, RouteDecision::Decline);
  EXPECT_TRUE(v.noted);
  EXPECT_NE(v.why.find("only as a cbuffer (--eye-source=uniform-block)"), std::string::npos) << v.why;
  RouteDecision g = geometry.ask("hlsl-source-splice", TargetLanguage::Hlsl);
  EXPECT_EQ(g.kind, RouteDecision::Refuse);
  EXPECT_NE(g.why.find("supports only --eye-source=uniform-block"), std::string::npos) << g.why;
}

TEST(BackEndRoutes, HlslSpliceCannotCarryWhatOnlyTheIrHolds) {
  Stage_ copies(SourceLanguage::Hlsl);
  copies.changedBy("halo");  // exact copies of the position: the splice shifts them in the text
  EXPECT_EQ(copies.ask("hlsl-source-splice", TargetLanguage::Hlsl).kind, RouteDecision::Accept);
  Stage_ derived(SourceLanguage::Hlsl);
  derived.changedBy("halo");
  derived.context->record.halo.derivedOutputs = {"vScreen"};
  RouteDecision d = derived.ask("hlsl-source-splice", TargetLanguage::Hlsl);
  EXPECT_EQ(d.kind, RouteDecision::Decline);
  EXPECT_NE(d.why.find("changed the output 'vScreen', which is computed from the clip position"), std::string::npos);
  Stage_ perEye(SourceLanguage::Hlsl, Stage::TessEvaluation);
  perEye.changedBy("per-eye-view");
  RouteDecision p = perEye.ask("hlsl-source-splice", TargetLanguage::Hlsl);
  EXPECT_EQ(p.kind, RouteDecision::Refuse);
  EXPECT_NE(p.why.find("it cannot carry what the per-eye-view pass changed"), std::string::npos) << p.why;
}

// The pixel-shader correction splice takes an HLSL pixel shader kept as HLSL whose deferred pass
// left text fixes, and only while nothing else changed what only the IR carries.
TEST(BackEndRoutes, HlslPixelSpliceTakesTextFixesOfPixelShadersKeptAsHlsl) {
  Stage_ s(SourceLanguage::Hlsl, Stage::Fragment);
  s.changedBy("deferred-unprojection");
  EXPECT_EQ(s.ask("hlsl-pixel-splice", TargetLanguage::Hlsl).kind, RouteDecision::Decline);  // no text fix
  s.context->record.deferred.textFixes.push_back({});
  s.context->record.deferred.fixed.push_back({});
  EXPECT_EQ(s.ask("hlsl-pixel-splice", TargetLanguage::Hlsl).kind, RouteDecision::Accept);
  EXPECT_EQ(s.ask("hlsl-pixel-splice", TargetLanguage::Glsl).kind, RouteDecision::Decline);
  // A fix the pass made in the module besides the text fixes: only the IR carries it.
  s.context->record.deferred.fixed.push_back({});
  EXPECT_EQ(s.ask("hlsl-pixel-splice", TargetLanguage::Hlsl).kind, RouteDecision::Decline);
  s.context->record.deferred.fixed.pop_back();
  s.changedBy("per-eye-view");
  EXPECT_EQ(s.ask("hlsl-pixel-splice", TargetLanguage::Hlsl).kind, RouteDecision::Decline);
  Stage_ vertex(SourceLanguage::Hlsl, Stage::Vertex);
  vertex.context->record.deferred.textFixes.push_back({});
  vertex.context->record.deferred.fixed.push_back({});
  EXPECT_EQ(vertex.ask("hlsl-pixel-splice", TargetLanguage::Hlsl).kind, RouteDecision::Decline);
}

TEST(BackEndRoutes, LegacyGlslSpliceKeepsOldVertexShadersInTheirDialect) {
  Stage_ gl120(SourceLanguage::Glsl, Stage::Vertex, 120), es100(SourceLanguage::Glsl, Stage::Vertex, 100, true);
  for (Stage_* s : {&gl120, &es100}) s->context->eye.source = EyeSource::LooseUniforms;
  EXPECT_EQ(gl120.ask("legacy-glsl-source-splice", TargetLanguage::Glsl).kind, RouteDecision::Accept);
  EXPECT_EQ(es100.ask("legacy-glsl-source-splice", TargetLanguage::Essl).kind, RouteDecision::Accept);
  EXPECT_EQ(es100.ask("legacy-glsl-source-splice", TargetLanguage::Glsl).kind, RouteDecision::Decline);
  EXPECT_EQ(Stage_(SourceLanguage::Glsl, Stage::Vertex, 330).ask("legacy-glsl-source-splice", TargetLanguage::Glsl).kind,
            RouteDecision::Decline);
  EXPECT_EQ(Stage_(SourceLanguage::Glsl, Stage::Fragment, 120).ask("legacy-glsl-source-splice", TargetLanguage::Glsl).kind,
            RouteDecision::Decline);
  gl120.options.targetVersion = 120;  // an explicit version asks for a re-emit
  EXPECT_EQ(gl120.ask("legacy-glsl-source-splice", TargetLanguage::Glsl).kind, RouteDecision::Decline);
  Stage_ block(SourceLanguage::Glsl, Stage::Vertex, 120);  // eye parameters in a block: 1xx has none
  RouteDecision refused = block.ask("legacy-glsl-source-splice", TargetLanguage::Glsl);
  EXPECT_EQ(refused.kind, RouteDecision::Refuse);
  EXPECT_NE(refused.why.find("use --eye-source loose-uniforms"), std::string::npos);
}

TEST(BackEndRoutes, GlslSpliceTakesEveryPreRasterStageKeptInItsDialect) {
  for (Stage stage : {Stage::Vertex, Stage::TessEvaluation, Stage::Geometry}) {
    Stage_ s(SourceLanguage::Glsl, stage, 330);
    s.context->shiftPosition = true;
    s.changedBy("stereo-shift");
    s.changedBy("eye-params");
    EXPECT_EQ(s.ask("glsl-source-splice", TargetLanguage::Glsl).kind, RouteDecision::Accept) << stageName(stage);
    EXPECT_EQ(s.ask("glsl-source-splice", TargetLanguage::Hlsl).kind, RouteDecision::Decline);
  }
  Stage_ es(SourceLanguage::Glsl, Stage::Vertex, 300, true);
  es.context->shiftPosition = true;
  es.changedBy("stereo-shift");
  EXPECT_EQ(es.ask("glsl-source-splice", TargetLanguage::Essl).kind, RouteDecision::Accept);
  EXPECT_EQ(es.ask("glsl-source-splice", TargetLanguage::Glsl).kind, RouteDecision::Decline);
  // Not the splice's: fragment, tessellation-control, compute and mesh stages; another version;
  // --force-reemit.
  for (Stage stage : {Stage::Fragment, Stage::TessControl, Stage::Compute, Stage::Mesh})
    EXPECT_EQ(Stage_(SourceLanguage::Glsl, stage, 450).ask("glsl-source-splice", TargetLanguage::Glsl).kind,
              RouteDecision::Decline);
  Stage_ versioned(SourceLanguage::Glsl, Stage::Vertex, 330);
  versioned.context->shiftPosition = true;
  versioned.options.targetVersion = 450;
  EXPECT_EQ(versioned.ask("glsl-source-splice", TargetLanguage::Glsl).kind, RouteDecision::Decline);
  Stage_ forced(SourceLanguage::Glsl, Stage::Vertex, 330);
  forced.context->shiftPosition = true;
  forced.options.forceReemit = true;
  EXPECT_EQ(forced.ask("glsl-source-splice", TargetLanguage::Glsl).kind, RouteDecision::Decline);
}

TEST(BackEndRoutes, GlslSpliceLeavesToTheReemitWhatOnlyTheIrCarries) {
  Stage_ perEye(SourceLanguage::Glsl, Stage::Vertex, 450);
  perEye.context->shiftPosition = true;
  perEye.changedBy("stereo-shift");
  perEye.changedBy("hud-at-depth");
  RouteDecision d = perEye.ask("glsl-source-splice", TargetLanguage::Glsl);
  EXPECT_EQ(d.kind, RouteDecision::Decline);
  EXPECT_TRUE(d.noted);
  EXPECT_NE(d.why.find("cannot carry what the hud-at-depth pass changed"), std::string::npos) << d.why;
  Stage_ multiview(SourceLanguage::Glsl, Stage::Vertex, 450);
  multiview.context->shiftPosition = true;
  multiview.options.eye.select = EyeSelect::ViewIndex;
  EXPECT_EQ(multiview.ask("glsl-source-splice", TargetLanguage::Glsl).kind, RouteDecision::Decline);
  Stage_ fused(SourceLanguage::Glsl, Stage::Vertex, 330);  // GLSL 330 has no fma
  fused.context->shiftPosition = true;
  fused.changedBy("stereo-shift");
  fused.options.fusedShift = true;
  RouteDecision f = fused.ask("glsl-source-splice", TargetLanguage::Glsl);
  EXPECT_EQ(f.kind, RouteDecision::Decline);
  EXPECT_NE(f.why.find("needs fma"), std::string::npos) << f.why;
  Stage_ declaredOnly(SourceLanguage::Glsl, Stage::Vertex, 450);  // --pass eye-params: no shift to write
  declaredOnly.context->shiftPosition = true;
  declaredOnly.changedBy("eye-params");
  EXPECT_EQ(declaredOnly.ask("glsl-source-splice", TargetLanguage::Glsl).kind, RouteDecision::Decline);
}

TEST(BackEndRoutes, ReemitTakesWhatIsLeft) {
  EXPECT_EQ(Stage_(SourceLanguage::Glsl, Stage::Fragment, 450).ask("spirv-cross", TargetLanguage::Msl).kind,
            RouteDecision::Accept);
}

TEST(BackEndRoutes, EditsBeyondWhatASpliceRenders) {
  RunRecord record;
  auto changed = [](const char* name) { return PassStatus{name, PassResult::Changed, "", findPass(name)->edits}; };
  record.passes = {changed("stereo-shift"), changed("per-eye-view"),
                   {"deferred-unprojection", PassResult::Unchanged, "", kNoEdits}, changed("halo")};
  EXPECT_EQ(record.passesWithEditsBeyond(editSet(EditKind::PositionShift)),
            (std::vector<std::string>{"halo", "per-eye-view"}));
  EXPECT_EQ(record.passesWithEditsBeyond(kGlslSpliceRenders), (std::vector<std::string>{"per-eye-view"}));
  EXPECT_TRUE(record.passesWithEditsBeyond(kGlslSpliceRenders | EditKind::PerEyeCamera).empty());
  EXPECT_TRUE(record.madeEdit(EditKind::DerivedOutputShift));
  EXPECT_FALSE(record.madeEdit(EditKind::UnprojectionCorrection));  // the pass ran and changed nothing
}

// What a stage's output can carry is decided from the routes before the passes, which read it from
// PassOutput: the HLSL geometry / domain splice carries the eye parameters and the shift only, an
// HLSL hull shader back to HLSL nothing (it is copied); any other output, or another language, all.
TEST(BackEndRoutes, OutputCapabilityFollowsTheRoutes) {
  auto decide = [](SourceLanguage language, Stage stage, TargetLanguage target) {
    SourceInfo info;
    info.language = language;
    info.stage = stage;
    PassOutput output;
    decideOutputCapability(info, target, output);
    return output;
  };
  PassOutput geometry = decide(SourceLanguage::Hlsl, Stage::Geometry, TargetLanguage::Hlsl);
  EXPECT_TRUE(geometry.canCarry(EditKind::PositionShift));
  EXPECT_FALSE(geometry.canCarry(EditKind::PerEyeCamera));
  EXPECT_FALSE(geometry.canCarry(EditKind::SinglePassEye));
  EXPECT_NE(geometry.limitedBecause.find("spliced into their own text"), std::string::npos);
  EXPECT_EQ(decide(SourceLanguage::Hlsl, Stage::TessEvaluation, TargetLanguage::Hlsl).carries, geometry.carries);
  PassOutput hull = decide(SourceLanguage::Hlsl, Stage::TessControl, TargetLanguage::Hlsl);
  EXPECT_EQ(hull.carries, kNoEdits);
  EXPECT_FALSE(hull.limitedBecause.empty());
  for (PassOutput all : {decide(SourceLanguage::Hlsl, Stage::Geometry, TargetLanguage::Spirv),
                         decide(SourceLanguage::Hlsl, Stage::Vertex, TargetLanguage::Hlsl),
                         decide(SourceLanguage::Glsl, Stage::Geometry, TargetLanguage::Glsl)}) {
    EXPECT_EQ(all.carries, kAllEdits);
    EXPECT_TRUE(all.limitedBecause.empty());
  }
}

// Every pass that can change the module says what its change is, each a kind of its own, so a route
// that renders a kind renders exactly one pass's change; detection only classifies.
TEST(BackEndRoutes, EveryChangingPassDeclaresItsEdits) {
  EditSet seen = kNoEdits;
  for (const PassInfo& info : passRegistry()) {
    if (std::string(info.name) == "clip-position-detection") {
      EXPECT_EQ(info.edits, kNoEdits);
      continue;
    }
    EXPECT_NE(info.edits, kNoEdits) << info.name;
    EXPECT_EQ(info.edits & seen, kNoEdits) << info.name << " shares a kind: " << describeEdits(info.edits & seen);
    seen |= info.edits;
  }
  EXPECT_EQ(describeEdits(seen), "eye parameters, position shift, derived-output shift, position at depth, "
                                 "single-pass eye, per-eye camera, unprojection correction");
}

}  // namespace
}  // namespace stereoshift::test
