// This turns a ShiftSpec into SPIR-V: the loads of the eye parameters, the shifted x in its plain,
// fused or compensated form, and the cutoff condition around it (see shift_emitter.h).
#include "passes/shift_emitter.h"

#include "passes/eye_param_emitter.h"
#include "passes/eye_select.h"
#include "passes/ir/builder.h"
#include "passes/pass.h"

#include <glslang/SPIRV/GLSL.std.450.h>

namespace stereoshift {

using spirv::Builder;
using spirv::Instruction;

ShiftSpec makeShiftSpec(const PassOptions& options, bool preciseSupported) {
  ShiftSpec spec;
  spec.cutoff = normalisedCutoff(options.cutoff, options.cutoffEpsilon);
  spec.epsilon = options.cutoffEpsilon;
  spec.form = options.shiftForm;
  spec.fused = options.fusedShift;
  spec.compensated = options.compensatedShift;
  spec.precise = options.invariantPosition && preciseSupported;
  spec.eyeSignName = options.eye.eyeSignName;
  spec.separationName = options.eye.separationName;
  spec.convergenceName = options.eye.convergenceName;
  return spec;
}

ShiftSpec shiftSpec(const PassContext& context) {
  ShiftSpec spec = makeShiftSpec(context.options, targetSupportsPrecise(context));
  // eye-params may have renamed them to avoid a clash with the shader's own names.
  if (context.eye.declared > kConvergence) {
    spec.eyeSignName = context.eye.names[kEyeSign];
    spec.separationName = context.eye.names[kSeparation];
    spec.convergenceName = context.eye.names[kConvergence];
  }
  return spec;
}

bool targetSupportsPrecise(const PassContext& context) {
  TargetLanguage target = context.output.language;
  if (target == TargetLanguage::Auto) {
    switch (context.source.language) {
      case SourceLanguage::Hlsl: return true;
      case SourceLanguage::Spirv: return true;
      case SourceLanguage::Glsl: break;
    }
    int version = context.output.version.value_or(context.source.version);
    if (context.source.vulkan) return true;
    return context.source.es ? version >= 320 : version >= 400;
  }
  switch (target) {
    case TargetLanguage::Spirv: case TargetLanguage::SpirvAsm: case TargetLanguage::Hlsl: return true;
    case TargetLanguage::Glsl: return context.output.version.value_or(450) >= 400;
    case TargetLanguage::Essl: return context.output.version.value_or(310) >= 320;
    default: return false;
  }
}

uint32_t emitStereoGuard(PassContext& context, std::vector<Instruction>& out, uint32_t eyeSign) {
  auto& m = context.module;
  Builder b(m, out);
  uint32_t stereo = b.reserveId();
  return b.addAs(stereo, spv::OpFUnordNotEqual, m.typeBool(), {eyeSign, m.constantFloat(0.0f)});
}

uint32_t emitEyeScale(PassContext& context, std::vector<Instruction>& out, uint32_t eyeSign, uint32_t separation,
                      bool noContraction) {
  auto& m = context.module;
  Builder b(m, out);
  uint32_t scale = b.reserveId();
  b.addAs(scale, spv::OpFMul, m.typeFloat(32), {eyeSign, separation});
  if (noContraction) m.decorate(scale, spv::DecorationNoContraction);
  return scale;
}

uint32_t emitShiftedX(PassContext& context, std::vector<Instruction>& out, uint32_t x, uint32_t w) {
  return emitShiftedX(context, shiftSpec(context), out, x, w);
}

uint32_t emitShiftedX(PassContext& context, const ShiftSpec& spec, std::vector<Instruction>& out, uint32_t x,
                      uint32_t w) {
  auto& m = context.module;
  uint32_t f = m.typeFloat(32);
  uint32_t eyeSign = emitLoadEyeParam(context, out, 0);
  uint32_t separation = emitLoadEyeParam(context, out, 1);
  uint32_t convergence = emitLoadEyeParam(context, out, 2);
  bool precise = spec.precise;
  Builder b(m, out);
  auto op = [&](spv::Op code, uint32_t lhs, uint32_t rhs) {
    uint32_t id = b.add(code, f, {lhs, rhs});
    if (precise) m.decorate(id, spv::DecorationNoContraction);
    return id;
  };
  // x + (eyeSign * separation) * (w - convergence): the order of docs/stereo-math.md section 1.
  uint32_t depth = op(spv::OpFSub, w, convergence);
  uint32_t scale = emitEyeScale(context, out, eyeSign, separation, precise);
  if (spec.compensated) {
    // x + a*(w - C) correctly rounded up to a hair: w - C exactly as dh + dl (TwoSum), a*dh exactly
    // as ph + pl (TwoProduct), x + ph exactly as sh + sl (TwoSum), then one final rounding of
    // sh + (sl + pl + a*dl). Needs NoContraction honoured (no re-association), so `precise`.
    auto always = [&](spv::Op code, uint32_t lhs, uint32_t rhs) {
      uint32_t id = b.add(code, f, {lhs, rhs});
      m.decorate(id, spv::DecorationNoContraction);
      return id;
    };
    uint32_t dh = always(spv::OpFSub, w, convergence);
    uint32_t bb = always(spv::OpFSub, dh, w);
    uint32_t dl = always(spv::OpFSub, always(spv::OpFSub, w, always(spv::OpFSub, dh, bb)),
                         always(spv::OpFAdd, convergence, bb));
    uint32_t a = emitEyeScale(context, out, eyeSign, separation, true);
    uint32_t ph = always(spv::OpFMul, a, dh);
    // The product's rounding error by Dekker's TwoProduct (Veltkamp split, 2^12 + 1): exact without
    // relying on a fused fma, which some drivers (lavapipe among them) evaluate as mul + add.
    uint32_t splitter = m.constantFloat(4097.0f);
    auto split = [&](uint32_t v, uint32_t* hi, uint32_t* lo) {
      uint32_t c = always(spv::OpFMul, splitter, v);
      *hi = always(spv::OpFSub, c, always(spv::OpFSub, c, v));
      *lo = always(spv::OpFSub, v, *hi);
    };
    uint32_t ahi, alo, dhi, dlo;
    split(a, &ahi, &alo);
    split(dh, &dhi, &dlo);
    uint32_t pl = always(spv::OpFAdd,
                         always(spv::OpFAdd, always(spv::OpFAdd, always(spv::OpFSub, always(spv::OpFMul, ahi, dhi), ph),
                                                    always(spv::OpFMul, ahi, dlo)),
                                always(spv::OpFMul, alo, dhi)),
                         always(spv::OpFMul, alo, dlo));
    uint32_t sh = always(spv::OpFAdd, x, ph);
    uint32_t bb2 = always(spv::OpFSub, sh, x);
    uint32_t sl = always(spv::OpFAdd, always(spv::OpFSub, x, always(spv::OpFSub, sh, bb2)),
                         always(spv::OpFSub, ph, bb2));
    uint32_t tail = always(spv::OpFAdd, sl, always(spv::OpFAdd, pl, always(spv::OpFMul, a, dl)));
    return always(spv::OpFAdd, sh, tail);
  }
  if (spec.fused) {
    // One rounding less: fma(eyeSign * separation, w - convergence, x).
    uint32_t glsl = m.extInstImport("GLSL.std.450");
    uint32_t id = b.add(spv::OpExtInst, f, {glsl, GLSLstd450Fma, scale, depth, x});
    if (precise) m.decorate(id, spv::DecorationNoContraction);
    return id;
  }
  uint32_t offset = op(spv::OpFMul, scale, depth);
  return op(spv::OpFAdd, x, offset);
}

uint32_t emitCutoffCondition(PassContext& context, std::vector<Instruction>& out, uint32_t w) {
  return emitCutoffCondition(context, shiftSpec(context), out, w);
}

uint32_t emitCutoffCondition(PassContext& context, const ShiftSpec& spec, std::vector<Instruction>& out, uint32_t w) {
  auto& m = context.module;
  uint32_t boolType = m.typeBool();
  uint32_t f = m.typeFloat(32);
  // eyeSign != 0 first: a mono draw runs none of the shift, so it is the original bit for bit
  // (x + 0 would turn a -0 x into +0).
  uint32_t eyeSign = emitLoadEyeParam(context, out, 0);
  uint32_t stereo = emitStereoGuard(context, out, eyeSign);
  if (spec.cutoff == CutoffMode::None) return stereo;

  uint32_t one = m.constantFloat(1.0f);
  Builder b(m, out);
  // Ordered comparisons: a NaN w is never shifted (no new NaN in x).
  uint32_t far = b.reserveId();
  if (spec.cutoff == CutoffMode::Exact) {
    // The driver's rule: w != 1.
    b.addAs(far, spv::OpFOrdNotEqual, boolType, {w, one});
  } else {
    uint32_t glsl = m.extInstImport("GLSL.std.450");
    uint32_t diff = b.add(spv::OpFSub, f, {w, one});
    uint32_t absDiff = b.add(spv::OpExtInst, f, {glsl, GLSLstd450FAbs, diff});
    b.addAs(far, spv::OpFOrdGreaterThan, boolType, {absDiff, m.constantFloat(spec.epsilon)});
  }
  // An infinite w is not shifted either: separation 0 times infinity would be NaN. GLSL below 130
  // and ESSL 100 have no isinf: there `|w| <= FLT_MAX` (false for inf and NaN alike; a NaN w fails
  // the ordered comparison above anyway), as the text routes write it.
  TargetLanguage target = outputLanguage(context);
  bool hasIsinf = !glslOutput(target) || glslOutputVersion(context, target) >= (target == TargetLanguage::Essl ? 300 : 130);
  uint32_t finite;
  if (hasIsinf) {
    uint32_t infinite = b.add(spv::OpIsInf, boolType, {w});
    finite = b.add(spv::OpLogicalNot, boolType, {infinite});
  } else {
    uint32_t absW = b.add(spv::OpExtInst, f, {m.extInstImport("GLSL.std.450"), GLSLstd450FAbs, w});
    finite = b.add(spv::OpFOrdLessThanEqual, boolType, {absW, m.constantFloat(3.40282347e+38f)});
  }
  uint32_t farAndFinite = b.add(spv::OpLogicalAnd, boolType, {far, finite});
  return b.add(spv::OpLogicalAnd, boolType, {stereo, farAndFinite});
}

uint32_t emitShiftedVec4Select(PassContext& context, std::vector<Instruction>& out, uint32_t value) {
  auto& m = context.module;
  uint32_t f = m.typeFloat(32);
  uint32_t v4 = m.typeVector(f, 4);
  Builder b(m, out);
  uint32_t x = b.extract(f, value, 0);
  uint32_t w = b.extract(f, value, 3);
  ShiftSpec spec = shiftSpec(context);
  uint32_t shifted = emitShiftedX(context, spec, out, x, w);
  if (uint32_t cond = emitCutoffCondition(context, spec, out, w)) shifted = b.add(spv::OpSelect, f, {cond, shifted, x});
  return b.add(spv::OpCompositeInsert, v4, {shifted, value, 0});
}

}  // namespace stereoshift
