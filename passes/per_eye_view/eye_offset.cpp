// See eye_offset.h: docs/stereo-math.md section 3, C_eye = C + InvVP * (eyeSign*separation*convergence, 0, 0, 0).
#include "passes/per_eye_view/eye_offset.h"

#include "passes/eye_param_emitter.h"
#include "passes/eye_select.h"
#include "passes/ir/builder.h"
#include "passes/ir/walker.h"
#include "passes/pass.h"
#include "passes/per_eye_view/name_hints.h"
#include "passes/shift_emitter.h"

#include <glslang/SPIRV/GLSL.std.450.h>

#include <algorithm>

namespace stereoshift::per_eye_view {

using analysis::Slot;
using spirv::Instruction;
using spirv::Module;
using namespace analysis;

std::vector<Slot> ClipChain::productFor(size_t level) const {
  std::vector<Slot> product;
  // M2 * (M1 * W) = (M2 * M1) * W;  (W * M1) * M2 = W * (M1 * M2).
  for (size_t i = 0; i <= level; ++i) {
    const auto& factor = factors[columnVectors ? i : level - i];
    product.insert(product.end(), factor.begin(), factor.end());
  }
  return product;
}

namespace {

bool expandMatrix(const Module& m, uint32_t matrix, std::vector<Slot>& out) {
  const Instruction* def = m.definition(matrix);
  if (!def) return false;
  if (def->opcode == spv::OpMatrixTimesMatrix)
    return expandMatrix(m, def->operand(0), out) && expandMatrix(m, def->operand(1), out);
  auto slot = valueSlot(m, matrix);  // a load, or a member of a whole-struct load
  if (!slot || slot->inverseTranslation) return false;
  out.push_back(*slot);
  return true;
}

std::optional<ClipChain> clipChainFrom(const Module& m, uint32_t value) {
  ClipChain chain;
  for (int depth = 0; depth < 8; ++depth) {
    const Instruction* def = m.definition(value);
    if (!def) break;
    bool column = def->opcode == spv::OpMatrixTimesVector, row = def->opcode == spv::OpVectorTimesMatrix;
    if (!column && !row) break;
    if (!chain.factors.empty() && chain.columnVectors != column) break;  // mixed conventions: stop here
    std::vector<Slot> factor;
    if (!expandMatrix(m, column ? def->operand(0) : def->operand(1), factor)) break;  // not uniform matrices
    chain.columnVectors = column;
    chain.factors.push_back(factor);
    value = column ? def->operand(1) : def->operand(0);
    chain.points.push_back(value);
  }
  if (chain.factors.empty()) return std::nullopt;
  return chain;
}

// Whether the vec3/vec4 `point` is the vec4 `w` (or its xyz, or `vec4(point, 1)`).
uint32_t leadingComponentsOf(const Module& m, uint32_t value);

// The vector whose x, y, z a point is: `vec4(v, 1)`, `vec4(v.x, v.y, v.z, 1)`, `v.xyz`, or itself.
uint32_t pointSource(const Module& m, uint32_t value) {
  const Instruction* d = m.definition(value);
  if (d && d->opcode == spv::OpCompositeConstruct && d->operands.size() == 2) return leadingComponentsOf(m, d->operand(0));
  if (d && d->opcode == spv::OpCompositeConstruct && d->operands.size() == 4) {
    uint32_t from = 0;
    for (uint32_t i = 0; i < 3; ++i) {
      const Instruction* e = m.definition(d->operands[i]);
      if (!e || e->opcode != spv::OpCompositeExtract || e->operands.size() != 2 || e->operand(1) != i) return value;
      if (from && e->operand(0) != from) return value;
      from = e->operand(0);
    }
    return leadingComponentsOf(m, from);
  }
  return leadingComponentsOf(m, value);
}

bool samePoint(const Module& m, uint32_t point, uint32_t w) {
  if (point == w) return true;
  // The same x, y, z through any of the ways of writing vec3 <-> vec4 (the optimizer forwards
  // `vec4(vec3(world), 1)` to the extracts of `world` itself).
  if (pointSource(m, point) == pointSource(m, w)) return true;
  const Instruction* p = m.definition(point);
  if (p && p->opcode == spv::OpVectorShuffle && p->operand(0) == w && p->operands.size() == 5 &&
      p->operand(2) == 0 && p->operand(3) == 1 && p->operand(4) == 2)
    return true;
  const Instruction* d = m.definition(w);
  if (!d || d->opcode != spv::OpCompositeConstruct) return false;
  if (d->operands.size() == 2 && d->operand(0) == point) return true;
  if (d->operands.size() != 4) return false;
  for (uint32_t i = 0; i < 3; ++i) {
    const Instruction* e = m.definition(d->operands[i]);
    if (!e || e->opcode != spv::OpCompositeExtract || e->operand(0) != point || e->operand(1) != i) return false;
  }
  return true;
}

// `point` as (uniform matrices) * chain.points[level], the matrices being the ones applied first in
// the chain's product (`FragPos = model * p` beside `gl_Position = projection * view * model * p`):
// the rest of the product, which takes `point` to the clip position. Nullopt otherwise.
// `v.xyz` written as a shuffle or as vec3(v.x, v.y, v.z): v; else the value itself.
uint32_t leadingComponentsOf(const Module& m, uint32_t value) {
  const Instruction* def = m.definition(value);
  if (!def) return value;
  if (def->opcode == spv::OpVectorShuffle && def->operand(0) == def->operand(1)) return def->operand(0);
  if (def->opcode != spv::OpCompositeConstruct || def->operands.empty()) return value;
  uint32_t from = 0;
  for (uint32_t i = 0; i < def->operands.size(); ++i) {
    const Instruction* e = m.definition(def->operands[i]);
    if (!e || e->opcode != spv::OpCompositeExtract || e->operands.size() != 2 || e->operand(1) != i) return value;
    if (from && e->operand(0) != from) return value;
    from = e->operand(0);
  }
  return from;
}

std::optional<std::vector<Slot>> worldProduct(const Module& m, uint32_t point, const ClipChain& chain, size_t level) {
  const Instruction* def = m.definition(leadingComponentsOf(m, point));
  if (!def) return std::nullopt;
  bool column = def->opcode == spv::OpMatrixTimesVector, row = def->opcode == spv::OpVectorTimesMatrix;
  if ((!column && !row) || column != chain.columnVectors) return std::nullopt;
  std::vector<Slot> applied;
  if (!expandMatrix(m, column ? def->operand(0) : def->operand(1), applied)) return std::nullopt;
  uint32_t inner = column ? def->operand(1) : def->operand(0);
  if (!samePoint(m, inner, chain.points[level])) return std::nullopt;
  std::vector<Slot> product = chain.productFor(level);
  if (applied.size() >= product.size()) return std::nullopt;
  if (column) {  // P * V * M: M applied first, at the end
    if (!std::equal(applied.begin(), applied.end(), product.end() - static_cast<long>(applied.size()))) return std::nullopt;
    product.resize(product.size() - applied.size());
  } else {  // M * V * P applied left to right
    if (!std::equal(applied.begin(), applied.end(), product.begin())) return std::nullopt;
    product.erase(product.begin(), product.begin() + static_cast<long>(applied.size()));
  }
  return product;
}

}  // namespace

// The points a vertex shader writes to its non-built-in outputs (as `Subtraction`s without a
// subtraction): `FragPos`, `TBN * FragPos` (the frame taken off). Where the camera goes to an output
// as it is, these say which space it lives in.
std::vector<Subtraction> pointsWrittenToOutputs(const Module& m) {
  std::vector<Subtraction> points;
  spirv::forEachFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode != spv::OpStore) return;
    uint32_t root = m.rootVariable(inst.operand(0));
    if (!root || m.storageClassOf(root) != spv::StorageClassOutput || m.hasDecoration(root, spv::DecorationBuiltIn)) return;
    int64_t member = -1;
    if (const Instruction* chain = m.definition(inst.operand(0));
        chain && chain->opcode == spv::OpAccessChain && chain->operands.size() >= 2)
      if (auto index = constantValue(m, chain->operand(1))) member = *index;
    const Instruction* block = m.definition(m.pointeeType(m.definition(root)->typeId));
    if (block && block->opcode == spv::OpTypeStruct &&
        (member < 0 || m.hasMemberDecoration(block->resultId, static_cast<uint32_t>(member), spv::DecorationBuiltIn)))
      return;  // gl_PerVertex (the clip position itself), or a whole block
    uint32_t value = inst.operand(1);
    const Instruction* def = m.definition(value);
    // A tangent frame times the point: the point. The frame is built in the shader (mat3(T, B, N),
    // its transpose), not a uniform matrix.
    auto builtFrame = [&](uint32_t matrix) {
      const Instruction* d = m.definition(matrix);
      return d && (d->opcode == spv::OpTranspose || d->opcode == spv::OpCompositeConstruct);
    };
    if (def && def->opcode == spv::OpMatrixTimesVector && builtFrame(def->operand(0))) value = def->operand(1);
    else if (def && def->opcode == spv::OpVectorTimesMatrix && builtFrame(def->operand(1))) value = def->operand(0);
    points.push_back({0, value});
  });
  return points;
}

// Clip chains of every store to the clip position in the folded module.
std::vector<ClipChain> clipChains(const std::vector<ClipPosition>& positions, const Module& f) {
  std::vector<ClipChain> chains;
  spirv::forEachFunctionInstruction(f, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode != spv::OpStore) return;
    uint32_t pointer = inst.operand(0);
    for (const auto& p : positions) {
      if (p.arrayed) continue;
      bool hit = !p.isMember && pointer == p.variable;
      if (const Instruction* chain = f.definition(pointer);
          p.isMember && chain && chain->opcode == spv::OpAccessChain && chain->operand(0) == p.variable &&
          chain->operands.size() == 2 && constantValue(f, chain->operand(1)) == p.member)
        hit = true;
      if (hit)
        if (auto c = clipChainFrom(f, inst.operand(1))) chains.push_back(*c);
    }
  });
  return chains;
}


namespace {

// A mat4 named like an inverse view-projection, next to the camera: a member of the camera's own
// block, or (for a loose camera uniform) another loose uniform. Only an unambiguous one counts.
std::optional<Slot> namedInverseViewProjection(const Module& m, const Slot& camera) {
  std::vector<Slot> found;
  if (!camera.indices.empty()) {
    uint32_t block = m.pointeeType(m.definition(camera.variable)->typeId);
    const Instruction* def = m.definition(block);
    for (uint32_t i = 0; def && def->opcode == spv::OpTypeStruct && i < def->operands.size(); ++i)
      if (isMat4(m, def->operands[i]) && namesInverseViewProjection(m.memberName(block, i)))
        found.push_back({camera.variable, {i}});
  } else {
    for (const auto& inst : m.typesValues)
      if (inst.opcode == spv::OpVariable && inst.operand(0) == spv::StorageClassUniformConstant &&
          isMat4(m, m.pointeeType(inst.typeId)) && namesInverseViewProjection(m.name(inst.resultId)))
        found.push_back({inst.resultId, {}});
  }
  if (found.size() != 1) return std::nullopt;
  return found.front();
}

// How the shader multiplies points by its uniform matrices, when there is no clip chain to ask:
// the majority of its products with a uniform mat4, else the language's habit (glslang turns
// HLSL mul(M, v) into v * M).
bool shaderUsesColumnVectors(const PassContext& ctx, const Module& f) {
  int column = 0, row = 0;
  spirv::forEachFunctionInstruction(f, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode == spv::OpMatrixTimesVector && loadedSlot(f, inst.operand(0)) && isMat4(f, f.definition(inst.operand(0))->typeId)) ++column;
    if (inst.opcode == spv::OpVectorTimesMatrix && loadedSlot(f, inst.operand(1)) && isMat4(f, f.definition(inst.operand(1))->typeId)) ++row;
  });
  if (column != row) return column > row;
  return ctx.source.language != SourceLanguage::Hlsl;
}


uint32_t emitLoadSlot(Module& m, std::vector<Instruction>& out, const Slot& slot) {
  uint32_t type = slotType(m, slot);
  auto storage = *m.storageClassOf(slot.variable);
  uint32_t pointer = slot.variable;
  spirv::Builder b(m, out);
  if (!slot.indices.empty()) {
    std::vector<uint32_t> operands = {slot.variable};
    for (uint32_t index : slot.indices) operands.push_back(m.constantInt(static_cast<int32_t>(index)));
    pointer = b.reserveId();
    b.addAs(pointer, spv::OpAccessChain, m.typePointer(storage, type), operands);
  }
  return b.load(type, pointer);
}

// Appends the world-space offset of this eye's centre from the mono camera; returns a vec3 id.
uint32_t emitEyeOffset(PassContext& ctx, std::vector<Instruction>& out, const OffsetSource& source) {
  auto& m = ctx.module;
  uint32_t f = m.typeFloat(32), v3 = m.typeVector(f, 3), v4 = m.typeVector(f, 4);
  spirv::Builder b(m, out);
  auto op = [&](spv::Op code, uint32_t type, std::vector<uint32_t> operands) { return b.add(code, type, std::move(operands)); };
  if (source.kind == OffsetSource::EyeOffsetParams) {
    uint32_t x = emitLoadEyeParam(ctx, out, kEyeOffsetX);
    uint32_t y = emitLoadEyeParam(ctx, out, kEyeOffsetY);
    uint32_t z = emitLoadEyeParam(ctx, out, kEyeOffsetZ);
    return op(spv::OpCompositeConstruct, v3, {x, y, z});
  }
  // InvVP * (e*S*C, 0, 0, 0): the clip-space direction of the shift at zero depth, back in world space.
  uint32_t eyeSign = emitLoadEyeParam(ctx, out, kEyeSign);
  uint32_t separation = emitLoadEyeParam(ctx, out, kSeparation);
  uint32_t convergence = emitLoadEyeParam(ctx, out, kConvergence);
  uint32_t shift = op(spv::OpFMul, f, {emitEyeScale(ctx, out, eyeSign, separation), convergence});
  uint32_t zero = m.constantFloat(0.0f);
  uint32_t direction = op(spv::OpCompositeConstruct, v4, {shift, zero, zero, zero});
  uint32_t matrixType = slotType(m, source.matrices.front());  // every factor is a mat4
  uint32_t matrix = 0;
  for (const Slot& slot : source.matrices) {
    uint32_t loaded = emitLoadSlot(m, out, slot);
    matrix = matrix ? op(spv::OpMatrixTimesMatrix, matrixType, {matrix, loaded}) : loaded;
  }
  if (source.kind == OffsetSource::InvertedClipMatrices)
    matrix = op(spv::OpExtInst, matrixType, {m.extInstImport("GLSL.std.450"), GLSLstd450MatrixInverse, matrix});
  uint32_t world = source.columnVectors ? op(spv::OpMatrixTimesVector, v4, {matrix, direction})
                                        : op(spv::OpVectorTimesMatrix, v4, {direction, matrix});
  return op(spv::OpVectorShuffle, v3, {world, world, 0, 1, 2});
}

}  // namespace

// Rewrites every load of `camera` (the whole vector or one component) into `loaded + offset`.
// Returns how many loads were rewritten. A loop of its own rather than the walker: it inserts the
// offset code after each load while it goes.
int rewriteCameraLoads(PassContext& ctx, const Slot& camera, const OffsetSource& source) {
  auto& m = ctx.module;
  uint32_t f = m.typeFloat(32);
  int rewritten = 0;
  auto v4OfOffset = [&](std::vector<Instruction>& code, uint32_t offset, uint32_t vectorType) {
    const Instruction* t = m.definition(vectorType);
    if (!t || t->operand(1) != 4) return offset;
    spirv::Builder b(m, code);
    uint32_t widened = b.reserveId();
    return b.addAs(widened, spv::OpCompositeConstruct, vectorType, {offset, m.constantFloat(0.0f)});
  };
  for (auto& fn : m.functions)
    for (auto& block : fn.blocks)
      for (size_t i = 0; i < block.instructions.size(); ++i) {
        const Instruction& inst = block.instructions[i];
        // inverse(view): its translation column (the camera centre) moves to the eye; the rotation
        // stays, so the inverse is the per-eye camera's.
        if (camera.inverseTranslation) {
          if (!isGlslExtInst(m, inst, {GLSLstd450MatrixInverse}) || loadedSlot(m, inst.operand(2)) !=
                                                                        std::optional<Slot>(Slot{camera.variable, camera.indices}))
            continue;
          uint32_t matrixType = inst.typeId, columnType = slotType(m, camera);
          uint32_t perEye = inst.resultId, mono = m.takeId();
          block.instructions[i].resultId = mono;
          std::vector<Instruction> code;
          uint32_t addend = v4OfOffset(code, emitEyeOffset(ctx, code, source), columnType);
          spirv::Builder b(m, code);
          uint32_t column = b.reserveId(), moved = b.reserveId();
          b.addAs(column, spv::OpCompositeExtract, columnType, {mono, 3});
          b.addAs(moved, spv::OpFAdd, columnType, {column, addend});
          b.addAs(perEye, spv::OpCompositeInsert, matrixType, {moved, mono, 3});
          block.instructions.insert(block.instructions.begin() + static_cast<long>(i) + 1, code.begin(), code.end());
          i += code.size();
          m.invalidateDefinitions();
          ++rewritten;
          continue;
        }
        if (inst.opcode != spv::OpLoad) continue;
        auto slot = slotOfPointer(m, inst.operand(0));
        if (!slot || slot->variable != camera.variable) continue;
        // A whole-struct load (`Camera c = camera;`): the camera member inside the loaded value moves.
        if (slot->indices.size() < camera.indices.size() &&
            std::equal(slot->indices.begin(), slot->indices.end(), camera.indices.begin())) {
          std::vector<uint32_t> path(camera.indices.begin() + static_cast<long>(slot->indices.size()), camera.indices.end());
          uint32_t structType = inst.typeId, memberType = slotType(m, camera);
          uint32_t perEye = inst.resultId, mono = m.takeId();
          block.instructions[i].resultId = mono;
          std::vector<Instruction> code;
          uint32_t addend = v4OfOffset(code, emitEyeOffset(ctx, code, source), memberType);
          spirv::Builder b(m, code);
          uint32_t member = b.reserveId(), moved = b.reserveId();
          std::vector<uint32_t> extract = {mono}, insert = {moved, mono};
          extract.insert(extract.end(), path.begin(), path.end());
          insert.insert(insert.end(), path.begin(), path.end());
          b.addAs(member, spv::OpCompositeExtract, memberType, extract);
          b.addAs(moved, spv::OpFAdd, memberType, {member, addend});
          b.addAs(perEye, spv::OpCompositeInsert, structType, insert);
          block.instructions.insert(block.instructions.begin() + static_cast<long>(i) + 1, code.begin(), code.end());
          i += code.size();
          m.invalidateDefinitions();
          ++rewritten;
          continue;
        }
        bool whole = slot->indices == camera.indices;
        bool component = slot->indices.size() == camera.indices.size() + 1 &&
                         std::equal(camera.indices.begin(), camera.indices.end(), slot->indices.begin());
        if (!whole && !component) continue;
        uint32_t componentIndex = component ? slot->indices.back() : 0;
        if (component && componentIndex > 2) continue;  // .w of a vec4 position: not moved
        uint32_t type = block.instructions[i].typeId;
        uint32_t perEye = block.instructions[i].resultId;  // every use now reads the per-eye centre
        uint32_t mono = m.takeId();
        block.instructions[i].resultId = mono;
        std::vector<Instruction> code;
        uint32_t offset = emitEyeOffset(ctx, code, source);
        uint32_t addend = offset;
        spirv::Builder b(m, code);
        if (component) {
          addend = b.add(spv::OpCompositeExtract, f, {offset, componentIndex});
        } else if (const Instruction* t = m.definition(type); t && t->operand(1) == 4) {
          addend = b.reserveId();
          b.addAs(addend, spv::OpCompositeConstruct, type, {offset, m.constantFloat(0.0f)});
        }
        b.addAs(perEye, spv::OpFAdd, type, {mono, addend});
        block.instructions.insert(block.instructions.begin() + static_cast<long>(i) + 1, code.begin(), code.end());
        i += code.size();
        m.invalidateDefinitions();
        ++rewritten;
      }
  return rewritten;
}

// ---- the offset source ----------------------------------------------------------------------------

OffsetSource chooseOffsetSource(const PassContext& ctx, const Module& f, const Slot& camera,
                                const std::vector<Subtraction>& subs, const std::vector<ClipChain>& chains) {
  OffsetSource source;
  // The clip chain of a point this camera is subtracted from: the very matrices the stereo shift
  // is consistent with.
  const ClipChain* chain = nullptr;
  std::vector<Slot> product;
  for (const auto& c : chains)
    for (size_t level = 0; level < c.points.size() && !chain; ++level)
      for (const auto& s : subs) {
        if (chain) break;
        if (samePoint(f, s.point, c.points[level])) {
          chain = &c;
          product = c.productFor(level);
        } else if (auto world = worldProduct(f, s.point, c, level)) {
          chain = &c;  // the point is a model transform of the chain's: the rest takes world to clip
          product = *world;
        }
      }
  bool columns = chain ? chain->columnVectors : shaderUsesColumnVectors(ctx, f);
  std::string k = "eyeSign*separation*convergence";
  auto apply = [&](const std::string& matrix) {
    return columns ? "(" + matrix + " * vec4(" + k + ", 0, 0, 0)).xyz" : "(vec4(" + k + ", 0, 0, 0) * " + matrix + ").xyz";
  };
  if (auto inverse = namedInverseViewProjection(f, camera)) {
    source.kind = OffsetSource::InverseViewProjection;
    source.matrices = {*inverse};
    source.columnVectors = columns;
    source.description = apply(slotName(f, *inverse)) + "  [inverse view-projection by name]";
    return source;
  }
  // GLSL below 150 and ESSL 100 have no inverse() (core/shader.h): there the application's eye-offset parameters.
  TargetLanguage target = outputLanguage(ctx);
  bool hasInverse = !glslOutput(target) || glslHasInverse(glslOutputVersion(ctx, target), target == TargetLanguage::Essl);
  if (chain && !product.empty() && hasInverse) {
    bool allMat4 = std::all_of(product.begin(), product.end(),
                               [&](const Slot& s) { return isMat4(f, slotType(f, s)); });
    if (allMat4) {
      source.kind = OffsetSource::InvertedClipMatrices;
      source.matrices = product;
      source.columnVectors = chain->columnVectors;
      std::string text;
      for (const auto& s : product) text += (text.empty() ? "" : " * ") + slotName(f, s);
      source.description = apply("inverse(" + text + ")") +
                           "  [matrices that take the same world point to the clip position]";
      return source;
    }
  }
  source.kind = OffsetSource::EyeOffsetParams;
  source.description = "vec3(" + ctx.options.eye.eyeOffsetXName + ", " + ctx.options.eye.eyeOffsetYName + ", " +
                       ctx.options.eye.eyeOffsetZName + ")  [no matrix to derive it from: set by the application]";
  return source;
}

}  // namespace stereoshift::per_eye_view
