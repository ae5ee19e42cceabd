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
//
// Second form, the view ray (docs/stereo-math.md section 4, "view rays"): `p = ray * depth`, a
// float vector computed from gl_FragCoord / an input varying and no texel (the ray: interpolated
// from the full-screen pass's vertex stage, or built here from the pixel and the projection) times
// a scalar computed from a texel (the depth read back; it may also divide by the ray's own
// components, `depth / ray.z`); one texture weighting vectors from several inputs is a basis
// (tangent-space normal mapping), not a ray. Further scalings of the product by values without a texel
// (`ray * depth / ray.z`) are part of it; the fix goes after the last. The pixel's view-space x is
// corrected to the mono one,
//     p.x' = p.x - eyeSign*separation*(|p.z| - convergence) / P00
// with P00 the projection's x scale: 1 / InvP[0][0] when the ray is made by a uniform inverse
// projection, else P[0][0] of a uniform matrix that re-projects the rebuilt position or whose
// [0][0] the shader reads; a shader with none of these gets the eye parameter projScaleX (the
// application sets it to P00) and the report says so, except for an interpolated ray: without a
// projection in the shader it cannot be told from a colour or normal scaled by a texel, and is
// reported, not fixed.
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

// Where the view-ray fix takes the projection's x scale P00 from.
enum class ScaleKind {
  None,
  Injected,           // none in the shader: the injected eye parameter projScaleX, set by the application
  InverseElement,     // the uniform inverse projection that makes the ray: 1/P00 = InvP[0][0]
  ProjectionElement,  // a uniform projection (re-projecting the position, or read at [0][0]): P00 = P[0][0]
};

struct ProjectionScale {
  ScaleKind kind = ScaleKind::None;
  uint32_t matrixValue = 0;  // InverseElement: the loaded matrix, in the fix point's function
  uint32_t root = 0;         // ProjectionElement: the uniform variable and the path to the matrix
  AccessPath path;
  std::string name;
};

// One `ray * depth` product that rebuilds a view-space position.
struct RayProduct {
  spirv::Function* function = nullptr;
  uint32_t product = 0;   // the OpVectorTimesScalar
  uint32_t fixPoint = 0;  // the product, or the last scaling of it by values without a texel
  uint32_t components = 0;
  bool interpolated = false;  // the ray is an input varying, not made in this shader
  Sources ray, depth;
  std::string form;
  ProjectionScale scale;
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

    nlohmann::json rayFixes = nlohmann::json::array(), rayLeftAlone = nlohmann::json::array();
    // The view-ray form, on the same index: each ray x depth product, with the projection scale.
    std::vector<RayProduct> rays = findViewRays(m, index, flow, fixedResults);
    std::set<uint32_t> opaque = fixedResults;
    for (const auto& r : rays) opaque.insert(r.fixPoint);
    SourceAnalysis besidesFixes(index, hlsl, eyeParameters, opaque);
    std::vector<RayProduct*> fixableRays;
    bool needsInjectedScale = false;
    for (auto& r : rays) {
      findProjectionScale(index, besidesFixes, products, r);
      // No uniform inverse projection making the ray, no uniform matrix re-projecting the position
      // or read at [0][0]: the application supplies P00.
      // An interpolated vector times a texel with no projection anywhere in the shader is as
      // likely a colour times a mask or occlusion as a view ray times a depth: reported, not fixed.
      if (r.scale.kind == ScaleKind::None && r.interpolated) {
        nlohmann::json entry;
        entry["construct"] = "interpolated vector * texel";
        entry["form"] = r.form;
        entry["depth"] = joined(r.depth.textures);
        entry["reason"] = "no projection in the shader to tell a view ray (frustum corners) from a colour or "
                          "normal scaled by a texel: if it rebuilds a view-space position, its x is off by "
                          "eyeSign*separation*(depth - convergence)/P00 per eye; check by eye";
        rayLeftAlone.push_back(entry);
        continue;
      }
      if (r.scale.kind == ScaleKind::None) {
        r.scale.kind = ScaleKind::Injected;
        needsInjectedScale = true;
      }
      rayFixes.push_back(describeRayFix(r, ctx.eyeDeclared && ctx.eye.declared > kProjScaleX
                                               ? ctx.eye.names[kProjScaleX]
                                               : ctx.options.eye.projScaleXName));
      fixableRays.push_back(&r);
    }
    auto& report = ctx.report["passes"][name()];
    nlohmann::json fixed = nlohmann::json::array(), leftAlone = nlohmann::json::array();
    std::vector<const Product*> reprojections;
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
      // A product that makes a fixed view ray, or re-projects a fixed view-ray position, is part
      // of that fix: per-eye through it.
      bool makesRay = std::any_of(fixableRays.begin(), fixableRays.end(),
                                  [&](const RayProduct* r) { return r->ray.products.count(p.result) > 0; });
      bool followsRay = std::any_of(fixableRays.begin(), fixableRays.end(), [&](const RayProduct* r) {
        return besidesFixes.value(p.vector).products.count(r->fixPoint) > 0;
      });
      // A re-projection of a corrected (mono) view-space position back to this eye's screen (SSAO
      // samples, screen-space reflections) must land where this eye's depth buffer has it: it gets
      // the shift of docs/stereo-math.md section 1, as the G-buffer pass's position did.
      if (followsRay && !followsFix && isUniformOnly(p.matrixSources)) {
        entry["construct"] = "matrix * view-ray position";
        entry["fix"] = "x + eyeSign*separation*(w - convergence): back to this eye's screen";
        fixed.push_back(entry);
        reprojections.push_back(&p);
        continue;
      }
      entry["reason"] = followsFix   ? "computed from a corrected unprojection: per-eye through it"
                        : makesRay   ? "makes a view ray: corrected where the ray meets the depth"
                        : followsRay ? "computed from a corrected view-ray position: per-eye through it"
                                     : p.reason;
      leftAlone.push_back(entry);
    }
    for (auto& entry : rayFixes) fixed.push_back(entry);
    for (auto& entry : rayLeftAlone) leftAlone.push_back(entry);
    reportFragCoordUses(ctx, index, besidesFixes, leftAlone);
    reportReflections(ctx, leftAlone);
    if (!fixed.empty()) report["fixed"] = fixed;
    if (!leftAlone.empty()) report["left_alone"] = leftAlone;
    if (fixed.empty()) return PassResult::Unchanged;

    if (!ensureEyeParams(ctx, needsInjectedScale ? kProjScaleX + 1 : kConvergence + 1)) return PassResult::Failed;
    if (needsInjectedScale)
      report["application_fills"] = ctx.eye.names[kProjScaleX] +
                                    " = P[0][0], the x scale of the projection the G-buffer was drawn with "
                                    "(no projection matrix in the shader to take it from)";
    for (const auto& p : products)
      if (p.recognised) rewrite(ctx, p);
    for (const RayProduct* r : fixableRays) rewriteRay(ctx, *r);
    for (const Product* p : reprojections) rewriteReprojection(ctx, *p);
    m.invalidateDefinitions();
    return PassResult::Changed;
  }

 private:
  // Every `ray * depth` product (OpVectorTimesScalar of a float vec3 / vec4) whose vector is a view
  // ray and whose scalar a depth read back: see the file comment. Products computed from an already
  // fixed unprojection are per-eye through it and skipped.
  static std::vector<RayProduct> findViewRays(spirv::Module& m, const ValueFlow& index, SourceAnalysis& flow,
                                              const std::set<uint32_t>& fixedResults) {
    std::vector<RayProduct> rays;
    auto floatVectorSize = [&](uint32_t type) -> uint32_t {
      const Instruction* vector = m.definition(type);
      if (!vector || vector->opcode != spv::OpTypeVector) return 0;
      const Instruction* component = m.definition(vector->operand(0));
      bool isFloat32 = component && component->opcode == spv::OpTypeFloat && component->operand(0) == 32;
      return isFloat32 ? vector->operand(1) : 0;
    };
    auto touchesFix = [&](const Sources& s) {
      return std::any_of(s.products.begin(), s.products.end(), [&](uint32_t r) { return fixedResults.count(r) > 0; });
    };
    spirv::forEachFunctionInstruction(m, [&](const Instruction& inst, spirv::Function& fn, const spirv::Block&) {
      if (inst.opcode != spv::OpVectorTimesScalar) return;
      uint32_t components = floatVectorSize(inst.typeId);
      if (components != 3 && components != 4) return;  // a position has at least x, y, z
      RayProduct r;
      r.function = &fn;
      r.product = r.fixPoint = inst.resultId;
      r.components = components;
      r.ray = flow.value(inst.operand(0));
      r.depth = flow.value(inst.operand(1));
      Sources x = flow.value(inst.operand(0), {0}), z = flow.value(inst.operand(0), {2});
      if (r.ray.eyeParameter || r.depth.eyeParameter || touchesFix(r.ray) || touchesFix(r.depth)) return;
      // The ray: per pixel (its x from the pixel position or an interpolated input), no texel.
      if (!(x.fragCoord || x.varying) || x.texel || x.other || r.ray.texel || r.ray.other) return;
      // The depth: read back from a texture; beside the texel only constants, uniforms and the
      // ray's own inputs (`depth / ray.z`), never another per-pixel value.
      if (!r.depth.texel || r.depth.other) return;
      if ((r.depth.varying || r.depth.fragCoord) && !std::includes(r.ray.inputs.begin(), r.ray.inputs.end(), r.depth.inputs.begin(),
                                            r.depth.inputs.end()))
        return;
      bool computedHere = !z.fragCoord && !z.varying;  // `vec3(ndc * tanHalfFov * aspect, -1)`
      bool fromInverse = !r.ray.products.empty();      // `invProj * vec4(ndc, 1, 1)`
      r.interpolated = !computedHere && !fromInverse;
      // An interpolated ray is a vec3 direction; an interpolated vec4 times a texel is a colour
      // times a mask (text, sprites).
      if (r.interpolated && components != 3) return;
      if (!r.interpolated)
        r.form = "view ray computed from " + joined(r.ray.inputs) + (fromInverse ? " and an inverse projection" : "");
      else
        r.form = "view ray interpolated from the vertex stage (" + joined(r.ray.inputs) + ")";
      // Scalings that follow belong to the rebuilt position (`ray * depth / ray.z`).
      for (int step = 0; step < 8; ++step) {
        const auto& uses = index.defUse().uses(r.fixPoint);
        if (uses.size() != 1 || uses[0].operand != 0) break;
        const Instruction* user = uses[0].user;
        bool scales = user->opcode == spv::OpVectorTimesScalar ||
                      ((user->opcode == spv::OpFDiv || user->opcode == spv::OpFMul) && user->typeId == inst.typeId);
        if (!scales || flow.value(user->operand(1)).texel) break;
        r.fixPoint = user->resultId;
      }
      rays.push_back(std::move(r));
    });
    // A view ray meets its depth once. One texture weighting vectors from different inputs is a
    // basis combination (a tangent-space normal, `tn.x * T + tn.y * B + tn.z * N`), not a position.
    std::map<std::string, std::set<std::string>> rayInputsByTexture;
    for (const auto& r : rays)
      for (const auto& texture : r.depth.textures) rayInputsByTexture[texture].insert(joined(r.ray.inputs));
    std::erase_if(rays, [&](const RayProduct& r) {
      return std::any_of(r.depth.textures.begin(), r.depth.textures.end(),
                         [&](const std::string& texture) { return rayInputsByTexture[texture].size() > 1; });
    });
    return rays;
  }

  // The projection's x scale for a view ray, from what the shader already has (file comment).
  static void findProjectionScale(const ValueFlow& index, SourceAnalysis& besidesFixes,
                                  const std::vector<Product>& products, RayProduct& r) {
    const spirv::Module& m = index.module();
    // 1. The inverse projection that makes the ray, when its matrix is at hand where the fix goes.
    for (const auto& p : products) {
      if (!r.ray.products.count(p.result) || !p.matrixSources.uniform || p.matrixSources.texel ||
          p.matrixSources.fragCoord || p.matrixSources.varying || p.matrixSources.other)
        continue;
      if (index.defUse().definingFunction(p.matrix) != r.function) continue;
      r.scale = {ScaleKind::InverseElement, p.matrix, 0, {}, joined(p.matrixSources.uniforms)};
      return;
    }
    auto uniformMatrix = [&](uint32_t matrixValue, ProjectionScale& out) {
      const Instruction* load = index.definition(matrixValue);
      if (!load || load->opcode != spv::OpLoad) return false;
      auto target = index.resolvePointer(load->operand(0));
      if (!target || std::count(target->path.begin(), target->path.end(), kAnyIndex)) return false;
      const Instruction* variable = m.definition(target->root);
      if (!variable || variable->opcode != spv::OpVariable) return false;
      auto storage = static_cast<spv::StorageClass>(variable->operand(0));
      if (storage != spv::StorageClassUniform && storage != spv::StorageClassUniformConstant &&
          storage != spv::StorageClassPushConstant)
        return false;
      out = {ScaleKind::ProjectionElement, 0, target->root, target->path, describe(m, target->root, target->path)};
      return true;
    };
    // 2. A uniform matrix that re-projects the rebuilt position (SSAO's sample projection).
    for (const auto& p : products)
      if (besidesFixes.value(p.vector).products.count(r.fixPoint) && uniformMatrix(p.matrix, r.scale)) return;
    // 3. A uniform matrix whose [0][0] the shader reads (`proj[0][0]`, a radius in pixels).
    bool found = false;
    spirv::forEachFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
      if (found) return;
      if (inst.opcode == spv::OpCompositeExtract && inst.operands.size() == 3 && inst.operand(1) == 0 &&
          inst.operand(2) == 0) {
        const Instruction* source = index.definition(inst.operand(0));
        const Instruction* type = source ? m.definition(source->typeId) : nullptr;
        if (type && type->opcode == spv::OpTypeMatrix && type->operand(1) == 4) found = uniformMatrix(inst.operand(0), r.scale);
      } else if (inst.opcode == spv::OpLoad) {
        auto target = index.resolvePointer(inst.operand(0));
        if (!target || target->path.size() < 2 || target->path[target->path.size() - 1] != 0 ||
            target->path[target->path.size() - 2] != 0)
          return;
        AccessPath toMatrix(target->path.begin(), target->path.end() - 2);
        if (std::count(toMatrix.begin(), toMatrix.end(), kAnyIndex)) return;
        // The type at `toMatrix` must be a mat4: walk the variable's type down the path.
        const Instruction* variable = m.definition(target->root);
        if (!variable || variable->opcode != spv::OpVariable) return;
        auto storage = static_cast<spv::StorageClass>(variable->operand(0));
        if (storage != spv::StorageClassUniform && storage != spv::StorageClassUniformConstant &&
            storage != spv::StorageClassPushConstant)
          return;
        uint32_t type = m.pointeeType(variable->typeId);
        for (uint32_t step : toMatrix) {
          const Instruction* t = m.definition(type);
          if (!t) return;
          if (t->opcode == spv::OpTypeStruct) type = t->operand(step);
          else if (t->opcode == spv::OpTypeArray || t->opcode == spv::OpTypeRuntimeArray) type = t->operand(0);
          else return;
        }
        const Instruction* t = m.definition(type);
        if (!t || t->opcode != spv::OpTypeMatrix || t->operand(1) != 4) return;
        r.scale = {ScaleKind::ProjectionElement, 0, target->root, toMatrix, describe(m, target->root, toMatrix)};
        found = true;
      }
    });
  }

  static nlohmann::json describeRayFix(const RayProduct& r, const std::string& injectedName) {
    nlohmann::json entry;
    entry["construct"] = "view ray * depth";
    entry["form"] = r.form;
    entry["depth"] = joined(r.depth.textures);
    entry["projection_scale"] = r.scale.kind == ScaleKind::InverseElement ? "1 / " + r.scale.name + "[0][0]"
                                : r.scale.kind == ScaleKind::Injected
                                    ? injectedName + " (injected: set by the application)"
                                    : r.scale.name + "[0][0]";
    entry["fix"] = "p.x - eyeSign*separation*(|p.z| - convergence) / P00, after the last scaling of the product";
    return entry;
  }

  // p' = eyeSign != 0 ? p with x - (eyeSign*separation)*(|p.z| - convergence)*(1/P00) : p.
  static void rewriteRay(PassContext& ctx, const RayProduct& r) {
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

  static bool isUniformOnly(const Sources& s) {
    return s.uniform && !s.fragCoord && !s.varying && !s.texel && !s.other;
  }

  // q' = eyeSign != 0 ? q with x + eyeSign*separation*(q.w - convergence) : q.
  static void rewriteReprojection(PassContext& ctx, const Product& p) {
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
