// per-eye-view: turns the mono camera position that feeds view vectors into the per-eye centre
//     C_eye = C + InvVP * (eyeSign*separation*convergence, 0, 0, 0)      (docs/stereo-math.md section 3)
// wherever a view vector offsets texture coordinates (relief / parallax occlusion / steep / cone
// mapping, reflection lookups), so each eye sees the surface relief from its own position.
//
// Detection is by data flow (analysis/view_vector_flow.h, on the forward engine of
// analysis/value_flow.h) on the shared folded copy (helpers inlined, loops in SSA form):
//   1. a candidate is `C - P` or `P - C` where C is a vec3/vec4 uniform or push-constant value (a
//      "slot": variable plus constant member indices) and P varies per vertex/pixel (it depends on
//      a stage input);
//   2. its value is followed forward (through arithmetic, phis and local variables) and tagged when
//      it becomes a direction (normalize, reflect/refract, v.xy / v.z) and when it is multiplied by
//      a tangent frame (a matrix built from per-vertex vectors, or an interpolated one);
//   3. the slot is the camera when a *direction* derived from it reaches the coordinate operand of
//      a texture sample in this stage, or when it is written to an output that the next stage
//      steps texture coordinates along (pipeline facts from transpilePipeline()), or, with no such
//      facts, when the output is a tangent-space vector and the uniform's name says camera/eye.
// Names are hints only: a camera-like name is needed where structure cannot decide (a vertex
// shader alone, specular-only uses with --per-eye-specular); a light-like name vetoes (a POM
// self-shadowing ray marches toward the light and must stay mono). --camera-uniform forces.
//
// The fix rewrites every load of the camera slot: the load keeps its place under a fresh id and
// the old id now names `loaded + offset`, so every use sees C_eye. The offset comes, in this order,
// from an inverse view-projection matrix the camera's block already carries (by name), from the
// matrices that take the same world point to the clip position (structure; inverted in the
// shader), or from three eye-offset parameters the application fills (include/stereoshift/
// The offset and the rewrite live in per_eye_view/eye_offset.h; the next-stage facts in
// analysis/stage_interface.h; names in per_eye_view/name_hints.h.
#include "passes/analysis/stage_interface.h"
#include "passes/analysis/uniform_slots.h"
#include "passes/analysis/view_vector_flow.h"
#include "passes/eye_param_emitter.h"
#include "passes/ir/walker.h"
#include "passes/pass.h"
#include "passes/pass_registry.h"
#include "passes/per_eye_view/eye_offset.h"
#include "passes/per_eye_view/name_hints.h"

#include <algorithm>
#include <map>
#include <set>

namespace stereoshift {

using spirv::Instruction;
using spirv::Module;
using namespace analysis;
using namespace per_eye_view;

namespace {

// Every `C - P` / `P - C` with C a camera-like uniform slot and P varying per vertex / pixel.
std::map<Slot, std::vector<Subtraction>> findSubtractions(ViewVectorFlow& flow) {
  const Module& m = flow.module();
  std::map<Slot, std::vector<Subtraction>> found;
  spirv::forEachFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode != spv::OpFSub) return;
    const Instruction* type = m.definition(inst.typeId);
    if (!type || type->opcode != spv::OpTypeVector || type->operand(1) < 3) return;
    for (int side = 0; side < 2; ++side) {
      auto slot = cameraSide(m, inst.operand(side));
      uint32_t other = inst.operand(1 - side);
      if (slot && !cameraSide(m, other) && flow.dependsOnInput(other)) found[*slot].push_back({inst.resultId, other});
    }
  });
  return found;
}

// Values of the folded module that are a camera-like uniform (a vec3/vec4 slot, a member of a
// whole-struct load, inverse(view)[3]), by slot, for slots not already found in a subtraction.
std::map<Slot, std::vector<uint32_t>> cameraValuesOutsideSubtractions(const Module& f,
                                                                      const std::map<Slot, std::vector<Subtraction>>& subtractions) {
  std::map<Slot, std::vector<uint32_t>> found;
  spirv::forEachFunctionInstruction(f, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (!inst.resultId) return;
    if (auto slot = cameraSide(f, inst.resultId); slot && !subtractions.count(*slot)) found[*slot].push_back(inst.resultId);
  });
  return found;
}

std::string joined(const std::vector<std::string>& list) {
  std::string text;
  for (const auto& s : list) text += (text.empty() ? "" : ", ") + s;
  return text;
}

ViewDependentUse note(const std::string& uniform, NameHint hint, const std::string& use, const std::string& reason) {
  ViewDependentUse entry;
  entry.uniform = uniform;
  entry.nameHint = hintName(hint);
  entry.use = use;
  entry.reason = reason;
  return entry;
}

using Cameras = std::map<Slot, std::string>;  // slot -> why it is the camera

// Where the outputs a camera subtraction reaches go: what the next stage does with them, or the
// single-shader hint.
struct OutputUses {
  std::vector<std::string> offset, shaded, unknownTangent, unknown;
};

OutputUses useOfOutputs(const PassContext& ctx, const Module& folded, const ViewVectorFlow::Sinks& sinks) {
  OutputUses uses;
  bool fragment = folded.executionModel() == spv::ExecutionModelFragment;
  for (const auto& [output, f] : sinks.outputs) {
    InterfaceSlot written = interfaceSlot(folded, output.variable, output.member);
    if (written.builtin) continue;
    const std::string& outputName = written.display;
    const StageInputUse* use = consumerOf(ctx.nextStage, folded, output);
    if (fragment) {
      uses.shaded.push_back(outputName);  // a colour: nothing after it samples along it
    } else if (use && use->read) {
      bool offsets = (f & kDirection) ? use->feedsTexcoord : use->feedsTexcoordAsDirection;
      (offsets ? uses.offset : uses.shaded).push_back(outputName);
    } else if (f & kTangent) {
      uses.unknownTangent.push_back(outputName);
    } else {
      uses.unknown.push_back(outputName);
    }
  }
  return uses;
}

// How many elements of the array `slot` is an element of are subtracted from a varying point
// (`slot` included); 0 when its last index is not an array's (a loose uniform, a struct member).
size_t arrayElementsSubtracted(const Module& m, const Slot& slot, const std::map<Slot, std::vector<Subtraction>>& all) {
  if (slot.indices.empty() || slot.inverseTranslation) return 0;
  uint32_t type = m.pointeeType(m.definition(slot.variable)->typeId);
  for (size_t k = 0; k + 1 < slot.indices.size(); ++k) {
    const Instruction* def = m.definition(type);
    if (!def) return 0;
    type = def->opcode == spv::OpTypeStruct ? def->operand(slot.indices[k]) : def->operand(0);
  }
  const Instruction* container = m.definition(type);
  if (!container || container->opcode != spv::OpTypeArray) return 0;
  size_t count = 0;
  for (const auto& entry : all) {
    const Slot& other = entry.first;
    count += other.variable == slot.variable && !other.inverseTranslation && other.indices.size() == slot.indices.size() &&
             std::equal(other.indices.begin(), other.indices.end() - 1, slot.indices.begin());
  }
  return count;
}

// The decision for one uniform a view vector is subtracted from: the camera (with the reason), or
// left alone (with what it is used for and why). `all`: every slot's subtractions.
void decideSlot(const PassContext& ctx, ViewVectorFlow& flow, const Slot& slot, const std::vector<Subtraction>& subs,
                const std::map<Slot, std::vector<Subtraction>>& all, Cameras& cameras,
                std::vector<ViewDependentUse>& leftAlone) {
  const Module& folded = flow.module();
  std::string name = slotName(folded, slot);
  NameHint hint = nameHint(name);
  std::map<uint32_t, uint8_t> seeds;
  for (const auto& s : subs) seeds[s.id] = kDerived;
  auto sinks = flow.follow(seeds);
  auto leave = [&](const std::string& use, const std::string& reason) { leftAlone.push_back(note(name, hint, use, reason)); };
  if (slotMatchesName(folded, slot, ctx.options.cameraUniform)) {
    cameras[slot] = "forced by --camera-uniform";
    return;
  }
  // There is one camera: several elements of one array each subtracted from the surface point
  // are points of the scene (an area light's polygon, a set of lights or probes), whatever a
  // direction from them then reaches.
  if (size_t points = arrayElementsSubtracted(folded, slot, all); points >= 2) {
    leave("one of " + std::to_string(points) + " elements of an array each subtracted from the surface point",
          "points of the scene (an area light's polygon, lights, probes), not the one camera; --camera-uniform forces it");
    return;
  }
  bool offsetsHere = sinks.texcoord & kOffset;
  // A coordinate computed from the direction without moving another one along it: a BRDF table
  // at dot(N, V), an environment map along reflect(-V, N). Shading, mono by default.
  bool looksUpAlong = !offsetsHere && (sinks.texcoord & kDirection);
  OutputUses outputs = useOfOutputs(ctx, folded, sinks);
  if (hint == NameHint::Light && (offsetsHere || !outputs.offset.empty() || !outputs.unknownTangent.empty())) {
    leave(offsetsHere || !outputs.offset.empty() ? "direction that offsets texture coordinates" : "tangent-space vector output",
          "the name says light (a relief self-shadowing ray marches toward the light): not a view vector; "
          "--camera-uniform forces it");
    return;
  }
  if (offsetsHere) {
    cameras[slot] = "structure: a direction from it offsets texture coordinates in this stage" +
                    std::string(hint == NameHint::Camera ? " (the name agrees)" : "");
    return;
  }
  if (!outputs.offset.empty()) {
    cameras[slot] = "structure across stages: " + joined(outputs.offset) + " is read by " + ctx.nextStage->file +
                    " to offset texture coordinates";
    return;
  }
  if (!outputs.unknownTangent.empty() && hint == NameHint::Camera) {
    cameras[slot] = "structure + name hint: a tangent-space vector from it is written to " + joined(outputs.unknownTangent) +
                    (ctx.nextStage ? " (which " + ctx.nextStage->file + " does not read)"
                                   : " (single-shader mode: the next stage is not known)") +
                    " and the name says camera";
    return;
  }
  bool shadingOnly = sinks.texcoord == 0 && outputs.unknown.empty() && outputs.unknownTangent.empty();
  if (shadingOnly && hint == NameHint::Camera && ctx.options.perEyeSpecular) {
    cameras[slot] = "--per-eye-specular: the view vector only shades, and the name says camera";
    return;
  }
  if (looksUpAlong && hint != NameHint::Light && ctx.options.perEyeSpecular) {
    cameras[slot] = "--per-eye-specular: a texture is looked up along a direction from it (reflection, BRDF table)";
    return;
  }
  if (looksUpAlong && hint != NameHint::Light) {
    leave("texture looked up along a direction from it (reflection, BRDF table), no texture coordinate moved along it",
          "a lookup, not relief mapping: reflections and specular terms stay mono by default (no new application "
          "parameters); --per-eye-specular makes them per-eye");
    return;
  }
  if (hint == NameHint::Light) {
    leave("light vector", "the name says light: not view-dependent");
  } else if (!outputs.unknown.empty() || !outputs.unknownTangent.empty()) {
    std::vector<std::string> all = outputs.unknown;
    all.insert(all.end(), outputs.unknownTangent.begin(), outputs.unknownTangent.end());
    leave("vector written to " + joined(all),
          "the next stage is not known to offset texture coordinates with it" +
              std::string(outputs.unknownTangent.empty() ? "" : " and the name does not say camera") +
              ": convert the pipeline together (--pipeline) or force with --camera-uniform");
  } else if (sinks.texcoord) {
    leave("texture coordinate computed from the difference without making it a direction",
          "a position-dependent lookup (volume, projector), not a view vector");
  } else if (hint == NameHint::Camera) {
    leave(outputs.shaded.empty() ? "shading only (specular)" : "shading only (specular), written to " + joined(outputs.shaded),
          "specular highlights look right with the mono eye (docs/stereo-math.md section 3); --per-eye-specular makes it per-eye");
  } else {
    leave("direction used for shading only", "not known to be a camera (no texture-coordinate offset, no camera-like name)");
  }
}

// A forced camera that takes part in no subtraction is still replaced everywhere it is loaded.
void findForcedCamera(PassContext& ctx, const Module& folded, Cameras& cameras) {
  const std::string& forcedName = ctx.options.cameraUniform;
  if (forcedName.empty()) return;
  bool found = false;
  for (const auto& [slot, why] : cameras) found |= slotMatchesName(folded, slot, forcedName);
  if (!found)
    spirv::forEachFunctionInstruction(folded, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
      if (inst.opcode != spv::OpLoad) return;
      if (auto slot = cameraSide(folded, inst.resultId); slot && slotMatchesName(folded, *slot, forcedName)) {
        cameras[*slot] = "forced by --camera-uniform";
        found = true;
      }
    });
  if (!found) {
    ctx.diags.warning(ctx.file, "--camera-uniform '" + forcedName + "': no vec3/vec4 uniform of that name is read in this shader");
    ctx.record.perEyeView.forcedCameraNotFound = forcedName;
  }
}

// The tutorial form: the camera position itself goes to an output (`TangentViewPos = TBN *
// viewPos`, beside `TangentFragPos = TBN * FragPos`) and the next stage subtracts it from another
// input and moves texture coordinates along the difference. With the pipeline's facts that is
// structure enough; a shader converted alone cannot tell relief mapping from a specular term
// (the normal-mapping tutorials write the same vertex shader), so it is reported, not guessed.
void decidePassedCameras(const PassContext& ctx, ViewVectorFlow& flow,
                         const std::map<Slot, std::vector<Subtraction>>& subtractions, Cameras& cameras,
                         std::vector<ViewDependentUse>& leftAlone) {
  const Module& f = flow.module();
  if (f.executionModel() == spv::ExecutionModelFragment) return;  // its outputs are colours
  for (const auto& [slot, values] : cameraValuesOutsideSubtractions(f, subtractions)) {
    if (cameras.count(slot)) continue;
    std::string name = slotName(f, slot);
    NameHint hint = slot.inverseTranslation ? NameHint::Camera : nameHint(name);
    std::map<uint32_t, uint8_t> seeds;
    for (uint32_t v : values) seeds[v] = kDerived;
    auto sinks = flow.follow(seeds);
    std::vector<std::string> subtractedThere, notKnown, shadingThere;
    bool tangent = false;
    for (const auto& [output, flags] : sinks.outputs) {
      InterfaceSlot written = interfaceSlot(f, output.variable, output.member);
      if (written.builtin) continue;
      const StageInputUse* use = consumerOf(ctx.nextStage, f, output);
      tangent |= (flags & kTangent) != 0;
      if (!ctx.nextStage) notKnown.push_back(written.display);
      else if (use && use->read && !(flags & kDirection) && use->subtractedForOffset)  // a point, not a direction
        subtractedThere.push_back(written.display);
      else shadingThere.push_back(written.display);
    }
    if (hint == NameHint::Light) {
      if (subtractedThere.empty()) continue;  // a light position passed on for lighting: nothing to say
      leftAlone.push_back(note(name, hint, "position written to " + joined(subtractedThere) + ", which the next stage marches along",
                               "the name says light (a relief self-shadowing ray marches toward the light): not a view "
                               "vector; --camera-uniform forces it"));
      continue;
    }
    if (!subtractedThere.empty()) {
      cameras[slot] = "structure across stages: the camera position goes to " + joined(subtractedThere) + ", which " +
                      ctx.nextStage->file + " subtracts from another input and moves texture coordinates along";
      continue;
    }
    if (!notKnown.empty() && (hint == NameHint::Camera || tangent)) {
      leftAlone.push_back(note(name, hint, std::string(tangent ? "tangent-space " : "") + "camera position written to " + joined(notKnown),
                               "camera position passed to the next stage; convert the pipeline to decide (--pipeline, or "
                               "--camera-uniform to force): relief mapping needs it per eye, normal-mapped specular does not"));
    } else if (!shadingThere.empty() && hint == NameHint::Camera) {
      leftAlone.push_back(note(name, hint, "camera position written to " + joined(shadingThere),
                               ctx.nextStage->file + " does not move texture coordinates along it (shading, a lookup): mono"));
    }
  }
}

// View-dependent things this pass does not change, so a user knows what to check by eye: a
// camera-like uniform used outside any view vector (fog, LOD distance), gl_FragCoord effects.
void noteOtherViewDependentUses(const Module& f, const std::map<Slot, std::vector<Subtraction>>& subtractions,
                                const Cameras& cameras, std::vector<ViewDependentUse>& leftAlone) {
  std::set<Slot> noted;
  spirv::forEachFunctionInstruction(f, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode != spv::OpLoad) return;
    auto slot = cameraSide(f, inst.resultId);
    if (!slot || subtractions.count(*slot) || cameras.count(*slot) || noted.count(*slot)) return;
    std::string name = slotName(f, *slot);
    if (nameHint(name) != NameHint::Camera) return;
    noted.insert(*slot);
    for (const auto& entry : leftAlone)
      if (entry.uniform == name) return;  // already said what it does
    ViewDependentUse entry;
    entry.uniform = name;
    entry.use = "distance or other maths, no view vector (fog, level of detail)";
    entry.reason = "the eyes differ by a fraction of the interaxial: mono keeps both eyes alike";
    leftAlone.push_back(entry);
  });
  for (uint32_t id : f.entryInterface())
    if (f.decorationValue(id, spv::DecorationBuiltIn) == uint32_t(spv::BuiltInFragCoord)) {
      bool read = spirv::anyFunctionInstruction(f, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
        return inst.opcode == spv::OpLoad && f.rootVariable(inst.operand(0)) == id;
      });
      if (!read) continue;
      ViewDependentUse entry;
      entry.construct = "gl_FragCoord";
      entry.use = "screen-position effect";
      entry.reason = "pixel positions are already per eye; an effect that maps them back to the "
                     "world with mono matrices needs deferred-unprojection or a check by eye";
      leftAlone.push_back(entry);
    }
}

// Outputs that will differ between the eyes once the cameras are per eye (by design, like the
// shifted position): for the report, and for the execution harness's unchanged-outputs check.
std::set<std::string> perEyeOutputs(const Module& folded, ViewVectorFlow& flow, const Cameras& cameras) {
  std::set<std::string> outputs;
  for (const auto& camera : cameras) {
    const auto& slot = camera.first;  // a named reference: clang 14 cannot capture structured bindings
    std::map<uint32_t, uint8_t> loads;
    spirv::forEachFunctionInstruction(folded, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
      if (auto loaded = inst.opcode == spv::OpLoad ? slotOfPointer(folded, inst.operand(0)) : std::nullopt;
          loaded && loaded->variable == slot.variable && loaded->indices.size() >= slot.indices.size() &&
          std::equal(slot.indices.begin(), slot.indices.end(), loaded->indices.begin()))
        loads[inst.resultId] = kDerived;
      if (auto read = inst.resultId ? valueSlot(folded, inst.resultId) : std::nullopt; read && *read == slot)
        loads[inst.resultId] = kDerived;  // a member of a whole-struct load, inverse(view)[3]
    });
    for (const auto& [output, f] : flow.follow(loads, /*throughSamples=*/true).outputs)
      if (InterfaceSlot written = interfaceSlot(folded, output.variable, output.member); !written.builtin && !written.name.empty())
        outputs.insert(written.display);
  }
  return outputs;
}

class PerEyeViewPass final : public Pass {
 public:
  const char* name() const override { return "per-eye-view"; }

  PassResult run(PassContext& ctx) override {
    if (!ctx.options.perEyeView) return PassResult::Unchanged;
    PerEyeViewFacts& facts = ctx.record.perEyeView;
    // Already stereo (an earlier run, or the application's own parameters): never twice.
    if (std::string why = ctx.eyeDeclared ? "" : alreadyStereoReason(ctx);
        ctx.classification == Classification::AlreadyStereo || !why.empty()) {
      facts.skipped = "the shader " + (why.empty() ? std::string("is stereo already") : why);
      return PassResult::Unchanged;
    }
    // Cheap first: a view vector needs a vec3/vec4 subtraction somewhere in the module (inlining
    // and folding never create one), and most shaders have none; the folded copy costs an
    // optimizer run.
    if (ctx.options.cameraUniform.empty() && !hasVectorSubtraction(ctx.module) && !passesCameraCandidate(ctx.module))
      return PassResult::Unchanged;
    ViewVectorFlow* flow = ctx.analyses.foldedViewVectorFlow();
    if (!flow) {
      facts.skipped = "the optimizer could not inline and fold this module; nothing analysed";
      return PassResult::Unchanged;
    }
    const Module& folded = flow->module();
    auto subtractions = findSubtractions(*flow);
    Cameras cameras;
    for (const auto& [slot, subs] : subtractions) decideSlot(ctx, *flow, slot, subs, subtractions, cameras, facts.leftAlone);
    findForcedCamera(ctx, folded, cameras);
    decidePassedCameras(ctx, *flow, subtractions, cameras, facts.leftAlone);
    noteOtherViewDependentUses(folded, subtractions, cameras, facts.leftAlone);
    if (cameras.empty()) return PassResult::Unchanged;
    // An output that cannot carry the fix (the stage's own text with the shift spliced in) would
    // lose a module change silently.
    if (!ctx.output.canCarry(EditKind::PerEyeCamera)) {
      for (const auto& [slot, why] : cameras) {
        ViewDependentUse entry;
        entry.uniform = slotName(folded, slot);
        entry.use = "view vector";
        entry.reason = ctx.output.limitedBecause + ", which cannot carry this fix: fix the camera by hand";
        facts.leftAlone.push_back(entry);
      }
      return PassResult::Unchanged;
    }
    return fixCameras(ctx, folded, *flow, subtractions, cameras);
  }

 private:
  // CameraText::holderType: the name of the plain struct the access starts with, if it does.
  static std::string holderTypeName(const Module& m, const Slot& slot) {
    const Instruction* variable = m.definition(slot.variable);
    if (!variable || slot.indices.empty()) return {};
    uint32_t type = m.pointeeType(variable->typeId);
    if (m.name(slot.variable).empty()) {  // an anonymous block: the text starts at its member
      const Instruction* block = m.definition(type);
      if (!block || block->opcode != spv::OpTypeStruct || slot.indices.size() < 2 ||
          slot.indices[0] >= block->operands.size())
        return {};
      type = block->operand(slot.indices[0]);
    }
    const Instruction* holder = m.definition(type);
    if (!holder || holder->opcode != spv::OpTypeStruct || m.hasDecoration(type, spv::DecorationBlock) ||
        m.hasDecoration(type, spv::DecorationBufferBlock))
      return {};
    std::string name = m.name(type);
    return name.starts_with("gl_") || name.find("stereoshift_") != std::string::npos ? std::string() : name;
  }

  // The camera and its offset as the source text names them, for a splice (run_record.h).
  static void recordCameraText(const Module& m, const Slot& camera, const OffsetSource& source, PerEyeViewFacts& facts) {
    CameraText text;
    // inverse(view)[3]: the text names the matrix; its inverse is what the splice moves.
    Slot named = camera;
    named.inverseTranslation = false;
    text.inverseOf = camera.inverseTranslation;
    auto access = slotSourceAccess(m, named);
    const Instruction* type = m.definition(slotType(m, camera));
    if (!access || !type || type->opcode != spv::OpTypeVector) {
      facts.cameraTextMissing = "the camera " + slotName(m, camera) + " has no name the source reads it by";
      return;
    }
    text.access = *access;
    text.components = type->operand(1);
    text.holderType = holderTypeName(m, named);
    text.offset = source.kind == OffsetSource::InverseViewProjection ? CameraText::InverseViewProjection
                  : source.kind == OffsetSource::InvertedClipMatrices ? CameraText::InvertedClipMatrices
                                                                      : CameraText::EyeOffsetParams;
    text.columnVectors = source.columnVectors;
    for (const Slot& matrix : source.matrices) {
      auto named = slotSourceAccess(m, matrix);
      if (!named) {
        facts.cameraTextMissing = "the matrix " + slotName(m, matrix) + " has no name the source reads it by";
        return;
      }
      text.matrices.push_back(*named);
    }
    facts.cameraTexts.push_back(std::move(text));
  }

  // Each camera's loads become the per-eye centre; the module changes from here on.
  static PassResult fixCameras(PassContext& ctx, const Module& folded, ViewVectorFlow& flow,
                               std::map<Slot, std::vector<Subtraction>>& subtractions, const Cameras& cameras) {
    PerEyeViewFacts& facts = ctx.record.perEyeView;
    std::vector<ClipChain> chains = clipChains(ctx.analyses.clipPositions().outputs(), folded);
    facts.perEyeOutputs = perEyeOutputs(folded, flow, cameras);
    for (const auto& [slot, why] : cameras) {
      std::vector<Subtraction> points = subtractions[slot];
      if (points.empty()) points = pointsWrittenToOutputs(folded);  // the tutorial form: no subtraction here
      OffsetSource source = chooseOffsetSource(ctx, folded, slot, points, chains);
      int count = kConvergence + 1;
      if (source.kind == OffsetSource::EyeOffsetParams) count = kEyeOffsetZ + 1;
      if (!ensureEyeParams(ctx, count)) return PassResult::Failed;
      int loads = rewriteCameraLoads(ctx, slot, source);
      std::string name = slotName(ctx.module, slot);
      ViewDependentUse entry;
      entry.uniform = name;
      entry.why = why;
      entry.loadsReplaced = loads;
      entry.eyeCentre = name + " + " + source.description;
      facts.fixed.push_back(entry);
      recordCameraText(ctx.module, slot, source, facts);
      if (source.kind == OffsetSource::EyeOffsetParams)
        facts.application =
            "fill " + ctx.eye.names[kEyeOffsetX] + "/" + ctx.eye.names[kEyeOffsetY] + "/" + ctx.eye.names[kEyeOffsetZ] +
            " per eye with the world-space offset of the eye centre, eyeSign*separation*convergence/P00 along the "
            "camera's right axis (stereoshift::runtime::eyeOffsetFromInverseView in include/stereoshift/stereo_runtime.h)";
    }
    return PassResult::Changed;
  }
};

}  // namespace

std::unique_ptr<Pass> createPerEyeViewPass() { return std::make_unique<PerEyeViewPass>(); }

// The eye parameters it declares for itself are part of its edit.
PassInfo perEyeViewPassInfo() {
  return {"per-eye-view", createPerEyeViewPass,
          "uses the per-eye camera position in view vectors that offset texture coordinates",
          "on (--no-per-eye-view turns it off, --per-eye-specular extends it)",
          "independent of the shift (it also runs on fragment shaders) and declares the eye parameters it "
          "needs itself; it reads detection's classification and clip positions",
          {"clip-position-detection"}, kClipPositionAnalysis | kFoldedCopyAnalysis, kNoAnalyses,
          editSet(EditKind::PerEyeCamera)};
}

}  // namespace stereoshift
