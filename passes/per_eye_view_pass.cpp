// per-eye-view: turns the mono camera position that feeds view vectors into the per-eye centre
//     C_eye = C + InvVP * (eyeSign*separation*convergence, 0, 0, 0)      (docs/stereo-math.md section 3)
// wherever a view vector offsets texture coordinates (relief / parallax occlusion / steep / cone
// mapping, reflection lookups), so each eye sees the surface relief from its own position.
//
// Detection is by data flow (the forward engine of passes/analysis/value_flow.h) on the shared
// folded copy (helpers inlined, loops in SSA form):
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
// stereo_runtime.h). Everything found and left alone is listed in the report.
#include "passes/per_eye_view_pass.h"

#include "passes/pass.h"

#include "passes/analysis/value_flow.h"
#include "passes/ir/image_instructions.h"
#include "passes/ir/walker.h"

#include <glslang/SPIRV/GLSL.std.450.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <functional>
#include <map>
#include <set>
#include <unordered_map>

namespace stereoshift {

using spirv::Instruction;
using spirv::Module;
using analysis::ValueFlow;

namespace {

// ---- uniform slots --------------------------------------------------------------------------

// A uniform value by where it lives: a Uniform / PushConstant / UniformConstant variable and the
// constant member indices of the access chain to it. Ids of global variables are shared between
// the module and its folded copy, so a slot found in one names the same value in the other.
struct Slot {
  uint32_t variable = 0;
  std::vector<uint32_t> indices;
  bool operator<(const Slot& o) const { return std::tie(variable, indices) < std::tie(o.variable, o.indices); }
  bool operator==(const Slot& o) const { return variable == o.variable && indices == o.indices; }
};

std::optional<uint32_t> constantValue(const Module& m, uint32_t id) {
  const Instruction* def = m.definition(id);
  if (!def || def->opcode != spv::OpConstant) return std::nullopt;
  return def->operand(0);
}

bool isUniformStorage(spv::StorageClass s) {
  return s == spv::StorageClassUniform || s == spv::StorageClassPushConstant || s == spv::StorageClassUniformConstant;
}

std::optional<Slot> slotOfPointer(const Module& m, uint32_t pointer) {
  std::vector<uint32_t> reversed;
  for (int depth = 0; depth < 16; ++depth) {
    const Instruction* def = m.definition(pointer);
    if (!def) return std::nullopt;
    if (def->opcode == spv::OpVariable) {
      if (!isUniformStorage(spv::StorageClass(def->operand(0)))) return std::nullopt;
      return Slot{pointer, std::vector<uint32_t>(reversed.rbegin(), reversed.rend())};
    }
    if (def->opcode != spv::OpAccessChain && def->opcode != spv::OpInBoundsAccessChain) return std::nullopt;
    for (size_t k = def->operands.size(); k-- > 1;) {
      auto value = constantValue(m, def->operands[k]);
      if (!value) return std::nullopt;  // indexed by a variable: not one fixed value
      reversed.push_back(*value);
    }
    pointer = def->operand(0);
  }
  return std::nullopt;
}

// The slot an OpLoad reads, if it reads one.
std::optional<Slot> loadedSlot(const Module& m, uint32_t value) {
  const Instruction* def = m.definition(value);
  if (!def || def->opcode != spv::OpLoad) return std::nullopt;
  return slotOfPointer(m, def->operand(0));
}

// Type of the value a slot holds.
uint32_t slotType(const Module& m, const Slot& slot) {
  const Instruction* var = m.definition(slot.variable);
  uint32_t type = m.pointeeType(var->typeId);
  for (uint32_t index : slot.indices) {
    const Instruction* def = m.definition(type);
    if (!def) return 0;
    if (def->opcode == spv::OpTypeStruct) type = def->operand(index);
    else if (def->opcode == spv::OpTypeVector || def->opcode == spv::OpTypeMatrix || def->opcode == spv::OpTypeArray)
      type = def->operand(0);
    else return 0;
  }
  return type;
}

// "instance.member" (block type name when the instance is unnamed, as in HLSL cbuffers), or the
// loose uniform's name. Array and vector indices are written as [i].
std::string slotName(const Module& m, const Slot& slot) {
  const Instruction* var = m.definition(slot.variable);
  std::string text = m.name(slot.variable);
  uint32_t type = m.pointeeType(var->typeId);
  if (text.empty()) text = m.name(type);
  for (uint32_t index : slot.indices) {
    const Instruction* def = m.definition(type);
    if (def && def->opcode == spv::OpTypeStruct) {
      std::string member = m.memberName(type, index);
      text += (text.empty() ? "" : ".") + (member.empty() ? std::to_string(index) : member);
      type = def->operand(index);
    } else {
      text += "[" + std::to_string(index) + "]";
      type = def ? def->operand(0) : 0;
    }
  }
  return text;
}

// The innermost name of a slot: the member name, or the loose uniform's name.
std::string slotLeafName(const Module& m, const Slot& slot) {
  std::string full = slotName(m, slot);
  size_t dot = full.find_last_of('.');
  return dot == std::string::npos ? full : full.substr(dot + 1);
}

bool slotMatchesName(const Module& m, const Slot& slot, const std::string& wanted) {
  if (wanted.empty()) return false;
  if (slotName(m, slot) == wanted || slotLeafName(m, slot) == wanted) return true;
  // "Block.member" where the module names the instance.
  if (!slot.indices.empty()) {
    uint32_t type = m.pointeeType(m.definition(slot.variable)->typeId);
    return m.name(type) + "." + m.memberName(type, slot.indices.front()) == wanted;
  }
  return false;
}

// ---- name hints -------------------------------------------------------------------------------

std::string normalizedName(const std::string& name) {
  std::string out;
  for (char c : name)
    if (std::isalnum(static_cast<unsigned char>(c))) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

enum class NameHint { Camera, Light, Neutral };

NameHint nameHint(const std::string& name) {
  std::string n = normalizedName(name);
  for (const char* word : {"light", "lamp", "sun", "shadow", "probe"})
    if (n.find(word) != std::string::npos) return NameHint::Light;
  for (const char* word : {"camera", "campos", "eyepos", "eyeorigin", "eyeworld", "viewpos", "vieworigin", "viewer"})
    if (n.find(word) != std::string::npos) return NameHint::Camera;
  return NameHint::Neutral;
}

// An inverse view-projection matrix by its name: uInvViewProj, invViewProj, InverseViewProjection,
// g_ViewProjInv... A prefix of at most two characters is allowed (u, g, m, cb); longer ones
// (prevInvViewProj, shadowInvViewProj) name some other matrix.
bool namesInverseViewProjection(const std::string& name) {
  std::string n = normalizedName(name);
  for (const char* form : {"invviewproj", "inverseviewproj", "invviewprojection", "inverseviewprojection",
                           "viewprojinv", "viewprojinverse", "viewprojectioninv", "viewprojectioninverse",
                           "invvp", "viewprojectionmatrixinverse", "inverseviewprojectionmatrix",
                           "invviewprojectionmatrix", "invviewprojmatrix"})
    if (n.size() >= std::strlen(form) && n.compare(n.size() - std::strlen(form), std::string::npos, form) == 0 &&
        n.size() - std::strlen(form) <= 2)
      return true;
  return false;
}

// ---- the data flow ------------------------------------------------------------------------------

enum Flow : uint8_t {
  kDerived = 1,    // computed from the seed
  kDirection = 2,  // ... after it became a direction
  kTangent = 4,    // ... after it was multiplied by a tangent frame
};

bool isGlslExtInst(const Module& m, const Instruction& inst, std::initializer_list<GLSLstd450> which) {
  if (inst.opcode != spv::OpExtInst) return false;
  const Instruction* set = m.definition(inst.operand(0));
  if (!set || set->stringOperand(0) != "GLSL.std.450") return false;
  return std::find(which.begin(), which.end(), GLSLstd450(inst.operand(1))) != which.end();
}

bool isVariable(const Module& m, uint32_t id) {
  const Instruction* def = m.definition(id);
  return def && def->opcode == spv::OpVariable;
}

// This pass's questions about one (folded) module, as thin queries on the forward engine of the
// shared value flow (analysis/value_flow.h): what varies per vertex / pixel, and where a value
// derived from some seeds goes.
class FlowQueries {
 public:
  explicit FlowQueries(const Module& m) : m_(m), flow_(m) {}

  const Module& module() const { return m_; }

  // Whether `id` varies per vertex / pixel: it is computed from a stage input (through arithmetic,
  // phis and function-local or private variables).
  bool dependsOnInput(uint32_t id) {
    if (!inputDependent_) {
      ValueFlow::FlagMap seeds;
      for (const auto& inst : m_.typesValues)
        if (inst.opcode == spv::OpVariable && inst.operand(0) == spv::StorageClassInput) seeds[inst.resultId] = kDerived;
      InputRules rules(m_);
      inputDependent_ = flow_.propagate(seeds, rules);
    }
    return !isVariable(m_, id) && ValueFlow::flagsOf(*inputDependent_, id) != 0;
  }

  // A tangent frame: a matrix built in the shader from per-vertex vectors (`mat3(t, b, n)`,
  // possibly transposed) or an interpolated matrix input.
  bool isTangentFrame(uint32_t matrix) {
    const Instruction* def = m_.definition(matrix);
    if (!def) return false;
    if (def->opcode == spv::OpTranspose) return isTangentFrame(def->operand(0));
    if (def->opcode == spv::OpCompositeConstruct) {
      const Instruction* type = m_.definition(def->typeId);
      return type && type->opcode == spv::OpTypeMatrix && dependsOnInput(matrix);
    }
    if (def->opcode == spv::OpLoad) {
      uint32_t root = m_.rootVariable(def->operand(0));
      return root && m_.storageClassOf(root) == spv::StorageClassInput;
    }
    return false;
  }

  struct Sinks {
    uint8_t texcoord = 0;                 // flags seen at texture-coordinate operands
    std::map<uint32_t, uint8_t> outputs;  // output variable -> flags of what is stored to it
    bool anyUse = false;                  // the seed reaches any other instruction
  };

  // Follows the seeds forward to a fixed point. Seeds are values, or variables (their loads).
  // `throughSamples`: a texel fetched at a derived coordinate counts as derived too (for "what
  // changes", not for "what is a view vector").
  Sinks follow(const std::map<uint32_t, uint8_t>& seeds, bool throughSamples = false) {
    ViewVectorRules rules(*this, throughSamples);
    ValueFlow::FlagMap flags = flow_.propagate(ValueFlow::FlagMap(seeds.begin(), seeds.end()), rules);
    for (const auto& [id, f] : flags)
      if (!seeds.count(id)) rules.sinks.anyUse = true;
    return rules.sinks;
  }

 private:
  // "Varies per vertex / pixel": every value computed from a flagged one is flagged; stores carry
  // the flag through function-local and private variables.
  struct InputRules final : ValueFlow::ForwardRules {
    explicit InputRules(const Module& m) : m(m) {}
    const Module& m;
    bool storeCarries(const Instruction&, uint32_t root, ValueFlow::Flags) override {
      auto storage = isVariable(m, root) ? m.storageClassOf(root) : std::nullopt;
      return storage == spv::StorageClassFunction || storage == spv::StorageClassPrivate;
    }
    ValueFlow::Flags resultFlags(const Instruction& inst, const ValueFlow::FlagMap& flags) override {
      return inst.opcode == spv::OpVariable ? 0 : ValueFlow::operandFlags(inst, flags);
    }
  };

  // The view-vector flags: a derived value becomes a direction (normalize, reflect/refract,
  // v.xy / v.z) and a tangent-space vector (times a tangent frame); texture coordinates and
  // outputs are where it ends.
  struct ViewVectorRules final : ValueFlow::ForwardRules {
    ViewVectorRules(FlowQueries& queries, bool throughSamples) : q(queries), throughSamples(throughSamples) {}
    FlowQueries& q;
    bool throughSamples;
    Sinks sinks;

    bool storeCarries(const Instruction&, uint32_t root, ValueFlow::Flags f) override {
      if (!isVariable(q.m_, root)) return false;
      if (q.m_.storageClassOf(root) != spv::StorageClassOutput) return true;  // a local: its loads carry the value on
      sinks.outputs[root] |= static_cast<uint8_t>(f);
      return false;
    }

    ValueFlow::Flags resultFlags(const Instruction& inst, const ValueFlow::FlagMap& flags) override {
      auto flagsOf = [&](uint32_t id) { return static_cast<uint8_t>(ValueFlow::flagsOf(flags, id)); };
      if (spirv::isImageSampleOrFetch(inst.opcode)) {
        uint8_t coordinate = flagsOf(spirv::imageCoordinateOperand(inst));
        sinks.texcoord |= coordinate;
        return throughSamples && coordinate ? kDerived : 0;  // a sampled value is not the view vector any more
      }
      int tainted = 0;
      auto f = static_cast<uint8_t>(ValueFlow::operandFlags(inst, flags, &tainted));
      if (!f) return 0;
      if (isGlslExtInst(q.m_, inst, {GLSLstd450Normalize, GLSLstd450Reflect, GLSLstd450Refract})) f |= kDirection;
      // v.xy / v.z: a ratio of two parts of the same vector is a direction's slope.
      if (inst.opcode == spv::OpFDiv && tainted == 2) f |= kDirection;
      if (inst.opcode == spv::OpMatrixTimesVector && flagsOf(inst.operand(1)) && q.isTangentFrame(inst.operand(0)))
        f |= kTangent;
      if (inst.opcode == spv::OpVectorTimesMatrix && flagsOf(inst.operand(0)) && q.isTangentFrame(inst.operand(1)))
        f |= kTangent;
      if (inst.opcode == spv::OpCompositeConstruct && isTangentDots(inst, flagsOf)) f |= kTangent;
      return f;
    }

    // vec3(dot(v, t), dot(v, b), dot(v, n)) with per-vertex t, b, n: tangent space by hand.
    template <class FlagsOf>
    bool isTangentDots(const Instruction& construct, FlagsOf flagsOf) {
      int dots = 0;
      for (uint32_t part : construct.operands) {
        const Instruction* def = q.m_.definition(part);
        if (!def || def->opcode != spv::OpDot) continue;
        uint32_t a = def->operand(0), b = def->operand(1);
        if ((flagsOf(a) && q.dependsOnInput(b)) || (flagsOf(b) && q.dependsOnInput(a))) ++dots;
      }
      return dots >= 2;
    }
  };

  const Module& m_;
  ValueFlow flow_;
  std::optional<ValueFlow::FlagMap> inputDependent_;
};

// ---- candidates -----------------------------------------------------------------------------------

// `C - P` / `P - C` with C a vec3/vec4 uniform slot (or the .xyz of one) and P varying.
struct Subtraction {
  uint32_t id = 0;     // the OpFSub
  uint32_t point = 0;  // P
};

std::optional<Slot> cameraSide(const Module& m, uint32_t value) {
  const Instruction* def = m.definition(value);
  if (def && def->opcode == spv::OpVectorShuffle && def->operands.size() == 5 && def->operand(0) == def->operand(1) &&
      def->operand(2) == 0 && def->operand(3) == 1 && def->operand(4) == 2)
    value = def->operand(0);  // camera.xyz
  auto slot = loadedSlot(m, value);
  if (!slot) return std::nullopt;
  const Instruction* type = m.definition(slotType(m, *slot));
  if (!type || type->opcode != spv::OpTypeVector || (type->operand(1) != 3 && type->operand(1) != 4)) return std::nullopt;
  const Instruction* component = m.definition(type->operand(0));
  if (!component || component->opcode != spv::OpTypeFloat) return std::nullopt;
  return slot;
}

std::map<Slot, std::vector<Subtraction>> findSubtractions(FlowQueries& flow) {
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

// ---- where the eye offset comes from ------------------------------------------------------------

struct OffsetSource {
  enum Kind { InverseViewProjection, InvertedClipMatrices, EyeOffsetParams } kind = EyeOffsetParams;
  std::vector<Slot> matrices;  // InverseViewProjection: one; InvertedClipMatrices: product order
  bool columnVectors = true;   // the shader writes M * v (true) or v * M (false, HLSL mul(M, v))
  std::string description;     // the formula, for the report
};

// The matrices that take a point to the clip position: gl_Position = M_k * ... * M_1 * W (or
// W * M_1 * ... * M_k), each a uniform matrix (a slot) or a product of them. Every W along the
// way is a candidate: `VP * (Model * p)` offers both `Model * p` (world) and `p` (object space).
struct ClipChain {
  bool columnVectors = true;
  std::vector<std::vector<Slot>> factors;  // outermost first
  std::vector<uint32_t> points;            // points[i]: the vector factors[i] multiplies

  // The product that takes points[level] to the clip position, in multiplication order.
  std::vector<Slot> productFor(size_t level) const {
    std::vector<Slot> product;
    // M2 * (M1 * W) = (M2 * M1) * W;  (W * M1) * M2 = W * (M1 * M2).
    for (size_t i = 0; i <= level; ++i) {
      const auto& factor = factors[columnVectors ? i : level - i];
      product.insert(product.end(), factor.begin(), factor.end());
    }
    return product;
  }
};

bool expandMatrix(const Module& m, uint32_t matrix, std::vector<Slot>& out) {
  const Instruction* def = m.definition(matrix);
  if (!def) return false;
  if (def->opcode == spv::OpMatrixTimesMatrix)
    return expandMatrix(m, def->operand(0), out) && expandMatrix(m, def->operand(1), out);
  auto slot = loadedSlot(m, matrix);
  if (!slot) return false;
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
bool samePoint(const Module& m, uint32_t point, uint32_t w) {
  if (point == w) return true;
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

// Clip chains of every store to the clip position in the folded module.
std::vector<ClipChain> clipChains(const PassContext& ctx, const Module& f) {
  std::vector<ClipChain> chains;
  spirv::forEachFunctionInstruction(f, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode != spv::OpStore) return;
    uint32_t pointer = inst.operand(0);
    for (const auto& p : ctx.positions) {
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

bool isMat4(const Module& m, uint32_t type) {
  const Instruction* def = m.definition(type);
  if (!def || def->opcode != spv::OpTypeMatrix || def->operand(1) != 4) return false;
  const Instruction* column = m.definition(def->operand(0));
  return column && column->opcode == spv::OpTypeVector && column->operand(1) == 4;
}

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

// ---- emission -----------------------------------------------------------------------------------

uint32_t emitLoadSlot(Module& m, std::vector<Instruction>& out, const Slot& slot) {
  uint32_t type = slotType(m, slot);
  auto storage = *m.storageClassOf(slot.variable);
  uint32_t pointer = slot.variable;
  if (!slot.indices.empty()) {
    std::vector<uint32_t> operands = {slot.variable};
    for (uint32_t index : slot.indices) operands.push_back(m.constantInt(static_cast<int32_t>(index)));
    pointer = m.takeId();
    out.emplace_back(spv::OpAccessChain, m.typePointer(storage, type), pointer, operands);
  }
  uint32_t value = m.takeId();
  out.emplace_back(spv::OpLoad, type, value, std::vector<uint32_t>{pointer});
  return value;
}

// Appends the world-space offset of this eye's centre from the mono camera; returns a vec3 id.
uint32_t emitEyeOffset(PassContext& ctx, std::vector<Instruction>& out, const OffsetSource& source) {
  auto& m = ctx.module;
  uint32_t f = m.typeFloat(32), v3 = m.typeVector(f, 3), v4 = m.typeVector(f, 4);
  auto op = [&](spv::Op code, uint32_t type, std::vector<uint32_t> operands) {
    uint32_t id = m.takeId();
    out.emplace_back(code, type, id, std::move(operands));
    return id;
  };
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

// Rewrites every load of `camera` (the whole vector or one component) into `loaded + offset`.
// Returns how many loads were rewritten. A loop of its own rather than the walker: it inserts the
// offset code after each load while it goes.
int rewriteCameraLoads(PassContext& ctx, const Slot& camera, const OffsetSource& source) {
  auto& m = ctx.module;
  uint32_t f = m.typeFloat(32);
  int rewritten = 0;
  for (auto& fn : m.functions)
    for (auto& block : fn.blocks)
      for (size_t i = 0; i < block.instructions.size(); ++i) {
        if (block.instructions[i].opcode != spv::OpLoad) continue;
        auto slot = slotOfPointer(m, block.instructions[i].operand(0));
        if (!slot || slot->variable != camera.variable) continue;
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
        if (component) {
          addend = m.takeId();
          code.emplace_back(spv::OpCompositeExtract, f, addend, std::vector<uint32_t>{offset, componentIndex});
        } else if (const Instruction* t = m.definition(type); t && t->operand(1) == 4) {
          addend = m.takeId();
          code.emplace_back(spv::OpCompositeConstruct, type, addend, std::vector<uint32_t>{offset, m.constantFloat(0.0f)});
        }
        code.emplace_back(spv::OpFAdd, type, perEye, std::vector<uint32_t>{mono, addend});
        block.instructions.insert(block.instructions.begin() + static_cast<long>(i) + 1, code.begin(), code.end());
        i += code.size();
        m.invalidateDefinitions();
        ++rewritten;
      }
  return rewritten;
}

// ---- the pass -----------------------------------------------------------------------------------

const char* hintName(NameHint hint) {
  switch (hint) {
    case NameHint::Camera: return "camera-like";
    case NameHint::Light: return "light-like";
    case NameHint::Neutral: return "neutral";
  }
  return "?";
}

// The next stage's use of one of our outputs, if the pipeline said.
const StageInputUse* consumerOf(const PassContext& ctx, const Module& f, uint32_t output) {
  if (!ctx.nextStage) return nullptr;
  auto location = f.decorationValue(output, spv::DecorationLocation);
  std::string name = f.name(output);
  for (const auto& input : ctx.nextStage->inputs) {
    if (ctx.nextStage->linkByName ? (!name.empty() && input.name == name)
                                  : (location && input.hasLocation && input.location == *location))
      return &input;
  }
  return nullptr;
}

class PerEyeViewPass final : public Pass {
 public:
  const char* name() const override { return "per-eye-view"; }

  PassResult run(PassContext& ctx) override {
    if (!ctx.options.perEyeView) return PassResult::Unchanged;
    auto& report = ctx.report["passes"][name()];
    nlohmann::json fixed = nlohmann::json::array(), leftAlone = nlohmann::json::array();
    auto finish = [&](PassResult result) {  // a shader with nothing view-dependent gets no entries
      if (!fixed.empty()) report["fixed"] = fixed;
      if (!leftAlone.empty()) report["left_alone"] = leftAlone;
      return result;
    };
    // Already stereo (an earlier run, or the application's own parameters): never twice.
    if (std::string why = ctx.eyeDeclared ? "" : alreadyStereoReason(ctx);
        ctx.classification == Classification::AlreadyStereo || !why.empty()) {
      report["skipped"] = "the shader " + (why.empty() ? std::string("is stereo already") : why);
      return finish(PassResult::Unchanged);
    }
    // Cheap first: a view vector needs a vec3/vec4 subtraction somewhere in the module (inlining
    // and folding never create one), and most shaders have none; the folded copy costs an
    // optimizer run.
    if (ctx.options.cameraUniform.empty() && !hasVectorSubtraction(ctx.module)) return finish(PassResult::Unchanged);
    const Module* folded = foldedCopy(ctx);
    if (!folded) {
      report["skipped"] = "the optimizer could not inline and fold this module; nothing analysed";
      return finish(PassResult::Unchanged);
    }
    FlowQueries flow(*folded);
    auto subtractions = findSubtractions(flow);
    const std::string& forcedName = ctx.options.cameraUniform;

    // The decision, per slot.
    std::map<Slot, std::string> cameras;  // slot -> why
    for (const auto& [slot, subs] : subtractions) {
      std::string name = slotName(*folded, slot);
      NameHint hint = nameHint(name);
      std::map<uint32_t, uint8_t> seeds;
      for (const auto& s : subs) seeds[s.id] = kDerived;
      auto sinks = flow.follow(seeds);
      bool forced = slotMatchesName(*folded, slot, forcedName);
      nlohmann::json note = {{"uniform", name}, {"name_hint", hintName(hint)}};
      auto leave = [&](const std::string& use, const std::string& reason) {
        note["use"] = use;
        note["reason"] = reason;
        leftAlone.push_back(note);
      };
      if (forced) {
        cameras[slot] = "forced by --camera-uniform";
        continue;
      }
      bool offsetsHere = sinks.texcoord & kDirection;
      // Outputs: what the next stage does with them, or the single-shader hint.
      std::vector<std::string> offsetOutputs, shadedOutputs, unknownTangentOutputs, unknownOutputs;
      bool fragment = folded->executionModel() == spv::ExecutionModelFragment;
      for (const auto& [output, f] : sinks.outputs) {
        if (folded->hasDecoration(output, spv::DecorationBuiltIn)) continue;
        std::string outputName = folded->name(output).empty() ? std::to_string(output) : folded->name(output);
        const StageInputUse* use = consumerOf(ctx, *folded, output);
        if (fragment) {
          shadedOutputs.push_back(outputName);  // a colour: nothing after it samples along it
        } else if (use && use->read) {
          bool offsets = (f & kDirection) ? use->feedsTexcoord : use->feedsTexcoordAsDirection;
          (offsets ? offsetOutputs : shadedOutputs).push_back(outputName);
        } else if (f & kTangent) {
          unknownTangentOutputs.push_back(outputName);
        } else {
          unknownOutputs.push_back(outputName);
        }
      }
      auto joined = [](const std::vector<std::string>& list) {
        std::string text;
        for (const auto& s : list) text += (text.empty() ? "" : ", ") + s;
        return text;
      };
      if (hint == NameHint::Light && (offsetsHere || !offsetOutputs.empty() || !unknownTangentOutputs.empty())) {
        leave(offsetsHere || !offsetOutputs.empty() ? "direction that offsets texture coordinates" : "tangent-space vector output",
              "the name says light (a relief self-shadowing ray marches toward the light): not a view vector; "
              "--camera-uniform forces it");
        continue;
      }
      if (offsetsHere) {
        cameras[slot] = "structure: a direction from it offsets texture coordinates in this stage" +
                        std::string(hint == NameHint::Camera ? " (the name agrees)" : "");
        continue;
      }
      if (!offsetOutputs.empty()) {
        cameras[slot] = "structure across stages: " + joined(offsetOutputs) + " is read by " + ctx.nextStage->file +
                        " to offset texture coordinates";
        continue;
      }
      if (!unknownTangentOutputs.empty() && hint == NameHint::Camera) {
        cameras[slot] = "structure + name hint: a tangent-space vector from it is written to " +
                        joined(unknownTangentOutputs) +
                        (ctx.nextStage ? " (which " + ctx.nextStage->file + " does not read)"
                                       : " (single-shader mode: the next stage is not known)") +
                        " and the name says camera";
        continue;
      }
      bool shadingOnly = sinks.texcoord == 0 && unknownOutputs.empty() && unknownTangentOutputs.empty();
      if (shadingOnly && hint == NameHint::Camera && ctx.options.perEyeSpecular) {
        cameras[slot] = "--per-eye-specular: the view vector only shades, and the name says camera";
        continue;
      }
      if (hint == NameHint::Light) {
        leave("light vector", "the name says light: not view-dependent");
      } else if (!unknownOutputs.empty() || !unknownTangentOutputs.empty()) {
        std::vector<std::string> all = unknownOutputs;
        all.insert(all.end(), unknownTangentOutputs.begin(), unknownTangentOutputs.end());
        leave("vector written to " + joined(all),
              "the next stage is not known to offset texture coordinates with it" +
                  std::string(unknownTangentOutputs.empty() ? "" : " and the name does not say camera") +
                  ": convert the pipeline together (--pipeline) or force with --camera-uniform");
      } else if (sinks.texcoord) {
        leave("texture coordinate computed from the difference without making it a direction",
              "a position-dependent lookup (volume, projector), not a view vector");
      } else if (hint == NameHint::Camera) {
        leave(shadedOutputs.empty() ? "shading only (specular)" : "shading only (specular), written to " + joined(shadedOutputs),
              "specular highlights look right with the mono eye (docs/stereo-math.md section 3); --per-eye-specular makes it per-eye");
      } else {
        leave("direction used for shading only", "not known to be a camera (no texture-coordinate offset, no camera-like name)");
      }
    }

    // A forced camera that takes part in no subtraction is still replaced everywhere it is loaded.
    if (!forcedName.empty()) {
      bool found = false;
      for (const auto& [slot, why] : cameras) found |= slotMatchesName(*folded, slot, forcedName);
      if (!found)
        spirv::forEachFunctionInstruction(*folded, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
          if (inst.opcode != spv::OpLoad) return;
          if (auto slot = cameraSide(*folded, inst.resultId); slot && slotMatchesName(*folded, *slot, forcedName)) {
            cameras[*slot] = "forced by --camera-uniform";
            found = true;
          }
        });
      if (!found) {
        ctx.diags.warning(ctx.file, "--camera-uniform '" + forcedName + "': no vec3/vec4 uniform of that name is read in this shader");
        report["forced_camera_not_found"] = forcedName;
      }
    }

    noteOtherViewDependentUses(ctx, *folded, subtractions, cameras, leftAlone);

    if (cameras.empty()) return finish(PassResult::Unchanged);
    // The source-splice route (HLSL geometry / domain) emits the original text: a module change
    // would be lost silently.
    if (ctx.source.language == SourceLanguage::Hlsl &&
        (ctx.source.stage == Stage::Geometry || ctx.source.stage == Stage::TessEvaluation)) {
      for (const auto& [slot, why] : cameras)
        leftAlone.push_back({{"uniform", slotName(*folded, slot)}, {"use", "view vector"},
                             {"reason", "HLSL geometry and domain shaders take the source-splice route, which cannot "
                                        "carry this fix: fix the camera by hand"}});
      return finish(PassResult::Unchanged);
    }

    std::vector<ClipChain> chains = clipChains(ctx, *folded);
    // Outputs that will differ between the eyes once the camera is per eye (by design, like the
    // shifted position): for the report, and for the execution harness's unchanged-outputs check.
    std::set<std::string> perEyeOutputs;
    for (const auto& camera : cameras) {
      const auto& slot = camera.first;  // a named reference: clang 14 cannot capture structured bindings
      std::map<uint32_t, uint8_t> loads;
      spirv::forEachFunctionInstruction(*folded, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
        if (auto loaded = inst.opcode == spv::OpLoad ? slotOfPointer(*folded, inst.operand(0)) : std::nullopt;
            loaded && loaded->variable == slot.variable && loaded->indices.size() >= slot.indices.size() &&
            std::equal(slot.indices.begin(), slot.indices.end(), loaded->indices.begin()))
          loads[inst.resultId] = kDerived;
      });
      for (const auto& [output, f] : flow.follow(loads, /*throughSamples=*/true).outputs)
        if (!folded->hasDecoration(output, spv::DecorationBuiltIn) && !folded->name(output).empty())
          perEyeOutputs.insert(folded->name(output));
    }
    if (!perEyeOutputs.empty()) report["per_eye_outputs"] = perEyeOutputs;
    for (const auto& [slot, why] : cameras) {
      OffsetSource source = chooseOffsetSource(ctx, *folded, slot, subtractions[slot], chains);
      int count = kConvergence + 1;
      if (source.kind == OffsetSource::EyeOffsetParams) count = kEyeOffsetZ + 1;
      if (!ensureEyeParams(ctx, count)) return finish(PassResult::Failed);
      int loads = rewriteCameraLoads(ctx, slot, source);
      std::string name = slotName(ctx.module, slot);
      fixed.push_back({{"uniform", name}, {"why", why}, {"loads_replaced", loads},
                       {"eye_centre", name + " + " + source.description}});
      if (source.kind == OffsetSource::EyeOffsetParams)
        report["application"] =
            "fill " + ctx.eye.names[kEyeOffsetX] + "/" + ctx.eye.names[kEyeOffsetY] + "/" + ctx.eye.names[kEyeOffsetZ] +
            " per eye with the world-space offset of the eye centre, eyeSign*separation*convergence/P00 along the "
            "camera's right axis (stereoshift::runtime::eyeOffsetFromInverseView in include/stereoshift/stereo_runtime.h)";
    }
    return finish(PassResult::Changed);
  }

 private:
  OffsetSource chooseOffsetSource(const PassContext& ctx, const Module& f, const Slot& camera,
                                  const std::vector<Subtraction>& subs, const std::vector<ClipChain>& chains) {
    OffsetSource source;
    // The clip chain of a point this camera is subtracted from: the very matrices the stereo shift
    // is consistent with.
    const ClipChain* chain = nullptr;
    std::vector<Slot> product;
    for (const auto& c : chains)
      for (size_t level = 0; level < c.points.size() && !chain; ++level)
        for (const auto& s : subs)
          if (!chain && samePoint(f, s.point, c.points[level])) {
            chain = &c;
            product = c.productFor(level);
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
    if (chain && !product.empty()) {
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

  // View-dependent things this pass does not change, so a user knows what to check by eye: a
  // camera-like uniform used outside any view vector (fog, LOD distance), gl_FragCoord effects.
  static void noteOtherViewDependentUses(const PassContext& ctx, const Module& f,
                                         const std::map<Slot, std::vector<Subtraction>>& subtractions,
                                         const std::map<Slot, std::string>& cameras, nlohmann::json& leftAlone) {
    (void)ctx;
    std::set<Slot> noted;
    spirv::forEachFunctionInstruction(f, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
      if (inst.opcode != spv::OpLoad) return;
      auto slot = cameraSide(f, inst.resultId);
      if (!slot || subtractions.count(*slot) || cameras.count(*slot) || noted.count(*slot)) return;
      std::string name = slotName(f, *slot);
      if (nameHint(name) != NameHint::Camera) return;
      noted.insert(*slot);
      leftAlone.push_back({{"uniform", name}, {"use", "distance or other maths, no view vector (fog, level of detail)"},
                           {"reason", "the eyes differ by a fraction of the interaxial: mono keeps both eyes alike"}});
    });
    for (uint32_t id : f.entryInterface())
      if (f.decorationValue(id, spv::DecorationBuiltIn) == uint32_t(spv::BuiltInFragCoord)) {
        bool read = spirv::anyFunctionInstruction(f, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
          return inst.opcode == spv::OpLoad && f.rootVariable(inst.operand(0)) == id;
        });
        if (read)
          leftAlone.push_back({{"construct", "gl_FragCoord"}, {"use", "screen-position effect"},
                               {"reason", "pixel positions are already per eye; an effect that maps them back to the "
                                          "world with mono matrices needs deferred-unprojection or a check by eye"}});
      }
  }
};

}  // namespace

bool hasVectorSubtraction(const Module& m) {
  return spirv::anyFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode != spv::OpFSub) return false;
    const Instruction* type = m.definition(inst.typeId);
    return type && type->opcode == spv::OpTypeVector && type->operand(1) >= 3;
  });
}

NextStageFacts analyseStageInputs(PassContext& ctx) {
  NextStageFacts facts;
  facts.file = ctx.file;
  facts.linkByName = ctx.source.language == SourceLanguage::Glsl && !ctx.source.vulkan;
  const Module* folded = foldedCopy(ctx);
  const Module& m = ctx.module;
  std::optional<FlowQueries> flow;
  if (folded) flow.emplace(*folded);
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable || inst.operand(0) != spv::StorageClassInput) continue;
    if (m.hasDecoration(inst.resultId, spv::DecorationBuiltIn)) continue;
    StageInputUse use;
    use.name = m.name(inst.resultId);
    if (auto location = m.decorationValue(inst.resultId, spv::DecorationLocation)) {
      use.location = *location;
      use.hasLocation = true;
    }
    if (flow) {
      auto sinks = flow->follow({{inst.resultId, kDerived}});
      use.read = sinks.anyUse;
      use.feedsTexcoord = sinks.texcoord != 0;
      use.feedsTexcoordAsDirection = (sinks.texcoord & kDirection) != 0;
    }
    facts.inputs.push_back(use);
  }
  return facts;
}

std::unique_ptr<Pass> createPerEyeViewPass() { return std::make_unique<PerEyeViewPass>(); }

}  // namespace stereoshift
