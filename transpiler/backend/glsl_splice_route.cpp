// This turns the passes' decisions for a GLSL / ESSL vertex, tessellation-evaluation or geometry
// shader that comes back in its own dialect into the original text plus marked edits (glsl_splice.h):
// the ShiftSpec of the conversion, the eye parameters as eye-params declared them (a uniform block
// with its block, instance, set and binding; a fresh push-constant block; specialization constants;
// loose uniforms) and the halo copies. ESSL 100 / GLSL 1xx vertex shaders take the legacy route
// before this one (legacy_glsl_route.cpp): their passes ran on the analysis translation.
//
// SPIRV-Cross's re-emission of the same module is no drop-in: it flattens struct varyings, drops
// `component` layouts and extensions the source enabled, turns compatibility-profile stages into
// core ones, respells interpolation qualifiers and redeclared built-in blocks. So this route takes
// every stage it can carry; where the text cannot carry a decision (another pass's change, a halo
// output derived from the position, a shift inside an #include, an eye source it cannot declare in
// the source's version) it declines with a note and SPIRV-Cross re-emits, as before. The spliced
// text is re-compiled at the source's own version and environment; if that fails, the re-emit is
// tried too (EmitResult::declineIfChecksFail), never a text that does not compile.
#include "transpiler/backend/splice_routes.h"

#include "passes/shift_emitter.h"
#include "transpiler/backend/glsl_splice.h"
#include "transpiler/source/lexer.h"

#include <algorithm>

namespace stereoshift {

bool takesGlslSpliceRoute(const SourceInfo& info, TargetLanguage target, const BackEndOptions& options) {
  bool stage = info.stage == Stage::Vertex || info.stage == Stage::TessEvaluation || info.stage == Stage::Geometry ||
               info.stage == Stage::Fragment;  // a fragment shader for its per-eye fixes only
  return info.language == SourceLanguage::Glsl && stage &&
         target == (info.es ? TargetLanguage::Essl : TargetLanguage::Glsl) && !options.targetVersion &&
         !options.forceReemit;
}

namespace {

std::string fallbackNote(const std::string& why) {
  return "GLSL re-emitted by SPIRV-Cross instead of spliced into its own text: " + why;
}


// Whether the source enables `extension` in an #extension directive (any behaviour but disable).
bool enablesExtension(const std::string& text, const std::string& extension) {
  source::LexedText lexed(text);
  for (size_t k = 0; k < lexed.size(); ++k) {
    const source::Token& t = lexed[k];
    if (t.kind != source::TokenKind::Directive || t.directive != source::DirectiveKind::Extension) continue;
    std::string line = source::spelledString(text, t);
    if (line.find(extension) != std::string::npos && line.find("disable") == std::string::npos) return true;
  }
  return false;
}

// The eye parameters' declaration as text, and the names the shift reads them by (`spec`), from
// what eye-params declared; empty with `why` set when the source's dialect cannot declare them so.
bool renderEyeParams(const EmitRequest& r, GlslSpliceOptions& spec, std::string& why) {
  const PassContext& ctx = r.context;
  const SourceInfo& info = ctx.source;
  const EyeParamFacts& facts = ctx.record.eyeParams;
  std::vector<std::string> names = facts.names;
  if (names.size() < 3) names = {spec.eyeSignName, spec.separationName, spec.convergenceName};
  // An ESSL fragment shader's default float precision may be mediump; a uniform the vertex stage
  // declares too must have the same precision in both (highp there by default), or the program
  // does not link.
  const std::string highp = info.es && info.stage == Stage::Fragment ? "highp " : "";
  switch (ctx.eye.source) {
    case EyeSource::LooseUniforms:
      // `uniform float <name>;` (the splice's default for the three of the shift), each one declared
      // when the passes declared more (a per-eye camera's offset).
      if (facts.names.size() > 3 || !highp.empty())
        for (const auto& name : names) spec.declarations.push_back("uniform " + highp + "float " + name + ";");
      return true;
    case EyeSource::SpecConstant: {
      if (!info.vulkan) {
        why = "specialization constants exist only in Vulkan GLSL";
        return false;
      }
      for (size_t i = 0; i < names.size() && i < facts.specIds.size(); ++i)
        spec.declarations.push_back("layout(constant_id = " + std::to_string(facts.specIds[i]) + ") const float " +
                                    names[i] + " = " + glslFloatLiteral(eyeParamDefaultValue(static_cast<int>(i))) + ";");
      return true;
    }
    case EyeSource::PushConstant:
      if (ctx.eye.firstMember != 0) {
        // They join the shader's own block after its last member (eye_param_emitter.cpp): the same
        // offsets as the IR's, written out where the version has `offset` (GLSL 440), else the
        // packing's own (4-byte floats right after the last member, std430).
        const std::string instance = ctx.module.name(ctx.eye.variable);
        const bool explicitOffsets = !info.es && info.version >= 440;
        uint32_t offset = facts.pushConstantOffset.value_or(0);
        for (const auto& name : names) {
          spec.pushConstantMembers.push_back(
              (explicitOffsets ? "layout(offset = " + std::to_string(offset) + ") " : std::string()) +
              (info.es ? "highp " : "") + "float " + name + ";");
          offset += 4;
        }
        const std::string prefix = instance.empty() ? std::string() : instance + ".";
        spec.eyeSignName = prefix + names[0];
        spec.separationName = prefix + names[1];
        spec.convergenceName = prefix + names[2];
        return true;
      }
      [[fallthrough]];
    default: {
      const spirv::Module& m = ctx.module;
      std::string block = m.name(ctx.eye.blockType), instance = m.name(ctx.eye.variable);
      // Spelled as SPIRV-Cross spells the block, so the output reads the same on either route.
      std::vector<std::string> layout;
      if (ctx.eye.source == EyeSource::PushConstant) {
        layout.push_back("push_constant");
      } else {
        if (info.vulkan && facts.set) layout.push_back("set = " + std::to_string(*facts.set));
        if (facts.binding) {
          bool has420pack = info.es ? info.version >= 310 : info.version >= 420;
          if (!info.vulkan && !has420pack && !enablesExtension(r.input.contents, "GL_ARB_shading_language_420pack")) {
            why = "--gl-binding needs GLSL 420 / ESSL 310 (or GL_ARB_shading_language_420pack) for a binding layout";
            return false;
          }
          layout.push_back("binding = " + std::to_string(*facts.binding));
        }
        layout.push_back("std140");
      }
      std::string qualifiers;
      for (const auto& q : layout) qualifiers += (qualifiers.empty() ? "" : ", ") + q;
      spec.declarations.push_back("layout(" + qualifiers + ") uniform " + block);
      spec.declarations.push_back("{");
      for (const auto& name : names) spec.declarations.push_back("    " + highp + "float " + name + ";");
      spec.declarations.push_back("} " + instance + ";");
      spec.eyeSignName = instance + "." + names[0];
      spec.separationName = instance + "." + names[1];
      spec.convergenceName = instance + "." + names[2];
      return true;
    }
  }
}

// Eye parameter `which` as the splice's text reads it (`eyeOffsetX`, `stereo.eyeOffsetX`).
std::string eyeParamText(const EmitRequest& r, const GlslSpliceOptions& spec, int which) {
  const std::vector<std::string>& names = r.context.record.eyeParams.names;
  std::string name = which < static_cast<int>(names.size()) ? names[static_cast<size_t>(which)] : std::string();
  // The block's instance from separation's access (eyeSign may be multiview's expression).
  size_t dot = spec.separationName.find('.');
  return dot == std::string::npos ? name : spec.separationName.substr(0, dot + 1) + name;
}

// The per-eye cameras the passes made, as the splice writes them (glsl_splice.h); false with `why`
// set when one cannot be written in the text.
bool perEyeCameras(const EmitRequest& r, GlslSpliceOptions& spec, std::string& why) {
  const PerEyeViewFacts& facts = r.context.record.perEyeView;
  if (facts.fixed.empty()) return true;
  if (facts.cameraTexts.size() != facts.fixed.size()) {
    why = facts.cameraTextMissing.empty() ? "a per-eye camera has no name in the text" : facts.cameraTextMissing;
    return false;
  }
  const SourceInfo& info = r.context.source;
  for (const CameraText& c : facts.cameraTexts) {
    GlslSpliceOptions::CameraWrap wrap;
    wrap.access = c.access;
    wrap.type = c.components == 4 ? "vec4" : "vec3";
    wrap.function = std::string(c.inverseOf ? "stereoshift_eye_inverse_" : "stereoshift_eye_") + c.access;
    wrap.inverseOf = c.inverseOf;
    wrap.holderType = c.inverseOf ? std::string() : c.holderType;
    std::replace(wrap.function.begin(), wrap.function.end(), '.', '_');
    if (c.offset == CameraText::EyeOffsetParams) {
      wrap.offset = "vec3(" + eyeParamText(r, spec, kEyeOffsetX) + ", " + eyeParamText(r, spec, kEyeOffsetY) + ", " +
                    eyeParamText(r, spec, kEyeOffsetZ) + ")";
    } else {
      if (c.offset == CameraText::InvertedClipMatrices && !glslHasInverse(info.version, info.es)) {
        why = "the per-eye camera inverts the clip matrices, and inverse() needs GLSL 150 / ESSL 300";
        return false;
      }
      // InvVP * (e*S*C, 0, 0, 0): the clip-space direction of the shift at zero depth, in world space.
      std::string matrix;
      for (const auto& m : c.matrices) matrix += (matrix.empty() ? "" : " * ") + m;
      if (c.offset == CameraText::InvertedClipMatrices)
        matrix = "inverse(" + matrix + ")";
      else if (c.matrices.size() > 1)
        matrix = "(" + matrix + ")";
      std::string direction = "vec4((" + spec.eyeSignName + " * " + spec.separationName + ") * " +
                              spec.convergenceName + ", 0.0, 0.0, 0.0)";
      wrap.offset = (c.columnVectors ? "(" + matrix + " * " + direction + ")" : "(" + direction + " * " + matrix + ")") +
                    ".xyz";
    }
    spec.cameras.push_back(std::move(wrap));
  }
  // One struct holding two cameras: its whole reads cannot take both helpers (refused as before).
  for (auto& a : spec.cameras)
    for (auto& b : spec.cameras)
      if (&a != &b && !a.holderType.empty() && a.access.substr(0, a.access.find('.')) == b.access.substr(0, b.access.find('.')))
        a.holderType.clear(), b.holderType.clear();
  return true;
}

// The unprojections, re-projections and view rays the passes made per eye, as the splice writes
// them; false with `why` set when one of deferred-unprojection's rewrites cannot be written in the text.
bool unprojections(const EmitRequest& r, GlslSpliceOptions& spec, std::string& why) {
  const DeferredFacts& facts = r.context.record.deferred;
  if (!r.context.record.madeEdit(EditKind::UnprojectionCorrection)) return true;
  if (!facts.unprojectionTextMissing.empty() || (facts.unprojectionTexts.empty() && facts.viewRayTexts.empty())) {
    why = "the splice cannot write " +
          (facts.unprojectionTextMissing.empty() ? std::string("deferred-unprojection's fix") : facts.unprojectionTextMissing);
    return false;
  }
  for (const UnprojectionText& u : facts.unprojectionTexts) {
    auto same = std::find_if(spec.unprojections.begin(), spec.unprojections.end(),
                             [&](const GlslSpliceOptions::UnprojectionWrap& w) { return w.matrix == u.matrix; });
    if (same != spec.unprojections.end()) {
      // One matrix both unprojecting and re-projecting: the text cannot tell its products apart.
      if (same->reprojection != u.reprojection) {
        why = "the splice cannot tell the unprojections through '" + u.matrix + "' from its re-projections";
        return false;
      }
      ++same->products;
      continue;
    }
    GlslSpliceOptions::UnprojectionWrap wrap;
    wrap.matrix = u.matrix;
    wrap.reprojection = u.reprojection;
    wrap.function = (u.reprojection ? "stereoshift_reproject_" : "stereoshift_unproject_") + u.matrix;
    std::replace(wrap.function.begin(), wrap.function.end(), '.', '_');
    spec.unprojections.push_back(std::move(wrap));
  }
  for (const ViewRayText& v : facts.viewRayTexts) {
    GlslSpliceOptions::ViewRayWrap wrap;
    wrap.local = v.local;
    wrap.type = v.components == 4 ? "vec4" : "vec3";
    wrap.function = "stereoshift_view_ray_" + v.local;
    wrap.inverseScale = !v.inverseScale.empty() ? v.inverseScale : "(1.0 / " + eyeParamText(r, spec, kProjScaleX) + ")";
    if (std::any_of(spec.viewRays.begin(), spec.viewRays.end(),
                    [&](const GlslSpliceOptions::ViewRayWrap& w) { return w.local == v.local; })) {
      why = "two view rays are assigned to '" + v.local + "'";
      return false;
    }
    spec.viewRays.push_back(std::move(wrap));
  }
  return true;
}

// The halo outputs the passes shifted, as the source names them, when each is an exact copy of
// gl_Position the splice can re-copy; empty with `why` set when one is not.
bool haloCopies(const EmitRequest& r, GlslSpliceOptions& spec, std::string& why) {
  const RunRecord& record = r.context.record;
  std::vector<std::string>& copies = spec.haloCopies;
  // Outputs computed from the position: re-computed from the shifted one where the analysis says
  // how the text reads the position there (HaloFacts::DerivedText), else only the IR carries them.
  for (const auto& derived : record.halo.derivedOutputs) {
    auto text = std::find_if(record.halo.derivedTexts.begin(), record.halo.derivedTexts.end(),
                             [&](const HaloFacts::DerivedText& t) { return t.output == derived; });
    if (text == record.halo.derivedTexts.end()) {
      why = "the halo pass changed the output '" + derived +
            "', which is computed from the clip position in a way the text does not show (recomputed, or written "
            "more than once), and only the IR carries that";
      return false;
    }
    GlslSpliceOptions::DerivedHalo halo{sourceName(text->path), {}};
    for (const auto& name : text->positionNames) halo.positionNames.push_back(sourceName(name));
    spec.derivedHalos.push_back(std::move(halo));
  }
  if (!record.halo.shiftedOutputs) return true;
  std::vector<std::string> exact = exactPositionCopies(r.input.contents);
  auto add = [&](const std::string& path) {
    if (std::find(copies.begin(), copies.end(), path) == copies.end()) copies.push_back(path);
  };
  for (const auto& translated : *record.halo.shiftedOutputs) {
    if (std::find(record.halo.derivedOutputs.begin(), record.halo.derivedOutputs.end(), translated) !=
        record.halo.derivedOutputs.end())
      continue;
    std::string out = sourceName(translated);
    if (std::find(exact.begin(), exact.end(), out) != exact.end()) {
      add(out);
      continue;
    }
    // Proved a copy on the IR (equal by value to the one position value, the only store to its
    // part of the output): re-copied at the part the IR names (`surf.clip`).
    bool proved = false;
    for (const auto& copy : record.halo.exactCopies)
      if (copy.output == translated) {
        add(sourceName(copy.path));
        proved = true;
      }
    if (!proved) {
      why = "the halo copy '" + out + "' of the clip position is not a plain `" + out + " = gl_Position;` in the text";
      return false;
    }
  }
  return true;
}

class GlslSpliceRoute final : public BackEndRoute {
 public:
  const char* name() const override { return "glsl-source-splice"; }

  RouteDecision accepts(const EmitRequest& r) const override {
    const PassContext& ctx = r.context;
    if (!takesGlslSpliceRoute(ctx.source, r.target, r.options))
      return RouteDecision::decline("not a GLSL pre-rasterisation stage kept in its own dialect");
    // Multiview on Vulkan GLSL: the eye sign is gl_ViewIndex's (GL_EXT_multiview). OpenGL's
    // OVR_multiview (a num_views layout) and the instanced mode's routing stay SPIRV-Cross's.
    const bool vulkanMultiview = ctx.options.eye.select == EyeSelect::ViewIndex && ctx.source.vulkan;
    if (ctx.options.eye.select != EyeSelect::Parameter && !vulkanMultiview)
      return RouteDecision::decline(fallbackNote("the single-pass stereo modes other than Vulkan multiview are "
                                                 "written by SPIRV-Cross"),
                                    true);
    // Multiview's one change, the eye sign from the view index, is the splice's to write too.
    auto beyond = ctx.record.passesWithEditsBeyond(kGlslSpliceRenders | EditKind::PerEyeCamera |
                                                   (vulkanMultiview ? editSet(EditKind::SinglePassEye) : kNoEdits) |
                                                   EditKind::UnprojectionCorrection);
    if (!beyond.empty())
      return RouteDecision::decline(fallbackNote("the splice cannot carry what the " + beyond.front() + " pass changed"),
                                    true);
    // The splice writes the shift: only where the stereo-shift pass put one in the IR (not under
    // `--pass eye-params` alone, say).
    bool shifted = std::any_of(ctx.record.passes.begin(), ctx.record.passes.end(), [](const PassStatus& p) {
      return hasEdit(p.edits, EditKind::PositionShift);
    });
    // A stage without the shift (a fragment shader, a vertex shader before a geometry stage) takes
    // the splice for its per-eye helpers alone.
    bool helpersOnly = !shifted && (ctx.record.madeEdit(EditKind::PerEyeCamera) ||
                                    ctx.record.madeEdit(EditKind::UnprojectionCorrection));
    if ((!ctx.shiftPosition || !shifted) && !helpersOnly)
      return RouteDecision::decline(fallbackNote("the stage changed but its clip position is not shifted"), true);
    ShiftSpec spec = shiftSpec(ctx);
    if (spec.compensated)
      return RouteDecision::decline(fallbackNote("--compensated-shift is written by SPIRV-Cross"), true);
    if (spec.fused && !glslHasPreciseAndFma(ctx.source.version, ctx.source.es))
      return RouteDecision::decline(fallbackNote("--fused-shift needs fma (GLSL 400, ESSL 320)"), true);
    return RouteDecision::accept();
  }

  EmitResult emit(const EmitRequest& r, EmitFacts& facts, Diagnostics&) const override {
    EmitResult result;
    const PassContext& ctx = r.context;
    GlslSpliceOptions splice;
    static_cast<ShiftSpec&>(splice) = shiftSpec(ctx);
    splice.version = ctx.source.spliceVersionCap ? std::min(ctx.source.version, ctx.source.spliceVersionCap)
                                                 : ctx.source.version;
    splice.es = ctx.source.es;
    splice.stage = ctx.source.stage;
    if (!r.entryPointOption.empty()) splice.entryPoint = r.entryPointOption;
    std::string why;
    splice.shift = ctx.shiftPosition && ctx.record.madeEdit(EditKind::PositionShift);
    bool rendered = renderEyeParams(r, splice, why);
    if (rendered && ctx.options.eye.select == EyeSelect::ViewIndex) {
      // The eye sign the IR derives (eye_select.cpp): exactly -1 for view 0, +1 for view 1 (swapped
      // with --swap-eyes); separation and convergence stay where the eye source put them. Set
      // before the helpers are written, which read it.
      splice.eyeSignName = ctx.options.eye.swapEyes ? "(gl_ViewIndex != 0 ? -1.0 : 1.0)" : "(gl_ViewIndex != 0 ? 1.0 : -1.0)";
      if (!enablesExtension(r.input.contents, "GL_EXT_multiview")) splice.extensions.push_back("GL_EXT_multiview");
    }
    if (!rendered || !haloCopies(r, splice, why) || !perEyeCameras(r, splice, why) || !unprojections(r, splice, why)) {
      result.status = EmitResult::Declined;
      result.declinedBecause = fallbackNote(why);
      return result;
    }
    GlslSpliceResult spliced = spliceGlslStereo(r.input.contents, splice);
    if (!spliced.ok) {
      result.status = EmitResult::Declined;
      result.declinedBecause = fallbackNote(spliced.error);
      return result;
    }
    result.output = std::move(spliced.text);
    facts.route = "glsl-source-splice";
    facts.haloCopies = splice.haloCopies;
    facts.spliceSites = spliced.sites;
    // Re-compiled as a driver reads it: the source's version, profile and environment, its own
    // #include files and -D macros.
    CompileCheck check;
    check.text = result.output;
    check.stage = ctx.source.stage;
    check.vulkanSemantics = ctx.source.vulkan;
    check.includeFrom = r.input.path;
    check.entryPoint = splice.entryPoint;
    // ESSL 100 / GLSL below 330: through the front end and its analysis translation, as the input
    // was read (glslang alone lacks some of those dialects' built-ins).
    // A lifted copy's source (glsl_lift.h) likewise: glslang accepts only the lifted form of it.
    check.throughFrontEnd =
        isLegacyGlslDialect(ctx.source) || !ctx.source.liftedBecause.empty() || ctx.source.versionPrepended;
    check.failure = "the spliced GLSL does not compile at the source's version";
    result.checks.push_back(std::move(check));
    result.declineIfChecksFail = true;
    result.reportsVerified = true;
    result.status = EmitResult::Emitted;
    return result;
  }
};

}  // namespace

std::unique_ptr<BackEndRoute> createGlslSpliceRoute() { return std::make_unique<GlslSpliceRoute>(); }

}  // namespace stereoshift
