// See unprojection.h: the per-eye rewrites of what recognise.cpp found.
#include "passes/deferred_unprojection/unprojection.h"

#include "passes/eye_param_emitter.h"
#include "passes/ir/replace_uses.h"
#include "passes/pass.h"
#include "passes/shift_emitter.h"

namespace stereoshift::deferred {

using spirv::Instruction;

// q' = eyeSign != 0 ? q - InvM[col 0] * (eyeSign*separation)*(1 - convergence*q.w) : q.
// The select keeps a mono draw the original bit for bit (no -0 turned into +0, no 0*inf NaN).
void rewrite(PassContext& ctx, const Product& p) {
  auto& m = ctx.module;
  uint32_t f = m.typeFloat(32), v4 = m.typeVector(f, 4), bool4 = m.typeVector(m.typeBool(), 4);
  std::vector<Instruction> code;
  auto emit = [&](spv::Op op, uint32_t type, std::vector<uint32_t> operands) {
    uint32_t id = m.takeId();
    code.emplace_back(op, type, id, std::move(operands));
    return id;
  };
  uint32_t column0;
  if (!p.vectorTimesMatrix) {
    column0 = emit(spv::OpCompositeExtract, v4, {p.matrix, 0});
  } else {  // v * M: the mathematical matrix is M transposed, its column 0 is element 0 of each column of M
    std::vector<uint32_t> elements;
    for (uint32_t c = 0; c < 4; ++c) elements.push_back(emit(spv::OpCompositeExtract, f, {p.matrix, c, 0}));
    column0 = emit(spv::OpCompositeConstruct, v4, elements);
  }
  uint32_t eyeSign = emitLoadEyeParam(ctx, code, kEyeSign);
  uint32_t separation = emitLoadEyeParam(ctx, code, kSeparation);
  uint32_t convergence = emitLoadEyeParam(ctx, code, kConvergence);
  uint32_t inverseDepth = emit(spv::OpCompositeExtract, f, {p.result, 3});
  uint32_t scaled = emit(spv::OpFMul, f, {convergence, inverseDepth});
  uint32_t parallax = emit(spv::OpFSub, f, {m.constantFloat(1.0f), scaled});
  uint32_t scale = emitEyeScale(ctx, code, eyeSign, separation);
  uint32_t offset = emit(spv::OpFMul, f, {scale, parallax});
  uint32_t correction = emit(spv::OpVectorTimesScalar, v4, {column0, offset});
  uint32_t corrected = emit(spv::OpFSub, v4, {p.result, correction});
  m.constantFloat(0.0f);  // before the guard's own id, the order these ids have always had
  uint32_t stereo = emitStereoGuard(ctx, code, eyeSign);
  // A vector condition: OpSelect takes a scalar one only from SPIR-V 1.4 on.
  uint32_t stereo4 = emit(spv::OpCompositeConstruct, bool4, {stereo, stereo, stereo, stereo});
  uint32_t chosen = emit(spv::OpSelect, v4, {stereo4, corrected, p.result});

  // Every use of q now reads q' (the fix code itself, inserted below, still reads q).
  spirv::replaceAllUses(m, p.result, chosen);
  for (auto& block : p.function->blocks)
    for (size_t i = 0; i < block.instructions.size(); ++i)
      if (block.instructions[i].resultId == p.result) {
        block.instructions.insert(block.instructions.begin() + static_cast<long>(i) + 1, code.begin(), code.end());
        m.invalidateDefinitions();
        return;
      }
}

// p' = eyeSign != 0 ? p with x - (eyeSign*separation)*(|p.z| - convergence)*(1/P00) : p.
void rewriteRay(PassContext& ctx, const RayProduct& r) {
  auto& m = ctx.module;
  uint32_t f = m.typeFloat(32), boolType = m.typeBool();
  uint32_t vectorType = m.typeVector(f, r.components), boolVector = m.typeVector(boolType, r.components);
  std::vector<Instruction> code;
  auto emit = [&](spv::Op op, uint32_t type, std::vector<uint32_t> operands) {
    uint32_t id = m.takeId();
    code.emplace_back(op, type, id, std::move(operands));
    return id;
  };
  uint32_t inverseScale;  // 1 / P00
  if (r.scale.kind == ScaleKind::InverseElement) {
    inverseScale = emit(spv::OpCompositeExtract, f, {r.scale.matrixValue, 0, 0});
  } else if (r.scale.kind == ScaleKind::Injected) {
    uint32_t p00 = emitLoadEyeParam(ctx, code, kProjScaleX);
    inverseScale = emit(spv::OpFDiv, f, {m.constantFloat(1.0f), p00});
  } else {
    const Instruction* variable = m.definition(r.scale.root);
    auto storage = static_cast<spv::StorageClass>(variable->operand(0));
    std::vector<uint32_t> chain = {r.scale.root};
    for (uint32_t step : r.scale.path) chain.push_back(m.constantInt(static_cast<int32_t>(step)));
    chain.push_back(m.constantInt(0));
    chain.push_back(m.constantInt(0));
    uint32_t pointer = emit(spv::OpAccessChain, m.typePointer(storage, f), chain);
    uint32_t p00 = emit(spv::OpLoad, f, {pointer});
    inverseScale = emit(spv::OpFDiv, f, {m.constantFloat(1.0f), p00});
  }
  uint32_t eyeSign = emitLoadEyeParam(ctx, code, kEyeSign);
  uint32_t separation = emitLoadEyeParam(ctx, code, kSeparation);
  uint32_t convergence = emitLoadEyeParam(ctx, code, kConvergence);
  // |p.z| is the eye depth w for both handednesses (-z in OpenGL view space, z in Direct3D's).
  uint32_t z = emit(spv::OpCompositeExtract, f, {r.fixPoint, 2});
  uint32_t negated = emit(spv::OpFNegate, f, {z});
  uint32_t behind = emit(spv::OpFOrdLessThan, boolType, {z, m.constantFloat(0.0f)});
  uint32_t depth = emit(spv::OpSelect, f, {behind, negated, z});
  uint32_t parallax = emit(spv::OpFSub, f, {depth, convergence});
  uint32_t scale = emitEyeScale(ctx, code, eyeSign, separation);
  uint32_t offset = emit(spv::OpFMul, f, {scale, parallax});
  uint32_t viewOffset = emit(spv::OpFMul, f, {offset, inverseScale});
  uint32_t x = emit(spv::OpCompositeExtract, f, {r.fixPoint, 0});
  uint32_t correctedX = emit(spv::OpFSub, f, {x, viewOffset});
  uint32_t corrected = emit(spv::OpCompositeInsert, vectorType, {correctedX, r.fixPoint, 0});
  uint32_t stereo = emitStereoGuard(ctx, code, eyeSign);
  std::vector<uint32_t> lanes(r.components, stereo);
  uint32_t stereoVector = emit(spv::OpCompositeConstruct, boolVector, lanes);
  uint32_t chosen = emit(spv::OpSelect, vectorType, {stereoVector, corrected, r.fixPoint});

  spirv::replaceAllUses(m, r.fixPoint, chosen);
  for (auto& block : r.function->blocks)
    for (size_t i = 0; i < block.instructions.size(); ++i)
      if (block.instructions[i].resultId == r.fixPoint) {
        block.instructions.insert(block.instructions.begin() + static_cast<long>(i) + 1, code.begin(), code.end());
        m.invalidateDefinitions();
        return;
      }
}

// q' = eyeSign != 0 ? q with x + eyeSign*separation*(q.w - convergence) : q.
void rewriteReprojection(PassContext& ctx, const Product& p) {
  auto& m = ctx.module;
  uint32_t f = m.typeFloat(32), v4 = m.typeVector(f, 4), bool4 = m.typeVector(m.typeBool(), 4);
  std::vector<Instruction> code;
  auto emit = [&](spv::Op op, uint32_t type, std::vector<uint32_t> operands) {
    uint32_t id = m.takeId();
    code.emplace_back(op, type, id, std::move(operands));
    return id;
  };
  uint32_t x = emit(spv::OpCompositeExtract, f, {p.result, 0});
  uint32_t w = emit(spv::OpCompositeExtract, f, {p.result, 3});
  uint32_t shiftedX = emitShiftedX(ctx, code, x, w);
  uint32_t shifted = emit(spv::OpCompositeInsert, v4, {shiftedX, p.result, 0});
  uint32_t eyeSign = emitLoadEyeParam(ctx, code, kEyeSign);
  uint32_t stereo = emitStereoGuard(ctx, code, eyeSign);
  uint32_t stereo4 = emit(spv::OpCompositeConstruct, bool4, {stereo, stereo, stereo, stereo});
  uint32_t chosen = emit(spv::OpSelect, v4, {stereo4, shifted, p.result});
  spirv::replaceAllUses(m, p.result, chosen);
  for (auto& block : p.function->blocks)
    for (size_t i = 0; i < block.instructions.size(); ++i)
      if (block.instructions[i].resultId == p.result) {
        block.instructions.insert(block.instructions.begin() + static_cast<long>(i) + 1, code.begin(), code.end());
        m.invalidateDefinitions();
        return;
      }
}

}  // namespace stereoshift::deferred
