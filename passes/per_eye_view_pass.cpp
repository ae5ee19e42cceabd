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
// `inverseTranslation`: the slot is a mat4 (a view matrix) and the value meant is the translation
// column of its inverse, `inverse(view)[3]`: the camera position of a shader that has no uniform
// for it.
struct Slot {
  uint32_t variable = 0;
  std::vector<uint32_t> indices;
  bool inverseTranslation = false;
  bool operator<(const Slot& o) const {
    return std::tie(variable, indices, inverseTranslation) < std::tie(o.variable, o.indices, o.inverseTranslation);
  }
  bool operator==(const Slot& o) const {
    return variable == o.variable && indices == o.indices && inverseTranslation == o.inverseTranslation;
  }
};

bool isMat4(const Module& m, uint32_t type);
bool isGlslExtInstIn(const Module& m, const Instruction& inst, GLSLstd450 which);

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
  if (slot.inverseTranslation) {
    const Instruction* matrix = m.definition(type);
    return matrix && matrix->opcode == spv::OpTypeMatrix ? matrix->operand(0) : 0;
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
  return slot.inverseTranslation ? "inverse(" + text + ")[3]" : text;
}

// The innermost name of a slot: the member name, or the loose uniform's name.
std::string slotLeafName(const Module& m, const Slot& slot) {
  Slot plain = slot;
  plain.inverseTranslation = false;
  std::string full = slotName(m, plain);
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
  kOffset = 8,     // a texture coordinate moved along a direction from it: `uv +- f(v)`
};

// An output by where it is written: the variable, and the member of an interface block (or -1).
struct OutputSlot {
  uint32_t variable = 0;
  int64_t member = -1;
  bool operator<(const OutputSlot& o) const { return std::tie(variable, member) < std::tie(o.variable, o.member); }
};

bool isGlslExtInst(const Module& m, const Instruction& inst, std::initializer_list<GLSLstd450> which) {
  if (inst.opcode != spv::OpExtInst) return false;
  const Instruction* set = m.definition(inst.operand(0));
  if (!set || set->stringOperand(0) != "GLSL.std.450") return false;
  return std::find(which.begin(), which.end(), GLSLstd450(inst.operand(1))) != which.end();
}

bool isGlslExtInstIn(const Module& m, const Instruction& inst, GLSLstd450 which) {
  return isGlslExtInst(m, inst, {which});
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

  // An Input / Output variable of block type (`out VS_OUT { ... } vs_out;`): linked member by member.
  bool isInterfaceBlock(uint32_t variable) const {
    const Instruction* var = m_.definition(variable);
    uint32_t type = var ? m_.pointeeType(var->typeId) : 0;
    const Instruction* def = m_.definition(type);
    return def && def->opcode == spv::OpTypeStruct && m_.hasDecoration(type, spv::DecorationBlock);
  }

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
    uint8_t texcoord = 0;                    // flags seen at texture-coordinate operands
    std::map<OutputSlot, uint8_t> outputs;   // output (member) -> flags of what is stored to it
    std::set<uint32_t> subtractions;         // vec3/vec4 `a - b` with a from the seeds, b varying otherwise
    bool anyUse = false;                     // the seed reaches any other instruction
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

    bool storeCarries(const Instruction& store, uint32_t root, ValueFlow::Flags f) override {
      if (!isVariable(q.m_, root)) return false;
      if (q.m_.storageClassOf(root) != spv::StorageClassOutput) return true;  // a local: its loads carry the value on
      OutputSlot output{root, -1};
      if (q.isInterfaceBlock(root))
        if (auto target = q.flow_.resolvePointer(store.operand(0)); target && !target->path.empty() &&
                                                                    target->path.front() != analysis::kAnyIndex)
          output.member = target->path.front();
      sinks.outputs[output] |= static_cast<uint8_t>(f);
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
      // uv +- f(v): a two-component coordinate moved along a direction (parallax, a POM loop's step;
      // the optimizer folds `uv += a * b` into fma(a, b, uv)).
      bool addition = inst.opcode == spv::OpFAdd || inst.opcode == spv::OpFSub || isGlslExtInst(q.m_, inst, {GLSLstd450Fma});
      if (addition && vectorSize(inst.typeId) == 2) {
        size_t first = inst.opcode == spv::OpExtInst ? 2 : 0;
        for (size_t k = first; k < inst.operands.size(); ++k)
          if (flagsOf(inst.operands[k]) & kDirection) f |= kOffset;
      }
      if (inst.opcode == spv::OpFSub && tainted == 1 && vectorSize(inst.typeId) >= 3) {
        uint32_t other = flagsOf(inst.operand(0)) ? inst.operand(1) : inst.operand(0);
        if (q.dependsOnInput(other)) sinks.subtractions.insert(inst.resultId);
      }
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

    uint32_t vectorSize(uint32_t type) const {
      const Instruction* def = q.m_.definition(type);
      return def && def->opcode == spv::OpTypeVector ? def->operand(1) : 0;
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

// The slot a value reads: a load of it, a member of a whole-struct load (`Camera c = camera;
// c.position`), or the translation column of the inverse of a loaded matrix (`inverse(view)[3]`).
std::optional<Slot> valueSlot(const Module& m, uint32_t value) {
  if (auto slot = loadedSlot(m, value)) return slot;
  const Instruction* def = m.definition(value);
  if (!def || def->opcode != spv::OpCompositeExtract) return std::nullopt;
  std::vector<uint32_t> path(def->operands.begin() + 1, def->operands.end());
  const Instruction* from = m.definition(def->operand(0));
  if (from && isGlslExtInstIn(m, *from, GLSLstd450MatrixInverse) && path == std::vector<uint32_t>{3}) {
    auto matrix = loadedSlot(m, from->operand(2));
    if (!matrix || !isMat4(m, slotType(m, *matrix))) return std::nullopt;
    matrix->inverseTranslation = true;
    return matrix;
  }
  auto whole = loadedSlot(m, def->operand(0));
  if (!whole) return std::nullopt;
  const Instruction* type = m.definition(slotType(m, *whole));
  if (!type || type->opcode != spv::OpTypeStruct) return std::nullopt;  // a vector's component: not a position
  whole->indices.insert(whole->indices.end(), path.begin(), path.end());
  return whole;
}

std::optional<Slot> cameraSide(const Module& m, uint32_t value) {
  const Instruction* def = m.definition(value);
  if (def && def->opcode == spv::OpVectorShuffle && def->operands.size() == 5 && def->operand(0) == def->operand(1) &&
      def->operand(2) == 0 && def->operand(3) == 1 && def->operand(4) == 2)
    value = def->operand(0);  // camera.xyz
  auto slot = valueSlot(m, value);
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
  auto v4OfOffset = [&](std::vector<Instruction>& code, uint32_t offset, uint32_t vectorType) {
    const Instruction* t = m.definition(vectorType);
    if (!t || t->operand(1) != 4) return offset;
    uint32_t widened = m.takeId();
    code.emplace_back(spv::OpCompositeConstruct, vectorType, widened, std::vector<uint32_t>{offset, m.constantFloat(0.0f)});
    return widened;
  };
  for (auto& fn : m.functions)
    for (auto& block : fn.blocks)
      for (size_t i = 0; i < block.instructions.size(); ++i) {
        const Instruction& inst = block.instructions[i];
        // inverse(view): its translation column (the camera centre) moves to the eye; the rotation
        // stays, so the inverse is the per-eye camera's.
        if (camera.inverseTranslation) {
          if (!isGlslExtInstIn(m, inst, GLSLstd450MatrixInverse) || loadedSlot(m, inst.operand(2)) !=
                                                                        std::optional<Slot>(Slot{camera.variable, camera.indices}))
            continue;
          uint32_t matrixType = inst.typeId, columnType = slotType(m, camera);
          uint32_t perEye = inst.resultId, mono = m.takeId();
          block.instructions[i].resultId = mono;
          std::vector<Instruction> code;
          uint32_t addend = v4OfOffset(code, emitEyeOffset(ctx, code, source), columnType);
          uint32_t column = m.takeId(), moved = m.takeId();
          code.emplace_back(spv::OpCompositeExtract, columnType, column, std::vector<uint32_t>{mono, 3});
          code.emplace_back(spv::OpFAdd, columnType, moved, std::vector<uint32_t>{column, addend});
          code.emplace_back(spv::OpCompositeInsert, matrixType, perEye, std::vector<uint32_t>{moved, mono, 3});
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
          uint32_t member = m.takeId(), moved = m.takeId();
          std::vector<uint32_t> extract = {mono}, insert = {moved, mono};
          extract.insert(extract.end(), path.begin(), path.end());
          insert.insert(insert.end(), path.begin(), path.end());
          code.emplace_back(spv::OpCompositeExtract, memberType, member, extract);
          code.emplace_back(spv::OpFAdd, memberType, moved, std::vector<uint32_t>{member, addend});
          code.emplace_back(spv::OpCompositeInsert, structType, perEye, insert);
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

// One input or output as the other stage links to it: a loose variable, or a member of a block.
struct InterfaceSlot {
  std::string name;       // the variable's name, or the member's
  std::string blockName;  // the block type's name, for a member
  std::string display;    // for the report: `vs_out.TangentViewPos`
  std::optional<uint32_t> location;
  bool builtin = false;
};

InterfaceSlot interfaceSlot(const Module& m, uint32_t variable, int64_t member) {
  InterfaceSlot slot;
  slot.location = m.decorationValue(variable, spv::DecorationLocation);
  slot.builtin = m.hasDecoration(variable, spv::DecorationBuiltIn);
  slot.name = m.name(variable);
  if (member < 0) {
    slot.display = slot.name.empty() ? std::to_string(variable) : slot.name;
    return slot;
  }
  uint32_t block = m.pointeeType(m.definition(variable)->typeId);
  const Instruction* def = m.definition(block);
  while (def && def->opcode == spv::OpTypeArray) {  // a per-vertex array (`gs_in[]`): its element block
    block = def->operand(0);
    def = m.definition(block);
  }
  auto index = static_cast<uint32_t>(member);
  slot.blockName = m.name(block);
  slot.name = m.memberName(block, index);
  slot.display = (m.name(variable).empty() ? slot.blockName : m.name(variable)) + "." + slot.name;
  slot.builtin |= m.hasMemberDecoration(block, index, spv::DecorationBuiltIn);
  if (slot.location && def)
    for (uint32_t i = 0; i < index && i < def->operands.size(); ++i) *slot.location += spirv::interfaceLocationCount(m, def->operands[i]);
  return slot;
}

// The next stage's use of one of our outputs, if the pipeline said.
const StageInputUse* consumerOf(const PassContext& ctx, const Module& f, const OutputSlot& output) {
  if (!ctx.nextStage) return nullptr;
  InterfaceSlot ours = interfaceSlot(f, output.variable, output.member);
  for (const auto& input : ctx.nextStage->inputs) {
    if (ctx.nextStage->linkByName ? (!ours.name.empty() && input.name == ours.name && input.blockName == ours.blockName)
                                  : (ours.location && input.hasLocation && input.location == *ours.location))
      return &input;
  }
  return nullptr;
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
    if (ctx.options.cameraUniform.empty() && !hasVectorSubtraction(ctx.module) && !passesCameraCandidate(ctx.module))
      return finish(PassResult::Unchanged);
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
      bool offsetsHere = sinks.texcoord & kOffset;
      // A coordinate computed from the direction without moving another one along it: a BRDF table
      // at dot(N, V), an environment map along reflect(-V, N). Shading, mono by default.
      bool looksUpAlong = !offsetsHere && (sinks.texcoord & kDirection);
      // Outputs: what the next stage does with them, or the single-shader hint.
      std::vector<std::string> offsetOutputs, shadedOutputs, unknownTangentOutputs, unknownOutputs;
      bool fragment = folded->executionModel() == spv::ExecutionModelFragment;
      for (const auto& [output, f] : sinks.outputs) {
        InterfaceSlot written = interfaceSlot(*folded, output.variable, output.member);
        if (written.builtin) continue;
        const std::string& outputName = written.display;
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
      if (looksUpAlong && hint != NameHint::Light && ctx.options.perEyeSpecular) {
        cameras[slot] = "--per-eye-specular: a texture is looked up along a direction from it (reflection, BRDF table)";
        continue;
      }
      if (looksUpAlong && hint != NameHint::Light) {
        leave("texture looked up along a direction from it (reflection, BRDF table), no texture coordinate moved along it",
              "a lookup, not relief mapping: reflections and specular terms stay mono by default (no new application "
              "parameters); --per-eye-specular makes them per-eye");
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

    decidePassedCameras(ctx, flow, subtractions, cameras, leftAlone);
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
        if (auto read = inst.resultId ? valueSlot(*folded, inst.resultId) : std::nullopt; read && *read == slot)
          loads[inst.resultId] = kDerived;  // a member of a whole-struct load, inverse(view)[3]
      });
      for (const auto& [output, f] : flow.follow(loads, /*throughSamples=*/true).outputs)
        if (InterfaceSlot written = interfaceSlot(*folded, output.variable, output.member);
            !written.builtin && !written.name.empty())
          perEyeOutputs.insert(written.display);
    }
    if (!perEyeOutputs.empty()) report["per_eye_outputs"] = perEyeOutputs;
    for (const auto& [slot, why] : cameras) {
      std::vector<Subtraction> points = subtractions[slot];
      if (points.empty()) points = pointsWrittenToOutputs(*folded);  // the tutorial form: no subtraction here
      OffsetSource source = chooseOffsetSource(ctx, *folded, slot, points, chains);
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
  // The tutorial form: the camera position itself goes to an output (`TangentViewPos = TBN *
  // viewPos`, beside `TangentFragPos = TBN * FragPos`) and the next stage subtracts it from another
  // input and moves texture coordinates along the difference. With the pipeline's facts that is
  // structure enough; a shader converted alone cannot tell relief mapping from a specular term
  // (the normal-mapping tutorials write the same vertex shader), so it is reported, not guessed.
  static void decidePassedCameras(const PassContext& ctx, FlowQueries& flow,
                                  const std::map<Slot, std::vector<Subtraction>>& subtractions,
                                  std::map<Slot, std::string>& cameras, nlohmann::json& leftAlone) {
    const Module& f = flow.module();
    if (f.executionModel() == spv::ExecutionModelFragment) return;  // its outputs are colours
    auto joined = [](const std::vector<std::string>& list) {
      std::string text;
      for (const auto& s : list) text += (text.empty() ? "" : ", ") + s;
      return text;
    };
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
        const StageInputUse* use = consumerOf(ctx, f, output);
        tangent |= (flags & kTangent) != 0;
        if (!ctx.nextStage) notKnown.push_back(written.display);
        else if (use && use->read && !(flags & kDirection) && use->subtractedForOffset)  // a point, not a direction
          subtractedThere.push_back(written.display);
        else shadingThere.push_back(written.display);
      }
      nlohmann::json note = {{"uniform", name}, {"name_hint", hintName(hint)}};
      if (hint == NameHint::Light) {
        if (subtractedThere.empty()) continue;  // a light position passed on for lighting: nothing to say
        note["use"] = "position written to " + joined(subtractedThere) + ", which the next stage marches along";
        note["reason"] = "the name says light (a relief self-shadowing ray marches toward the light): not a view "
                         "vector; --camera-uniform forces it";
        leftAlone.push_back(note);
        continue;
      }
      if (!subtractedThere.empty()) {
        cameras[slot] = "structure across stages: the camera position goes to " + joined(subtractedThere) + ", which " +
                        ctx.nextStage->file + " subtracts from another input and moves texture coordinates along";
        continue;
      }
      if (!notKnown.empty() && (hint == NameHint::Camera || tangent)) {
        note["use"] = std::string(tangent ? "tangent-space " : "") + "camera position written to " + joined(notKnown);
        note["reason"] = "camera position passed to the next stage; convert the pipeline to decide (--pipeline, or "
                         "--camera-uniform to force): relief mapping needs it per eye, normal-mapped specular does not";
        leftAlone.push_back(note);
      } else if (!shadingThere.empty() && hint == NameHint::Camera) {
        note["use"] = "camera position written to " + joined(shadingThere);
        note["reason"] = ctx.nextStage->file + " does not move texture coordinates along it (shading, a lookup): mono";
        leftAlone.push_back(note);
      }
    }
  }

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
      for (const auto& entry : leftAlone)
        if (entry.contains("uniform") && entry["uniform"] == name) return;  // already said what it does
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

bool passesCameraCandidate(const Module& m) {
  if (m.executionModel() == spv::ExecutionModelFragment) return false;  // nothing after it to pass to
  return spirv::anyFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (isGlslExtInstIn(m, inst, GLSLstd450MatrixInverse)) return true;
    if (inst.opcode != spv::OpLoad) return false;
    auto storage = m.storageClassOf(inst.operand(0));
    if (!storage || !isUniformStorage(*storage)) return false;
    const Instruction* type = m.definition(inst.typeId);
    if (type && type->opcode == spv::OpTypeStruct) return true;  // a whole-struct load of a camera block
    if (!type || type->opcode != spv::OpTypeVector || type->operand(1) < 3) return false;
    const Instruction* component = m.definition(type->operand(0));
    return component && component->opcode == spv::OpTypeFloat;
  });
}

bool hasVectorSubtraction(const Module& m) {
  return spirv::anyFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (inst.opcode != spv::OpFSub) return false;
    const Instruction* type = m.definition(inst.typeId);
    return type && type->opcode == spv::OpTypeVector && type->operand(1) >= 3;
  });
}

namespace {

// The interface type of a stage input: a geometry / tessellation stage reads its per-vertex inputs
// as arrays (`in VS_OUT { ... } gs_in[];`, `in vec3 vNormal[]`), one element a vertex.
uint32_t perVertexType(const Module& m, uint32_t variableType) {
  const Instruction* def = m.definition(variableType);
  while (def && (def->opcode == spv::OpTypeArray || def->opcode == spv::OpTypeRuntimeArray)) def = m.definition(def->operand(0));
  return def ? def->resultId : 0;
}

// Every stage input (a loose variable, or one member of an input block), each described by
// `analyse` from the values that read it.
using DescribeInput = std::function<void(StageInputUse&, FlowQueries&, const std::map<uint32_t, uint8_t>&)>;

NextStageFacts describeStageInputs(PassContext& ctx, const DescribeInput& analyse) {
  NextStageFacts facts;
  facts.file = ctx.file;
  facts.linkByName = ctx.source.language == SourceLanguage::Glsl && !ctx.source.vulkan;
  const Module* folded = foldedCopy(ctx);
  const Module& m = folded ? *folded : ctx.module;  // global ids are shared
  std::optional<FlowQueries> flow;
  if (folded) flow.emplace(*folded);
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable || inst.operand(0) != spv::StorageClassInput) continue;
    if (m.hasDecoration(inst.resultId, spv::DecorationBuiltIn)) continue;
    const Instruction* block = m.definition(perVertexType(m, m.pointeeType(inst.typeId)));
    bool isBlock = block && block->opcode == spv::OpTypeStruct && m.hasDecoration(block->resultId, spv::DecorationBlock);
    if (!isBlock) {
      StageInputUse use;
      use.name = m.name(inst.resultId);
      if (auto location = m.decorationValue(inst.resultId, spv::DecorationLocation)) {
        use.location = *location;
        use.hasLocation = true;
      }
      if (flow) analyse(use, *flow, {{inst.resultId, kDerived}});
      facts.inputs.push_back(use);
      continue;
    }
    // `in VS_OUT { ... } fs_in;`: member by member, each from the loads that read it (a load of the
    // whole block reads them all). Behind the vertex index of an arrayed input (`gs_in[i].member`),
    // the member is the chain's second index.
    const bool arrayed = block->resultId != m.pointeeType(inst.typeId);
    const size_t memberOperand = arrayed ? 2 : 1;
    for (uint32_t member = 0; member < block->operands.size(); ++member) {
      InterfaceSlot slot = interfaceSlot(m, inst.resultId, member);
      if (slot.builtin) continue;
      StageInputUse use;
      use.name = slot.name;
      use.blockName = slot.blockName;
      if (slot.location) {
        use.location = *slot.location;
        use.hasLocation = true;
      }
      std::map<uint32_t, uint8_t> loads;
      spirv::forEachFunctionInstruction(m, [&](const Instruction& load, const spirv::Function&, const spirv::Block&) {
        if (load.opcode != spv::OpLoad || m.rootVariable(load.operand(0)) != inst.resultId) return;
        const Instruction* chain = m.definition(load.operand(0));
        bool isChain = chain && (chain->opcode == spv::OpAccessChain || chain->opcode == spv::OpInBoundsAccessChain);
        bool whole = chain && (chain->opcode == spv::OpVariable || (arrayed && isChain && chain->operands.size() == 2));
        bool thisMember = isChain && chain->operands.size() > memberOperand &&
                          constantValue(m, chain->operand(memberOperand)) == member;
        if (whole || thisMember) loads[load.resultId] = kDerived;
      });
      if (!loads.empty() && flow) analyse(use, *flow, loads);
      facts.inputs.push_back(use);
    }
  }
  return facts;
}

}  // namespace

NextStageFacts analyseStageInputs(PassContext& ctx) {
  return describeStageInputs(ctx, [](StageInputUse& use, FlowQueries& flow, const std::map<uint32_t, uint8_t>& asRead) {
    auto sinks = flow.follow(asRead);
    use.read = sinks.anyUse;
    use.feedsTexcoordAsDirection = (sinks.texcoord & kOffset) != 0;
    for (uint32_t difference : sinks.subtractions)
      if (flow.follow({{difference, kDerived}}).texcoord & kOffset) use.subtractedForOffset = true;
    std::map<uint32_t, uint8_t> asDirection;
    for (const auto& [id, f] : asRead) asDirection[id] = f | kDirection;
    use.feedsTexcoord = (flow.follow(asDirection).texcoord & kOffset) != 0;
  });
}

NextStageFacts carryStageFacts(PassContext& ctx) {
  if (!ctx.nextStage) return {};
  NextStageFacts facts = describeStageInputs(
      ctx, [&](StageInputUse& use, FlowQueries& flow, const std::map<uint32_t, uint8_t>& asRead) {
        auto sinks = flow.follow(asRead);
        use.read = sinks.anyUse;
        // What the stage after does with the outputs this input is written to (a pass-through, or
        // arithmetic on the way) is what it does with this input.
        for (const auto& [output, flags] : sinks.outputs) {
          const StageInputUse* after = consumerOf(ctx, flow.module(), output);
          if (!after) continue;
          use.read |= after->read;
          use.feedsTexcoord |= after->feedsTexcoord;
          use.feedsTexcoordAsDirection |= after->feedsTexcoordAsDirection;
          use.subtractedForOffset |= after->subtractedForOffset;
        }
      });
  facts.file = ctx.nextStage->file + " (through " + ctx.file + ")";
  return facts;
}

std::unique_ptr<Pass> createPerEyeViewPass() { return std::make_unique<PerEyeViewPass>(); }

}  // namespace stereoshift
