// See unprojection.h: recognising unprojections and view rays (deferred_unprojection_pass.cpp has
// the rules and why they are exact).
#include "passes/deferred_unprojection/unprojection.h"

#include "passes/ir/walker.h"

#include <algorithm>
#include <map>

namespace stereoshift::deferred {

using analysis::kAnyIndex;
using spirv::Instruction;

void classify(SourceAnalysis& flow, Product& p) {
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

// Every `ray * depth` product (OpVectorTimesScalar of a float vec3 / vec4) whose vector is a view
// ray and whose scalar a depth read back: see the file comment. Products computed from an already
// fixed unprojection are per-eye through it and skipped.
std::vector<RayProduct> findViewRays(spirv::Module& m, const ValueFlow& index, SourceAnalysis& flow,
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
void findProjectionScale(const ValueFlow& index, SourceAnalysis& besidesFixes,
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

bool isUniformOnly(const Sources& s) {
  return s.uniform && !s.fragCoord && !s.varying && !s.texel && !s.other;
}

}  // namespace stereoshift::deferred
