// deferred-unprojection: turns a fragment shader's position rebuild from a stereo depth buffer,
// `q = InvM * vec4(ndc.xy, depth, 1)` (InvM a uniform matrix, depth a texel, ndc from gl_FragCoord /
// SV_Position or an interpolated full-screen UV), into the stereo-correct
//     q' = q - InvM[col 0] * eyeSign*separation*(1 - convergence*q.w)
// applied to q itself, before the perspective divide, and reports the view-dependent constructs it
// leaves alone (other matrix products, gl_FragCoord-based effects, reflections).
//
// Why this is exact (docs/stereo-math.md section 4): the G-buffer of an eye was rendered with the stereo
// projection, whose clip x is x + e*S*(w - C), so the pixel's NDC x is the mono one plus
// e*S*(1 - C/w) while y, z and w are the mono ones. By linearity InvM * (ndc + d*e0) = q_mono +
// d*InvM[col 0]. For a perspective projection (or a view-projection with an affine view) InvM maps
// NDC points to points divided by their eye depth w, so q.w = 1/w, and the w component of
// InvM[col 0] is 0 (an x offset in NDC is a direction), which leaves q.w unchanged: the offset is
// d = e*S*(1 - C*q.w), known from q alone. The same holds for the world form (InvM = inverse
// view-projection) and the view-space form (InvM = inverse projection); only the matrix already in
// the shader is needed. The ndc source does not matter: in each eye's image gl_FragCoord, a
// full-screen UV and an interpolated clip position all give that eye's (stereo) NDC.
//
// Recognition runs on the real module (the backward engine of passes/analysis/value_flow.h),
// through the unoptimised code glslang emits: function-local variables (every store that may reach
// a load), helper functions (pointer parameters followed to each call site, return values to each
// return) and structs (access paths), so the rewrite can
// replace the product's own result id, whose every use then sees q'. Component by component:
//   w: only moves from the literal 1.0 (a point, not a direction);
//   z: computed from a texel (sample, fetch or subpass read; a depth comparison is not a depth),
//      constants and uniforms only (`depth`, `depth*2-1`, a linear remap);
//   x, y: computed from gl_FragCoord or an input varying (fragment stage), uniforms and constants,
//      no texel;
//   the matrix: computed from uniform data only.
#include "passes/pass.h"

#include "passes/analysis/value_flow.h"
#include "passes/ir/image_instructions.h"
#include "passes/ir/replace_uses.h"
#include "passes/ir/walker.h"

#include <glslang/SPIRV/GLSL.std.450.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>

namespace stereoshift {

using analysis::AccessPath;
using analysis::kAnyIndex;
using analysis::ValueFlow;
using spirv::Instruction;

namespace {

// What a value is computed from.
struct Sources {
  bool fragCoord = false;  // gl_FragCoord / SV_Position
  bool varying = false;    // another fragment input (full-screen UV, interpolated clip position)
  bool texel = false;      // an image sample, fetch or read
  bool uniform = false;    // uniform, push-constant or specialization-constant data
  bool constant = false;
  bool other = false;      // anything the analysis does not see through
  bool arithmetic = false;            // computed, not only moved
  bool constantOtherThanOne = false;  // some constant leaf is not the float 1.0
  bool eyeParameter = false;          // stereoshift's own eye parameters: injected code
  std::set<std::string> inputs, textures, uniforms;
  std::set<uint32_t> products;  // matrix x vector products the value went through

  Sources& operator|=(const Sources& o) {
    fragCoord |= o.fragCoord;
    varying |= o.varying;
    texel |= o.texel;
    uniform |= o.uniform;
    constant |= o.constant;
    other |= o.other;
    arithmetic |= o.arithmetic;
    constantOtherThanOne |= o.constantOtherThanOne;
    eyeParameter |= o.eyeParameter;
    inputs.insert(o.inputs.begin(), o.inputs.end());
    textures.insert(o.textures.begin(), o.textures.end());
    uniforms.insert(o.uniforms.begin(), o.uniforms.end());
    products.insert(o.products.begin(), o.products.end());
    return *this;
  }
};

std::string lower(std::string text) {
  for (auto& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string joined(const std::set<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "?" : out;
}

bool isFragCoord(const spirv::Module& m, uint32_t root, const AccessPath& path) {
  if (m.decorationValue(root, spv::DecorationBuiltIn) == uint32_t(spv::BuiltInFragCoord)) return true;
  const Instruction* var = m.definition(root);
  if (!var || path.empty() || path[0] == kAnyIndex) return false;
  return m.memberDecorationValue(m.pointeeType(var->typeId), path[0], spv::DecorationBuiltIn) ==
         uint32_t(spv::BuiltInFragCoord);
}

// A variable (and the member a path starts with) as the source names it.
std::string describe(const spirv::Module& m, uint32_t root, const AccessPath& path) {
  const Instruction* var = m.definition(root);
  std::string name = m.name(root);
  if (var && !path.empty() && path[0] != kAnyIndex) {
    uint32_t type = m.pointeeType(var->typeId);
    const Instruction* typeDef = m.definition(type);
    if (typeDef && typeDef->opcode == spv::OpTypeStruct) {
      std::string member = m.memberName(type, path[0]);
      // HLSL cbuffers and globals are anonymous instances: their members are what the source names.
      if (name.empty() || name == "$Global") return member;
      return name + "." + member;
    }
  }
  return name.empty() ? "%" + std::to_string(root) : name;
}

// The leaves of "what is this computed from" for this pass, on the shared backward value flow
// (analysis/value_flow.h): constants, uniforms, inputs, texels, the eye parameters.
class SourceRules {
 public:
  // `eyeParameters`: the injected eye-parameter variables / constants. `opaqueProducts`: products
  // whose result counts as computed from nothing (the fixed unprojections, when asking what else
  // a value depends on).
  SourceRules(const ValueFlow& flow, bool hlsl, std::set<uint32_t> eyeParameters, std::set<uint32_t> opaqueProducts)
      : flow_(flow), hlsl_(hlsl), eyeParameters_(std::move(eyeParameters)), opaqueProducts_(std::move(opaqueProducts)) {}

  Sources unknown() const {
    Sources s;
    s.other = true;
    return s;
  }

  std::optional<Sources> leaf(const Instruction& def, const AccessPath&) const {
    const spirv::Module& m = flow_.module();
    Sources s;
    if (eyeParameters_.count(def.resultId)) {  // a specialization constant
      s.uniform = s.eyeParameter = true;
      return s;
    }
    if (opaqueProducts_.count(def.resultId)) {
      s.products.insert(def.resultId);
      return s;
    }
    switch (def.opcode) {
      case spv::OpConstant: case spv::OpConstantTrue: case spv::OpConstantFalse: case spv::OpConstantNull:
        s.constant = true;
        s.constantOtherThanOne = m.floatConstant(def.resultId) != 1.0f;
        return s;
      case spv::OpSpecConstant: case spv::OpSpecConstantTrue: case spv::OpSpecConstantFalse:
      case spv::OpSpecConstantComposite: case spv::OpSpecConstantOp:
        s.uniform = true;  // chosen by the application, like a uniform
        return s;
      default:
        // A texel; a depth comparison is not a depth, and stays unknown.
        if (spirv::isTexelRead(def.opcode)) {
          s.texel = true;
          s.textures.insert(imageName(def.operand(0)));
          return s;
        }
        return std::nullopt;
    }
  }

  Sources moduleVariable(const Instruction& variable, const AccessPath& path) const {
    const spirv::Module& m = flow_.module();
    uint32_t root = variable.resultId;
    Sources s;
    switch (static_cast<spv::StorageClass>(variable.operand(0))) {
      case spv::StorageClassInput:
        if (isFragCoord(m, root, path)) {
          // Only x, y are the pixel position; z (the fragment's depth) and w are the same per eye.
          size_t component = m.hasDecoration(root, spv::DecorationBuiltIn) ? 0 : 1;
          if (path.size() > component && (path[component] == 2 || path[component] == 3)) return unknown();
          s.fragCoord = true;
          s.inputs.insert(hlsl_ ? "SV_Position" : "gl_FragCoord");
        } else if (m.hasDecoration(root, spv::DecorationBuiltIn)) {
          s.other = true;  // gl_FrontFacing, gl_SampleID, ...: not a screen position
        } else {
          s.varying = true;
          s.inputs.insert(describe(m, root, path));
        }
        return s;
      case spv::StorageClassUniform: case spv::StorageClassUniformConstant:
      case spv::StorageClassPushConstant: case spv::StorageClassStorageBuffer:
        s.uniform = true;
        s.eyeParameter = eyeParameters_.count(root) > 0;
        s.uniforms.insert(describe(m, root, path));
        return s;
      default:
        return unknown();
    }
  }

  void computed(const Instruction& def, Sources& s) const {
    s.arithmetic = true;
    if (def.opcode == spv::OpMatrixTimesVector || def.opcode == spv::OpVectorTimesMatrix) s.products.insert(def.resultId);
  }

 private:
  const ValueFlow& flow_;
  bool hlsl_;
  std::set<uint32_t> eyeParameters_, opaqueProducts_;

  std::string imageName(uint32_t image) const {
    for (int depth = 0; depth < 16; ++depth) {
      const Instruction* def = flow_.definition(image);
      if (!def) break;
      if (def->opcode == spv::OpSampledImage || def->opcode == spv::OpImage || def->opcode == spv::OpCopyObject) {
        image = def->operand(0);
        continue;
      }
      if (def->opcode == spv::OpLoad)
        if (auto target = flow_.resolvePointer(def->operand(0))) return describe(flow_.module(), target->root, target->path);
      break;
    }
    return "?";
  }
};

// What a value (or one element of it, by access path) of the real module is computed from: the
// backward engine of the shared value flow with this pass's leaves. Loads look at every store that
// may reach them, whatever the control flow (an over-approximation: a value counts as computed
// from every source it may come from).
class SourceAnalysis {
 public:
  SourceAnalysis(const ValueFlow& flow, bool hlsl, std::set<uint32_t> eyeParameters,
                 std::set<uint32_t> opaqueProducts = {})
      : rules_(flow, hlsl, std::move(eyeParameters), std::move(opaqueProducts)), engine_(flow, rules_) {}
  Sources value(uint32_t id, AccessPath path = {}) { return engine_.value(id, std::move(path)); }

 private:
  SourceRules rules_;
  analysis::BackwardFlow<Sources, SourceRules> engine_;
};

// One recognised unprojection, or the reason a matrix product is not one.
struct Product {
  spirv::Function* function = nullptr;
  uint32_t result = 0;
  bool vectorTimesMatrix = false;  // HLSL mul(M, v): v * M in SPIR-V, M's columns are HLSL rows
  uint32_t matrix = 0, vector = 0;
  Sources matrixSources, x, y, z, w, vectorSources;
  bool recognised = false;
  std::string reason;
};

class DeferredUnprojectionPass final : public Pass {
 public:
  const char* name() const override { return "deferred-unprojection"; }

  PassResult run(PassContext& ctx) override {
    auto& m = ctx.module;
    // A stereo depth buffer is read per pixel in fragment shaders; other stages transform forward.
    if (!ctx.options.deferredUnprojection || m.executionModel() != spv::ExecutionModelFragment)
      return PassResult::Unchanged;
    // Already converted (the eye parameters were there before this run): fixing q again would
    // subtract the parallax twice.
    if (std::string why = ctx.eyeDeclared ? "" : alreadyStereoReason(ctx); !why.empty()) {
      ctx.report["passes"][name()]["left_alone"] = "the shader " + why;
      return PassResult::Unchanged;
    }
    std::set<uint32_t> eyeParameters;
    if (ctx.eyeDeclared) {
      eyeParameters.insert(ctx.eye.variable);
      for (int i = 0; i < kEyeParamCount; ++i) {
        eyeParameters.insert(ctx.eye.looseVariables[i]);
        eyeParameters.insert(ctx.eye.specConstants[i]);
      }
      eyeParameters.erase(0);
    }
    bool hlsl = ctx.source.language == SourceLanguage::Hlsl;
    // One index of the module's memory and calls for both questions below; the module does not
    // change until the rewrite at the end.
    ValueFlow index(m);
    SourceAnalysis flow(index, hlsl, eyeParameters);
    // Looked up, not created: an analysis that finds nothing must leave the module as it was.
    auto isFloat4 = [&](uint32_t type) {
      const Instruction* vector = m.definition(type);
      if (!vector || vector->opcode != spv::OpTypeVector || vector->operand(1) != 4) return false;
      const Instruction* component = m.definition(vector->operand(0));
      return component && component->opcode == spv::OpTypeFloat && component->operand(0) == 32;
    };

    std::vector<Product> products;
    spirv::forEachFunctionInstruction(m, [&](const Instruction& inst, spirv::Function& fn, const spirv::Block&) {
      if (inst.opcode != spv::OpMatrixTimesVector && inst.opcode != spv::OpVectorTimesMatrix) return;
      if (!isFloat4(inst.typeId)) return;  // a 4-component float point, or nothing to do here
      Product p;
      p.function = &fn;
      p.result = inst.resultId;
      p.vectorTimesMatrix = inst.opcode == spv::OpVectorTimesMatrix;
      p.matrix = p.vectorTimesMatrix ? inst.operand(1) : inst.operand(0);
      p.vector = p.vectorTimesMatrix ? inst.operand(0) : inst.operand(1);
      const Instruction* matrixType = m.definition(m.definition(p.matrix)->typeId);
      if (!matrixType || matrixType->operand(1) != 4) return;  // only a mat4 maps NDC points
      products.push_back(std::move(p));
    });
    for (auto& p : products) classify(flow, p);
    // Products computed from the eye parameters were injected by an earlier pass (per-eye-view's
    // eye centre): stereo already, neither fixed nor reported.
    std::erase_if(products, [](const Product& p) { return p.matrixSources.eyeParameter || p.vectorSources.eyeParameter; });
    std::set<uint32_t> fixedResults;
    for (const auto& p : products)
      if (p.recognised) fixedResults.insert(p.result);

    auto& report = ctx.report["passes"][name()];
    nlohmann::json fixed = nlohmann::json::array(), leftAlone = nlohmann::json::array();
    for (const auto& p : products) {
      std::string matrixName = joined(p.matrixSources.uniforms);
      if (p.recognised) {
        fixed.push_back(describeFix(p, matrixName));
        continue;
      }
      // A product computed from a corrected position is already per-eye through it (e.g. the
      // light-space transform of the rebuilt world position for a shadow lookup).
      bool followsFix = std::any_of(p.vectorSources.products.begin(), p.vectorSources.products.end(),
                                    [&](uint32_t r) { return fixedResults.count(r) > 0; });
      nlohmann::json entry;
      entry["construct"] = "matrix * vector";
      entry["matrix"] = p.matrixSources.uniform ? matrixName : std::string("(not uniform)");
      entry["reason"] = followsFix ? "computed from a corrected unprojection: per-eye through it" : p.reason;
      leftAlone.push_back(entry);
    }
    SourceAnalysis besidesFixes(index, hlsl, eyeParameters, fixedResults);
    reportFragCoordUses(ctx, index, besidesFixes, leftAlone);
    reportReflections(ctx, leftAlone);
    if (!fixed.empty()) report["fixed"] = fixed;
    if (!leftAlone.empty()) report["left_alone"] = leftAlone;
    if (fixed.empty()) return PassResult::Unchanged;

    if (!ensureEyeParams(ctx, kConvergence + 1)) return PassResult::Failed;
    for (const auto& p : products)
      if (p.recognised) rewrite(ctx, p);
    m.invalidateDefinitions();
    return PassResult::Changed;
  }

 private:
  static void classify(SourceAnalysis& flow, Product& p) {
    p.matrixSources = flow.value(p.matrix);
    p.vectorSources = flow.value(p.vector);
    p.x = flow.value(p.vector, {0});
    p.y = flow.value(p.vector, {1});
    p.z = flow.value(p.vector, {2});
    p.w = flow.value(p.vector, {3});
    const Sources& mat = p.matrixSources;
    auto screenCoordinate = [](const Sources& s) {
      return (s.fragCoord || s.varying) && !s.texel && !s.other;
    };
    if (!mat.uniform || mat.fragCoord || mat.varying || mat.texel || mat.other) {
      p.reason = "the matrix is not uniform data";
    } else if (!(p.w.constant && !p.w.constantOtherThanOne && !p.w.arithmetic && !p.w.fragCoord && !p.w.varying &&
                 !p.w.texel && !p.w.uniform && !p.w.other)) {
      p.reason = p.w.constant && p.w.constantOtherThanOne && !p.w.arithmetic && !p.w.uniform && !p.w.other &&
                         !p.w.texel && !p.w.fragCoord && !p.w.varying
                     ? "w is a constant other than 1: a direction, not a point"
                     : "w is not the constant 1: not a point in NDC";
    } else if (!(p.z.texel && !p.z.fragCoord && !p.z.varying && !p.z.other)) {
      p.reason = "z is not a depth read from a texture";
    } else if (!screenCoordinate(p.x) || !screenCoordinate(p.y)) {
      p.reason = "x, y are not screen coordinates (gl_FragCoord or an interpolated UV)";
    } else {
      p.recognised = true;
    }
  }

  static nlohmann::json describeFix(const Product& p, const std::string& matrixName) {
    nlohmann::json entry;
    entry["matrix"] = matrixName;
    // The fix is the same for both; the form only tells a person which space the result is in,
    // judged from the matrix's name.
    std::string n = lower(matrixName);
    if (n.find("view") != std::string::npos || matrixName.find("VP") != std::string::npos)
      entry["form"] = "world position from an inverse view-projection";
    else if (n.find("proj") != std::string::npos)
      entry["form"] = "view-space position from an inverse projection";
    else
      entry["form"] = "position from an inverse matrix (space unknown from its name)";
    entry["depth"] = joined(p.z.textures);
    entry["depth_range"] = p.z.arithmetic ? "remapped in the shader (e.g. depth * 2 - 1)" : "as sampled ([0, 1])";
    std::set<std::string> ndc = p.x.inputs;
    ndc.insert(p.y.inputs.begin(), p.y.inputs.end());
    entry["ndc"] = joined(ndc);
    entry["fix"] = "q - " + matrixName + "[col 0] * eyeSign*separation*(1 - convergence*q.w), before the divide";
    return entry;
  }

  // q' = eyeSign != 0 ? q - InvM[col 0] * (eyeSign*separation)*(1 - convergence*q.w) : q.
  // The select keeps a mono draw the original bit for bit (no -0 turned into +0, no 0*inf NaN).
  static void rewrite(PassContext& ctx, const Product& p) {
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

  // gl_FragCoord values that reach an output or a branch other than through a fixed unprojection
  // or a texture lookup (reading this eye's G-buffer at this eye's pixel is per-eye already):
  // screen-space effects computed from the pixel position, left as they are. `flow` treats the
  // fixed unprojections as opaque and never looks through an image coordinate.
  static void reportFragCoordUses(PassContext& ctx, const ValueFlow& index, SourceAnalysis& flow,
                                  nlohmann::json& leftAlone) {
    auto& m = ctx.module;
    std::set<std::string> reaches;
    spirv::forEachFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
      if (inst.opcode == spv::OpStore) {
        auto target = index.resolvePointer(inst.operand(0));
        if (!target || m.storageClassOf(target->root) != spv::StorageClassOutput) return;
        if (flow.value(inst.operand(1)).fragCoord) reaches.insert(describe(m, target->root, target->path));
      } else if (inst.opcode == spv::OpBranchConditional || inst.opcode == spv::OpSwitch) {
        if (flow.value(inst.operand(0)).fragCoord) reaches.insert("a branch (e.g. a discard)");
      }
    });
    for (const auto& target : reaches) {
      nlohmann::json entry;
      entry["construct"] = ctx.source.language == SourceLanguage::Hlsl ? "SV_Position" : "gl_FragCoord";
      entry["reaches"] = target;
      entry["reason"] = "screen-space computation from this eye's pixel position, left as it is: check by eye";
      leftAlone.push_back(entry);
    }
  }

  static void reportReflections(PassContext& ctx, nlohmann::json& leftAlone) {
    auto& m = ctx.module;
    uint32_t glsl = 0;
    for (const auto& inst : m.extInstImports)
      if (inst.stringOperand(0) == "GLSL.std.450") glsl = inst.resultId;
    if (!glsl) return;
    int reflections = 0, refractions = 0;
    spirv::forEachFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
      if (inst.opcode == spv::OpExtInst && inst.operand(0) == glsl) {
        reflections += inst.operand(1) == GLSLstd450Reflect;
        refractions += inst.operand(1) == GLSLstd450Refract;
      }
    });
    auto add = [&](int count, const char* what) {
      if (!count) return;
      nlohmann::json entry;
      entry["construct"] = what;
      entry["count"] = count;
      entry["reason"] = "built from the shader's view vector: with a mono camera position both eyes see "
                        "the mono reflection; check by eye";
      leftAlone.push_back(entry);
    };
    add(reflections, "reflect()");
    add(refractions, "refract()");
  }
};

}  // namespace

std::unique_ptr<Pass> createDeferredUnprojectionPass() { return std::make_unique<DeferredUnprojectionPass>(); }

}  // namespace stereoshift
