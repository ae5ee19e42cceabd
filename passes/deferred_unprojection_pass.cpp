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
#include "passes/analysis/uniform_slots.h"
#include "passes/deferred_unprojection/row_products.h"
#include "passes/deferred_unprojection/unprojection.h"
#include "passes/eye_param_emitter.h"
#include "passes/ir/image_instructions.h"
#include "passes/ir/walker.h"
#include "passes/pass.h"
#include "passes/pass_registry.h"

#include <glslang/SPIRV/GLSL.std.450.h>

#include <algorithm>
#include <optional>
#include <set>

namespace stereoshift {

using spirv::Instruction;
using namespace deferred;

namespace {

ViewDependentUse describeRayFix(const RayProduct& r, const std::string& injectedName) {
  ViewDependentUse entry;
  entry.construct = "view ray * depth";
  entry.form = r.form;
  entry.depth = joined(r.depth.textures);
  entry.projectionScale = r.scale.kind == ScaleKind::InverseElement ? "1 / " + r.scale.name + "[0][0]"
                          : r.scale.kind == ScaleKind::Injected     ? injectedName + " (injected: set by the application)"
                                                                    : r.scale.name + "[0][0]";
  entry.fix = "p.x - eyeSign*separation*(|p.z| - convergence) / P00, after the last scaling of the product";
  return entry;
}

ViewDependentUse describeFix(const Product& p, const std::string& matrixName) {
  ViewDependentUse entry;
  entry.matrix = matrixName;
  // The fix is the same for both; the form only tells a person which space the result is in,
  // judged from the matrix's name.
  std::string n = lower(matrixName);
  if (n.find("view") != std::string::npos || matrixName.find("VP") != std::string::npos)
    entry.form = "world position from an inverse view-projection";
  else if (n.find("proj") != std::string::npos)
    entry.form = "view-space position from an inverse projection";
  else
    entry.form = "position from an inverse matrix (space unknown from its name)";
  entry.depth = joined(p.z.textures);
  entry.depthRange = p.z.arithmetic ? "remapped in the shader (e.g. depth * 2 - 1)" : "as sampled ([0, 1])";
  std::set<std::string> ndc = p.x.inputs;
  ndc.insert(p.y.inputs.begin(), p.y.inputs.end());
  entry.ndc = joined(ndc);
  entry.fix = "q - " + matrixName + "[col 0] * eyeSign*separation*(1 - convergence*q.w), before the divide";
  return entry;
}

// gl_FragCoord values that reach an output or a branch other than through a fixed unprojection
// or a texture lookup (reading this eye's G-buffer at this eye's pixel is per-eye already):
// screen-space effects computed from the pixel position, left as they are. `flow` treats the
// fixed unprojections as opaque and never looks through an image coordinate.
void reportFragCoordUses(PassContext& ctx, const ValueFlow& index, SourceAnalysis& flow,
                         std::vector<ViewDependentUse>& leftAlone) {
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
    ViewDependentUse entry;
    entry.construct = ctx.source.language == SourceLanguage::Hlsl ? "SV_Position" : "gl_FragCoord";
    entry.reaches = target;
    entry.reason = "screen-space computation from this eye's pixel position, left as it is: check by eye";
    leftAlone.push_back(entry);
  }
}

void reportReflections(PassContext& ctx, std::vector<ViewDependentUse>& leftAlone) {
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
    ViewDependentUse entry;
    entry.construct = what;
    entry.count = count;
    entry.reason = "built from the shader's view vector: with a mono camera position both eyes see "
                   "the mono reflection; check by eye";
    leftAlone.push_back(entry);
  };
  add(reflections, "reflect()");
  add(refractions, "refract()");
}

// The eye parameters the module already declares (from an earlier pass of this run): products
// computed from them were injected, not written by the application.
std::set<uint32_t> declaredEyeParameters(const PassContext& ctx) {
  std::set<uint32_t> ids;
  if (!ctx.eyeDeclared) return ids;
  ids.insert(ctx.eye.variable);
  for (int i = 0; i < kEyeParamCount; ++i) {
    ids.insert(ctx.eye.looseVariables[i]);
    ids.insert(ctx.eye.specConstants[i]);
  }
  ids.erase(0);
  return ids;
}

// Every mat4 * vec4 (or vec4 * mat4) product of float 4-vectors: the candidates.
std::vector<Product> findProducts(spirv::Module& m) {
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
  return products;
}

// What one run found: the facts for the record and what to rewrite.
struct Findings {
  std::vector<ViewDependentUse> fixed, leftAlone;
  std::vector<RayProduct*> fixableRays;
  std::vector<const Product*> reprojections;
  bool needsInjectedScale = false;
};

// The view-ray form, on the same index: each ray x depth product, with the projection scale.
void decideViewRays(PassContext& ctx, const ValueFlow& index, SourceAnalysis& besidesFixes,
                    const std::vector<Product>& products, std::vector<RayProduct>& rays, Findings& found,
                    std::vector<ViewDependentUse>& rayFixes, std::vector<ViewDependentUse>& rayLeftAlone) {
  for (auto& r : rays) {
    findProjectionScale(index, besidesFixes, products, r);
    // No uniform inverse projection making the ray, no uniform matrix re-projecting the position
    // or read at [0][0]: the application supplies P00.
    // An interpolated vector times a texel with no projection anywhere in the shader is as
    // likely a colour times a mask or occlusion as a view ray times a depth: reported, not fixed.
    if (r.scale.kind == ScaleKind::None && r.interpolated) {
      ViewDependentUse entry;
      entry.construct = "interpolated vector * texel";
      entry.form = r.form;
      entry.depth = joined(r.depth.textures);
      entry.reason = "no projection in the shader to tell a view ray (frustum corners) from a colour or "
                     "normal scaled by a texel: if it rebuilds a view-space position, its x is off by "
                     "eyeSign*separation*(depth - convergence)/P00 per eye; check by eye";
      rayLeftAlone.push_back(entry);
      continue;
    }
    if (r.scale.kind == ScaleKind::None) {
      r.scale.kind = ScaleKind::Injected;
      found.needsInjectedScale = true;
    }
    rayFixes.push_back(describeRayFix(r, ctx.eyeDeclared && ctx.eye.declared > kProjScaleX ? ctx.eye.names[kProjScaleX]
                                                                                          : ctx.options.eye.projScaleXName));
    found.fixableRays.push_back(&r);
  }
}

// The local a view ray's corrected value is assigned to, as the text names it: the value's one use
// is a store into a named function variable that nothing else writes (read through loads and
// access chains that are only loaded), so the text's one assignment to that name is the product.
std::optional<std::string> assignedLocal(const ValueFlow& index, uint32_t value) {
  const spirv::Module& m = index.module();
  const spirv::DefUse& du = index.defUse();
  const auto& uses = du.uses(value);
  if (uses.size() != 1 || uses[0].user->opcode != spv::OpStore || uses[0].operand != 1) return std::nullopt;
  uint32_t pointer = uses[0].user->operand(0);
  const Instruction* variable = du.definition(pointer);
  if (!variable || variable->opcode != spv::OpVariable || variable->operand(0) != spv::StorageClassFunction)
    return std::nullopt;
  std::string name = m.name(pointer);
  if (name.empty() || name.starts_with("gl_") || name.find("stereoshift_") != std::string::npos) return std::nullopt;
  for (const auto& use : du.uses(pointer)) {
    if (use.user == uses[0].user || use.user->opcode == spv::OpLoad) continue;
    if (use.user->opcode != spv::OpAccessChain && use.user->opcode != spv::OpInBoundsAccessChain) return std::nullopt;
    for (const auto& read : du.uses(use.user->resultId))
      if (read.user->opcode != spv::OpLoad) return std::nullopt;
  }
  return name;
}

// 1/P00 of a view ray's fix as the text reads it; nullopt when the matrix has no plain name there.
std::optional<std::string> inverseScaleText(const spirv::Module& m, const RayProduct& r) {
  if (r.scale.kind == ScaleKind::Injected) return std::string();
  std::optional<analysis::Slot> slot;
  if (r.scale.kind == ScaleKind::InverseElement) slot = analysis::loadedSlot(m, r.scale.matrixValue);
  if (r.scale.kind == ScaleKind::ProjectionElement) slot = analysis::Slot{r.scale.root, r.scale.path, false};
  auto access = slot ? analysis::slotSourceAccess(m, *slot) : std::nullopt;
  if (!access) return std::nullopt;
  return r.scale.kind == ScaleKind::InverseElement ? *access + "[0][0]" : "(1.0 / " + *access + "[0][0])";
}

// The rewrites as source text can carry them (run_record.h, UnprojectionText, ViewRayText):
// unprojections and re-projections `M * v` through a matrix the text names plainly, and (GLSL) view
// rays whose corrected value the text assigns to a local once.
void recordUnprojectionTexts(const ValueFlow& index, const std::vector<Product>& products, const Findings& found,
                             bool hlsl, DeferredFacts& facts) {
  const spirv::Module& m = index.module();
  if (hlsl && (!found.fixableRays.empty() || !found.reprojections.empty())) {
    facts.unprojectionTextMissing = "a view ray's or a re-projection's fix";
    return;
  }
  std::vector<ViewRayText> rays;
  for (const RayProduct* r : found.fixableRays) {
    auto local = assignedLocal(index, r->fixPoint);
    auto scale = inverseScaleText(m, *r);
    if (!local || !scale) {
      facts.unprojectionTextMissing =
          !local ? "a view ray whose corrected value is not the one value a local of the text is assigned"
                 : "a view ray's fix through a projection the text does not name plainly";
      return;
    }
    rays.push_back({*local, r->components, *scale});
  }
  std::vector<UnprojectionText> texts;
  auto addProduct = [&](const Product& p, bool reprojection) {
    auto slot = analysis::loadedSlot(m, p.matrix);
    auto access = slot ? analysis::slotSourceAccess(m, *slot) : std::nullopt;
    // HLSL writes its products mul(M, v), which glslang makes v * M; GLSL's v * M stays the IR's.
    if ((p.vectorTimesMatrix && !hlsl) || !access) {
      facts.unprojectionTextMissing = p.vectorTimesMatrix ? "an unprojection written `v * M`"
                                                          : "an unprojection through a matrix the text does not name plainly";
      return false;
    }
    texts.push_back({*access, hlsl, reprojection});
    return true;
  };
  for (const auto& p : products)
    if (p.recognised && !addProduct(p, false)) return;
  for (const Product* p : found.reprojections)
    if (!addProduct(*p, true)) return;
  facts.unprojectionTexts = std::move(texts);
  facts.viewRayTexts = std::move(rays);
}

// The matrix products whose results reach the coordinate of a read of a depth texture a fixed
// unprojection reads: a point projected back to the screen and read at in this eye's image (SSAO's
// samples, a reflection's march), not a light-space lookup of a shadow map drawn once for both eyes.
std::set<uint32_t> productsReadAtInTheDepth(const spirv::Module& m, const std::vector<Product>& products,
                                            SourceAnalysis& flow) {
  std::set<std::string> depths;
  for (const auto& p : products)
    if (p.recognised) depths.insert(p.z.textures.begin(), p.z.textures.end());
  std::set<uint32_t> found;
  if (depths.empty()) return found;
  spirv::forEachFunctionInstruction(m, [&](const Instruction& inst, const spirv::Function&, const spirv::Block&) {
    if (!spirv::isTexelRead(inst.opcode) || inst.operands.size() < 2) return;
    const Sources read = flow.value(inst.resultId);
    if (std::none_of(read.textures.begin(), read.textures.end(), [&](const std::string& t) { return depths.count(t) > 0; }))
      return;
    const Sources coordinate = flow.value(inst.operand(1));
    found.insert(coordinate.products.begin(), coordinate.products.end());
  });
  return found;
}

// Each matrix product: an unprojection (fixed), a re-projection of a fixed view-ray position or of
// a point computed from a fixed unprojection read at in its depth texture (shifted back to this
// eye's screen), or left alone with the reason.
void decideProducts(const std::vector<Product>& products, const std::set<uint32_t>& fixedResults,
                    const std::set<uint32_t>& readAtInTheDepth, SourceAnalysis& besidesFixes, Findings& found) {
  for (const auto& p : products) {
    std::string matrixName = joined(p.matrixSources.uniforms);
    if (p.recognised) {
      found.fixed.push_back(describeFix(p, matrixName));
      continue;
    }
    // A product computed from a corrected position is already per-eye through it (e.g. the
    // light-space transform of the rebuilt world position for a shadow lookup).
    bool followsFix = std::any_of(p.vectorSources.products.begin(), p.vectorSources.products.end(),
                                  [&](uint32_t r) { return fixedResults.count(r) > 0; });
    ViewDependentUse entry;
    entry.construct = "matrix * vector";
    entry.matrix = p.matrixSources.uniform ? matrixName : std::string("(not uniform)");
    // A product that makes a fixed view ray, or re-projects a fixed view-ray position, is part
    // of that fix: per-eye through it.
    bool makesRay = std::any_of(found.fixableRays.begin(), found.fixableRays.end(),
                                [&](const RayProduct* r) { return r->ray.products.count(p.result) > 0; });
    bool followsRay = std::any_of(found.fixableRays.begin(), found.fixableRays.end(), [&](const RayProduct* r) {
      return besidesFixes.value(p.vector).products.count(r->fixPoint) > 0;
    });
    // A re-projection of a corrected (mono) view-space position back to this eye's screen (SSAO
    // samples, screen-space reflections) must land where this eye's depth buffer has it: it gets
    // the shift of docs/stereo-math.md section 1, as the G-buffer pass's position did.
    if (followsFix && readAtInTheDepth.count(p.result) && isUniformOnly(p.matrixSources)) {
      entry.construct = "matrix * rebuilt position, read at in the depth texture";
      entry.fix = "x + eyeSign*separation*(w - convergence): back to this eye's screen";
      found.fixed.push_back(entry);
      found.reprojections.push_back(&p);
      continue;
    }
    if (followsRay && !followsFix && isUniformOnly(p.matrixSources)) {
      entry.construct = "matrix * view-ray position";
      entry.fix = "x + eyeSign*separation*(w - convergence): back to this eye's screen";
      found.fixed.push_back(entry);
      found.reprojections.push_back(&p);
      continue;
    }
    entry.reason = followsFix   ? "computed from a corrected unprojection: per-eye through it"
                   : makesRay   ? "makes a view ray: corrected where the ray meets the depth"
                   : followsRay ? "computed from a corrected view-ray position: per-eye through it"
                                : p.reason;
    found.leftAlone.push_back(entry);
  }
}

// The cbuffer-row form (row_products.h) of an HLSL pixel shader: with PassOptions::sourceTextFixes
// each one found becomes a text fix for the HLSL splice (the module is not changed: the register
// copy it is found on is not the module); otherwise, or where the text cannot carry it, it is
// reported with the reason. True when a text fix was recorded.
// The construct and form a found cbuffer-row product is reported as.
void nameTheForm(const RowProductTextFix& fix, ViewDependentUse& entry) {
  entry.construct = fix.basisRay ? "basis vectors in cbuffer rows: (bx * x + by * y + bz) * depth"
                    : fix.scaledByDepth && fix.scaleFromTheMatrix ? "matrix in cbuffer rows * (screen * depth, depth, 1)"
                    : fix.scaledByDepth ? "matrix in cbuffer rows * (ndc * depth, depth, 1)"
                    : fix.uvOfTheDepthTexture ? "matrix in cbuffer rows * (uv, depth, 1)"
                    : fix.scaleFromTheMatrix  ? "matrix in cbuffer rows * (screen coordinate, depth, 1)"
                                                : "matrix in cbuffer rows * vector";
  entry.form = fix.basisRay
                   ? "position rebuilt as a ray of cbuffer basis vectors times the view depth (the screen-to-world map "
                     "in another order; corrected where the ray's part along the view axis is 1, checked at run time)"
               : fix.scaledByDepth && fix.scaleFromTheMatrix
                   ? "position rebuilt through a screen-to-world matrix from the screen coordinate as the shader reads "
                     "it (a pixel position) held as four cbuffer rows (decompiled mul; the coordinate's half-width from "
                     "the matrix's optical axis, at run time)"
               : fix.scaledByDepth
                   ? "position rebuilt through a screen-to-world matrix held as four cbuffer rows (decompiled mul)"
               : fix.uvOfTheDepthTexture
                   ? "position rebuilt through a matrix from UV space held as four cbuffer rows (decompiled mul; the "
                     "UV is the one the depth is sampled at, NDC = 2u - 1: half the matrix's column of u)"
               : fix.scaleFromTheMatrix
                   ? "position rebuilt through a matrix from the screen coordinate as the shader reads it (a pixel "
                     "position or a UV) held as four cbuffer rows (decompiled mul; the coordinate's half-width from "
                     "the matrix's optical axis, at run time)"
                   : "position rebuilt through a matrix held as four cbuffer rows (decompiled mul)";
}

// A re-projection of a corrected rebuild (reprojections.cpp) as a text fix, or reported with `why`
// it is not fixed.
void recordReprojection(const Reprojection& r, const std::string& why, DeferredFacts& facts) {
  ViewDependentUse entry;
  entry.construct = "re-projection VP * (p, 1) of a corrected position, read at in the depth texture";
  entry.form = "a point computed from the corrected rebuild projected back to the screen through a matrix held "
               "as four cbuffer rows, its clip x the coordinate the depth texture is read at again (SSAO samples, "
               "a reflection's march): this eye's image has the point at clip.x + a*s.x*(clip.w - s.y)";
  entry.matrix = r.rows;
  entry.depth = r.texture;
  if (r.fix.afterLine) entry.line = static_cast<int>(r.fix.afterLine);
  if (!why.empty()) {
    entry.reason = "not fixed: " + why;
    facts.leftAlone.push_back(entry);
    return;
  }
  entry.fix = "clip.x + a*s.x*(clip.w - s.y), a = dot((" + r.fix.rowX[0] + ", " + r.fix.rowX[1] + ", " +
              r.fix.rowX[2] + "), (" + r.fix.column[0] + ", " + r.fix.column[1] + ", " + r.fix.column[2] +
              ")) after line " + std::to_string(r.fix.afterLine);
  facts.fixed.push_back(entry);
  facts.reprojectionTextFixes.push_back(r.fix);
}

// A position rebuilt from an interpolated ray (row_products.h) as a text fix where it is a full-screen
// pass's (checked where it runs), or reported with `why` it is not fixed. True when fixed.
bool recordInterpolatedRay(const InterpolatedRay& r, const std::string& why, DeferredFacts& facts) {
  ViewDependentUse entry;
  entry.construct = "interpolated ray / its z * depth";
  entry.form = "position rebuilt from a ray the vertex shader interpolates (a far-plane corner or a light "
               "volume's view-space position), scaled by one over its z and by the depth";
  entry.depth = joined(r.depth.textures);
  entry.ndc = r.input;
  if (r.line) entry.line = static_cast<int>(r.line);
  if (!why.empty()) {
    entry.reason = "not fixed: " + why;
    facts.leftAlone.push_back(entry);
    return false;
  }
  entry.projectionScale = "x * ddx(" + r.fix.rayX + " / " + r.fix.rayZ + ") - " + r.fix.rayX + " / " + r.fix.rayZ +
                          " (x the pixel's, from SV_Position)";
  entry.fix = "p.x - s.x*(|p.z| - s.y)*sign(p.z)*k after line " + std::to_string(r.fix.afterLine) +
              ", where the ray is a full-screen pass's (" + r.fix.farPlane + " / " + r.fix.rayZ +
              " = 1, checked at run time; a light volume's ray is left as it is)";
  facts.fixed.push_back(entry);
  facts.interpolatedRayTextFixes.push_back(r.fix);
  return true;
}

bool decideRowProducts(PassContext& ctx, DeferredFacts& facts) {
  if (ctx.source.language != SourceLanguage::Hlsl || !hasCbufferRows(ctx.module)) return false;
  const spirv::Module* registers = ctx.analyses.registerSsaCopy();
  if (!registers) return false;
  // A dump that reads 3Dmigoto's StereoParams was fixed by hand (or by an earlier run): a position
  // rebuild in it may be per eye already, and fixing it again would subtract the parallax twice.
  const ValueFlow& index = ctx.analyses.valueFlow();
  bool readsStereoParams = false;
  for (const auto& inst : ctx.module.typesValues)
    readsStereoParams |= inst.opcode == spv::OpVariable && ctx.module.name(inst.resultId) == "StereoParams" &&
                         !index.loadsFrom(inst.resultId).empty();
  // Why a form found is not fixed (its own reason, when the text cannot carry it), or "".
  auto notFixed = [&](const std::string& own) -> std::string {
    if (readsStereoParams) return "the shader already reads 3Dmigoto's StereoParams (fixed by hand?)";
    if (!ctx.options.sourceTextFixes)
      return "this form is fixed in the shader's own HLSL text, with --eye-source 3dmigoto (the dump's StereoParams)";
    return own;
  };
  bool recorded = false;
  DecompiledForms forms = findDecompiledForms(*registers, true, ctx.file);
  for (const RowProduct& p : forms.products) {
    ViewDependentUse entry;
    if (p.interpolated) {
      entry.construct = "matrix in cbuffer rows * interpolated position";
      entry.matrix = p.rows;
      entry.use = "position " + joined(p.x.inputs);
      if (p.fix.afterLine) entry.line = static_cast<int>(p.fix.afterLine);
      entry.reason = "a light-space transform of the interpolated position: a shadow-map or projector lookup is the "
                     "same for both eyes (the map was drawn once) and stays mono; a screen-space lookup of this "
                     "eye's image would need this eye's projection: left as it is, for a person to check";
      facts.leftAlone.push_back(entry);
      continue;
    }
    nameTheForm(p.fix, entry);
    entry.matrix = p.rows;
    entry.depth = p.z.texel ? joined(p.z.textures) : "the fragment's own depth (SV_Position.z)";
    std::set<std::string> ndc = p.x.inputs;
    ndc.insert(p.y.inputs.begin(), p.y.inputs.end());
    entry.ndc = joined(ndc);
    if (p.fix.afterLine) entry.line = static_cast<int>(p.fix.afterLine);
    if (std::string why = notFixed(p.reason); !why.empty()) {
      entry.reason = "not fixed: " + why;
      facts.leftAlone.push_back(entry);
      continue;
    }
    std::string column;
    for (size_t i = 0; i < 4; ++i) column += (i ? ", " : "") + (p.fix.present[i] ? p.fix.column[i] : std::string("-"));
    entry.fix = "q - (" + column + ") * " +
                (p.fix.scaledByDepth && p.fix.scaleFromTheMatrix
                     ? "s.x*(|z| - s.y)*sign(z) * h (h the coordinate's half-width the matrix shows)"
                 : p.fix.scaledByDepth      ? "s.x*(|z| - s.y)*sign(z)"
                 : p.fix.scaleFromTheMatrix ? "s.x*(1 - s.y*q.w) * h (h the coordinate's half-width the matrix shows)"
                                            : "s.x*(1 - s.y*q.w)") +
                " after line " + std::to_string(p.fix.afterLine) +
                (p.fix.present[3] ? ", before the divide" : " (the point has no w: an affine map)");
    facts.fixed.push_back(entry);
    facts.textFixes.push_back(p.fix);
    recorded = true;
    for (const CameraTextFix& camera : p.cameras) {
      ViewDependentUse view;
      view.construct = camera.fromCamera ? "view vector rebuilt position - camera" : "view vector camera - rebuilt position";
      view.form = camera.fromCamera ? "the rebuilt position minus a camera position (reflections, fog rays)"
                                    : "a camera position minus the rebuilt position (specular, Fresnel, reflections)";
      view.uniform = camera.camera[0].substr(0, camera.camera[0].rfind('.'));
      view.line = static_cast<int>(camera.line);
      view.fix = std::string(camera.fromCamera ? "v - " : "v + ") + "s.x*s.y*(" + camera.columnX[0] + ", " +
                 camera.columnX[1] + ", " + camera.columnX[2] +
                 ") after line " + std::to_string(camera.line) +
                 ", where the constant is the camera the matrix shows (checked at run time; a light position is left alone)";
      facts.fixed.push_back(view);
      facts.cameraTextFixes.push_back(camera);
    }
  }
  for (const Reprojection& r : forms.reprojections) recordReprojection(r, notFixed(r.reason), facts);
  for (const ComponentRay& r : forms.rays) {
    ViewDependentUse entry;
    entry.construct = "view-space x = ndc.x * depth * k, per component";
    entry.form = "view-space position rebuilt from depth one component at a time (decompiled view ray)";
    entry.depth = joined(r.depth.textures);
    entry.ndc = joined(r.x.inputs);
    // k is 1/P00, or spelled `(1 / P00)` where the shader divides by P00.
    const std::string& k = r.fix.scale;
    entry.projectionScale = k.empty()                ? std::string("?")
                            : k.rfind("(1 / ", 0) == 0 ? k.substr(5, k.size() - 6)
                                                       : "1 / " + k;
    if (r.fix.line) entry.line = static_cast<int>(r.fix.line);
    if (std::string why = notFixed(r.reason); !why.empty()) {
      entry.reason = "not fixed: " + why;
      facts.leftAlone.push_back(entry);
      continue;
    }
    entry.fix = "x - s.x*(|depth| - s.y)*|k| after line " + std::to_string(r.fix.line);
    facts.fixed.push_back(entry);
    facts.rayTextFixes.push_back(r.fix);
    recorded = true;
  }
  for (const InterpolatedRay& r : forms.interpolatedRays) recorded |= recordInterpolatedRay(r, notFixed(r.reason), facts);
  return recorded;
}

class DeferredUnprojectionPass final : public Pass {
 public:
  const char* name() const override { return "deferred-unprojection"; }

  PassResult run(PassContext& ctx) override {
    auto& m = ctx.module;
    // A stereo depth buffer is read per pixel in fragment shaders; other stages transform forward.
    if (!ctx.options.deferredUnprojection || m.executionModel() != spv::ExecutionModelFragment)
      return PassResult::Unchanged;
    DeferredFacts& facts = ctx.record.deferred;
    // Already converted (the eye parameters were there before this run): fixing q again would
    // subtract the parallax twice.
    if (std::string why = ctx.eyeDeclared ? "" : alreadyStereoReason(ctx); !why.empty()) {
      facts.leftAloneWhy = "the shader " + why;
      return PassResult::Unchanged;
    }
    std::set<uint32_t> eyeParameters = declaredEyeParameters(ctx);
    bool hlsl = ctx.source.language == SourceLanguage::Hlsl;
    // One index of the module's memory and calls for both questions below; the module does not
    // change until the rewrite at the end (the pass preserves no analysis).
    const ValueFlow& index = ctx.analyses.valueFlow();
    SourceAnalysis flow(index, hlsl, eyeParameters);
    std::vector<Product> products = findProducts(m);
    for (auto& p : products) classify(flow, p);
    // Products computed from the eye parameters were injected by an earlier pass (per-eye-view's
    // eye centre): stereo already, neither fixed nor reported.
    std::erase_if(products, [](const Product& p) { return p.matrixSources.eyeParameter || p.vectorSources.eyeParameter; });
    std::set<uint32_t> fixedResults;
    for (const auto& p : products)
      if (p.recognised) fixedResults.insert(p.result);

    std::vector<RayProduct> rays = findViewRays(m, index, flow, fixedResults);
    std::set<uint32_t> opaque = fixedResults;
    for (const auto& r : rays) opaque.insert(r.fixPoint);
    SourceAnalysis besidesFixes(index, hlsl, eyeParameters, opaque);
    Findings found;
    std::vector<ViewDependentUse> rayFixes, rayLeftAlone;
    decideViewRays(ctx, index, besidesFixes, products, rays, found, rayFixes, rayLeftAlone);
    decideProducts(products, fixedResults, productsReadAtInTheDepth(m, products, besidesFixes), besidesFixes, found);
    found.fixed.insert(found.fixed.end(), rayFixes.begin(), rayFixes.end());
    found.leftAlone.insert(found.leftAlone.end(), rayLeftAlone.begin(), rayLeftAlone.end());
    reportFragCoordUses(ctx, index, besidesFixes, found.leftAlone);
    reportReflections(ctx, found.leftAlone);
    facts.fixed = found.fixed;
    facts.leftAlone = found.leftAlone;
    // Text fixes change the stage's output, not the module.
    bool textFixes = decideRowProducts(ctx, facts);
    if (found.fixed.empty()) return textFixes ? PassResult::Changed : PassResult::Unchanged;

    if (!ensureEyeParams(ctx, found.needsInjectedScale ? kProjScaleX + 1 : kConvergence + 1)) return PassResult::Failed;
    if (found.needsInjectedScale)
      facts.applicationFills = ctx.eye.names[kProjScaleX] +
                               " = P[0][0], the x scale of the projection the G-buffer was drawn with "
                               "(no projection matrix in the shader to take it from)";
    recordUnprojectionTexts(index, products, found, ctx.source.language == SourceLanguage::Hlsl, facts);
    for (const auto& p : products)
      if (p.recognised) rewrite(ctx, p);
    for (const RayProduct* r : found.fixableRays) rewriteRay(ctx, *r);
    for (const Product* p : found.reprojections) rewriteReprojection(ctx, *p);
    m.invalidateDefinitions();
    return PassResult::Changed;
  }
};

}  // namespace

std::unique_ptr<Pass> createDeferredUnprojectionPass() { return std::make_unique<DeferredUnprojectionPass>(); }

PassInfo deferredUnprojectionPassInfo() {
  return {"deferred-unprojection", createDeferredUnprojectionPass,
          "makes position reconstruction in deferred lighting per eye: InvM * vec4(ndc, depth, 1) and viewRay * depth",
          "on (--no-deferred-unprojection turns it off)",
          "independent of the shift, like per-eye-view; last, as it needs nothing the others decide",
          {}, kValueFlowAnalysis, kNoAnalyses, editSet(EditKind::UnprojectionCorrection)};
}

}  // namespace stereoshift
