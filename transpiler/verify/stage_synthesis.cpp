// Pass-through stages for shaders handed to `verify` without the stages in front of them, and the
// stage-interface check: see stage_synthesis.h. The synthesized stages are GLSL text compiled by
// the front end, so they are as valid as any user shader; they take no resources and forward
// every varying the real stage reads, with values derived from one per-vertex seed attribute.
#include "transpiler/verify/stage_synthesis.h"

#include "transpiler/frontend/front_end.h"
#include "transpiler/transpile_options.h"
#include "transpiler/verify/capture_instrument.h"

#include <algorithm>
#include <sstream>

namespace stereoshift::harness {

using spirv::Instruction;
using spirv::Module;

namespace {

bool arrayedInputs(spv::ExecutionModel model) {
  return model == spv::ExecutionModelTessellationControl || model == spv::ExecutionModelTessellationEvaluation ||
         model == spv::ExecutionModelGeometry;
}

uint32_t arrayLength(const Module& m, const Instruction* array) {
  if (!array || array->opcode != spv::OpTypeArray) return 0;
  const Instruction* length = m.definition(array->operand(1));
  return length && length->opcode == spv::OpConstant ? length->operand(0) : 0;
}

// The scalar kind of a numeric type: 'f' float, 'd' double, 'i' int, 'u' uint, 0 other.
char scalarKind(const Module& m, uint32_t type) {
  const Instruction* d = m.definition(type);
  while (d && (d->opcode == spv::OpTypeVector || d->opcode == spv::OpTypeMatrix)) d = m.definition(d->operand(0));
  if (!d) return 0;
  if (d->opcode == spv::OpTypeFloat) return d->operand(0) == 32 ? 'f' : d->operand(0) == 64 ? 'd' : 0;
  if (d->opcode == spv::OpTypeInt && d->operand(0) == 32) return d->operand(1) ? 'i' : 'u';
  return 0;
}

uint32_t componentCount(const Module& m, uint32_t type) {
  const Instruction* d = m.definition(type);
  return d && d->opcode == spv::OpTypeVector ? d->operand(1) : 1;
}

// A GLSL expression of `type` whose scalars are distinct affine functions of the vec4 `seed`
// (x, y, z spread like positions, w = 1): four-component float vectors keep w = 1 so that a
// forwarded point stays a point; integers are small constants, safe as indices.
std::string valueExpression(const Module& m, uint32_t type, const std::string& seed, uint32_t salt, uint32_t& k) {
  const Instruction* d = m.definition(type);
  const std::string name = glslTypeName(m, type);
  auto scalar = [&](char kind, bool pointW) {
    uint32_t n = k++;
    if (kind == 'i' || kind == 'u') return std::string(kind == 'i' ? "int(" : "uint(") + std::to_string((salt + n) % 4) + ")";
    std::ostringstream e;
    if (pointW) {
      e << "1.0";
    } else {
      double scale = 1.0 + 0.0625 * double((salt + n) % 7), offset = 0.125 * double((salt * 3 + n) % 9) - 0.5;
      e << "(" << seed << "." << "xyz"[n % 3] << " * " << scale << " + " << offset << ")";
    }
    return kind == 'd' ? "double" + std::string("(") + e.str() + ")" : e.str();
  };
  switch (d->opcode) {
    case spv::OpTypeFloat:
    case spv::OpTypeInt: return scalar(scalarKind(m, type), false);
    case spv::OpTypeVector: {
      std::string e = name + "(";
      const uint32_t n = d->operand(1);
      const char kind = scalarKind(m, type);
      for (uint32_t i = 0; i < n; ++i) e += (i ? ", " : "") + scalar(kind, n == 4 && i == 3 && (kind == 'f' || kind == 'd'));
      return e + ")";
    }
    case spv::OpTypeMatrix:
    case spv::OpTypeArray: {
      std::string e = name + "(";
      uint32_t n = d->opcode == spv::OpTypeMatrix ? d->operand(1) : arrayLength(m, d);
      for (uint32_t i = 0; i < n; ++i) e += (i ? ", " : "") + valueExpression(m, d->operand(0), seed, salt, k);
      return e + ")";
    }
    default: return name + "(0)";
  }
}

// `layout(location = L, component = C) <qualifier> T name<suffix>;` with an array type spelled
// as `T[N] name[]` for the per-vertex arrays of the tessellation-control stage.
std::string declaration(const Module& m, const InterfaceSlot& s, const std::string& qualifier,
                        const std::string& name, const std::string& suffix = "") {
  std::string layout = "layout(location = " + std::to_string(s.location);
  if (s.component) layout += ", component = " + std::to_string(s.component);
  return layout + ") " + qualifier + " " + glslTypeName(m, s.type) + " " + name + suffix + ";\n";
}

std::string slotName(const char* prefix, const InterfaceSlot& s) {
  return std::string(prefix) + "_" + std::to_string(s.location) + "_" + std::to_string(s.component);
}

Result<Module> compileStage(const std::string& text, Stage stage, const char* label) {
  TranspileOptions options;
  options.stage = stage;
  options.language = SourceLanguage::Glsl;
  Diagnostics diags;
  FrontEndResult result = compileToSpirv(SourceFile{label, text}, options, diags);
  std::string parseError;
  std::optional<Module> m;
  if (result.ok) m = Module::parse(result.spirv, &parseError);
  if (!m)
    return plainError(std::string("cannot synthesize the ") + label + ": " +
                      (result.ok ? parseError : diags.format().substr(0, diags.format().find('\n'))));
  std::string convertError;
  convertOpenGLForVulkan(*m, 15, &convertError);
  return std::move(*m);
}

// Control points the tese needs: its patch arrays' declared size (HLSL InputPatch<T, N>), else
// one more than the largest constant index it reads, at least the domain's corners.
uint32_t controlPointsFor(const Module& tese) {
  uint32_t points = 3;
  for (const auto& mode : tese.executionModes) {
    if (mode.operand(1) == uint32_t(spv::ExecutionModeQuads)) points = 4;
    if (mode.operand(1) == uint32_t(spv::ExecutionModeIsolines)) points = 2;
  }
  std::vector<uint32_t> perVertex;
  for (uint32_t id : tese.entryInterface()) {
    const Instruction* var = tese.definition(id);
    if (!var || var->operand(0) != spv::StorageClassInput || tese.hasDecoration(id, spv::DecorationPatch)) continue;
    const Instruction* type = tese.definition(tese.pointeeType(var->typeId));
    uint32_t length = arrayLength(tese, type);
    if (length && length != 32) return std::min(length, 32u);  // declared size (not gl_MaxPatchVertices)
    perVertex.push_back(id);
  }
  for (const auto& f : tese.functions)
    for (const auto& b : f.blocks)
      for (const auto& inst : b.instructions) {
        if (inst.opcode != spv::OpAccessChain && inst.opcode != spv::OpInBoundsAccessChain) continue;
        if (std::find(perVertex.begin(), perVertex.end(), inst.operand(0)) == perVertex.end()) continue;
        const Instruction* index = tese.definition(inst.operand(1));
        if (index && index->opcode == spv::OpConstant) points = std::max(points, std::min(index->operand(0) + 1, 32u));
      }
  return points;
}

}  // namespace

const char* executionModelName(spv::ExecutionModel model) {
  switch (model) {
    case spv::ExecutionModelVertex: return "vertex";
    case spv::ExecutionModelTessellationControl: return "tessellation-control";
    case spv::ExecutionModelTessellationEvaluation: return "tessellation-evaluation";
    case spv::ExecutionModelGeometry: return "geometry";
    default: return "other";
  }
}

std::string glslTypeName(const Module& m, uint32_t type) {
  const Instruction* d = m.definition(type);
  if (!d) return {};
  const char kind = scalarKind(m, type);
  const std::string prefix = kind == 'd' ? "d" : kind == 'i' ? "i" : kind == 'u' ? "u" : "";
  switch (d->opcode) {
    case spv::OpTypeFloat:
    case spv::OpTypeInt:
      return kind == 'f' ? "float" : kind == 'd' ? "double" : kind == 'i' ? "int" : kind == 'u' ? "uint" : "";
    case spv::OpTypeVector: return kind ? prefix + "vec" + std::to_string(d->operand(1)) : "";
    case spv::OpTypeMatrix:
      if (kind != 'f' && kind != 'd') return {};
      return prefix + "mat" + std::to_string(d->operand(1)) + "x" + std::to_string(componentCount(m, d->operand(0)));
    case spv::OpTypeArray: {
      const Instruction* element = m.definition(d->operand(0));
      uint32_t length = arrayLength(m, d);
      if (!element || element->opcode == spv::OpTypeArray || !length) return {};
      std::string e = glslTypeName(m, d->operand(0));
      return e.empty() ? "" : e + "[" + std::to_string(length) + "]";
    }
    default: return {};
  }
}

std::vector<InterfaceSlot> interfaceSlots(const Module& m, spv::StorageClass storage) {
  std::vector<InterfaceSlot> slots;
  const spv::ExecutionModel model = m.executionModel();
  const bool arrayed = storage == spv::StorageClassInput ? arrayedInputs(model)
                                                         : model == spv::ExecutionModelTessellationControl;
  for (uint32_t id : m.entryInterface()) {
    const Instruction* var = m.definition(id);
    if (!var || var->opcode != spv::OpVariable || var->operand(0) != uint32_t(storage)) continue;
    if (m.hasDecoration(id, spv::DecorationBuiltIn)) continue;
    const bool patch = m.hasDecoration(id, spv::DecorationPatch);
    uint32_t type = m.pointeeType(var->typeId);
    const Instruction* d = m.definition(type);
    if (arrayed && !patch && d && (d->opcode == spv::OpTypeArray || d->opcode == spv::OpTypeRuntimeArray)) {
      type = d->operand(0);
      d = m.definition(type);
    }
    auto location = m.decorationValue(id, spv::DecorationLocation);
    uint32_t component = m.decorationValue(id, spv::DecorationComponent).value_or(0);
    if (d && d->opcode == spv::OpTypeStruct) {
      uint32_t next = location.value_or(0);
      for (uint32_t i = 0; i < d->operands.size(); ++i) {
        if (m.hasMemberDecoration(type, i, spv::DecorationBuiltIn)) continue;
        uint32_t at = m.memberDecorationValue(type, i, spv::DecorationLocation).value_or(next);
        uint32_t comp = m.memberDecorationValue(type, i, spv::DecorationComponent).value_or(0);
        slots.push_back({at, comp, d->operands[i], m.name(id) + "." + m.memberName(type, i), patch});
        next = at + spirv::interfaceLocationCount(m, d->operands[i]);
      }
      continue;
    }
    if (!location) continue;
    slots.push_back({*location, component, type, m.name(id), patch});
  }
  std::sort(slots.begin(), slots.end(), [](const InterfaceSlot& a, const InterfaceSlot& b) {
    return std::tie(a.patch, a.location, a.component) < std::tie(b.patch, b.location, b.component);
  });
  return slots;
}

Status checkStageInterface(const Module& previous, const Module& next) {
  const auto outs = interfaceSlots(previous, spv::StorageClassOutput);
  const auto ins = interfaceSlots(next, spv::StorageClassInput);
  const std::string from = executionModelName(previous.executionModel()), to = executionModelName(next.executionModel());
  for (const InterfaceSlot& in : ins) {
    const InterfaceSlot* match = nullptr;
    for (const InterfaceSlot& out : outs)
      if (out.location == in.location && out.component == in.component && out.patch == in.patch) match = &out;
    auto spelled = [](const Module& m, const InterfaceSlot& s) {
      std::string t = glslTypeName(m, s.type);
      return (t.empty() ? std::string("a type without a GLSL name") : t) + " '" + s.name + "'";
    };
    if (!match)
      return plainError("the " + to + " stage reads location " + std::to_string(in.location) + " (" + spelled(next, in) +
                        ") that the " + from + " stage does not write: the pipeline's stage interfaces do not match");
    // Vulkan lets an output vector carry more components than the input reads; anything else
    // must agree in scalar kind and shape.
    const char outKind = scalarKind(previous, match->type), inKind = scalarKind(next, in.type);
    const Instruction* outType = previous.definition(match->type);
    const Instruction* inType = next.definition(in.type);
    bool vectors = outType && inType && outType->opcode != spv::OpTypeMatrix && inType->opcode != spv::OpTypeMatrix &&
                   outType->opcode != spv::OpTypeArray && inType->opcode != spv::OpTypeArray;
    bool compatible = vectors ? outKind == inKind && outKind != 0 &&
                                    componentCount(previous, match->type) >= componentCount(next, in.type)
                              : glslTypeName(previous, match->type) == glslTypeName(next, in.type);
    if (!compatible)
      return plainError("location " + std::to_string(in.location) + ": the " + from + " stage writes " +
                        spelled(previous, *match) + ", the " + to + " stage reads " + spelled(next, in) +
                        ": the pipeline's stage interfaces do not match");
  }
  return Done{};
}

Result<LeadingStages> synthesizeLeadingStages(const Module& first) {
  LeadingStages leading;
  const spv::ExecutionModel model = first.executionModel();
  if (model == spv::ExecutionModelVertex) return leading;
  const auto inputs = interfaceSlots(first, spv::StorageClassInput);
  for (const auto& s : inputs)
    if (glslTypeName(first, s.type).empty())
      return plainError("cannot synthesize the stages in front of the " + std::string(executionModelName(model)) +
                        " shader: its input '" + s.name + "' (location " + std::to_string(s.location) +
                        ") has a type a pass-through stage cannot forward");
  // The vertex stage: every per-vertex input of the stage after it, from the seed attribute.
  std::ostringstream vs;
  vs << "#version 450\n// synthesized by stereoshift verify: forwards a seed attribute to every varying\n"
     << "layout(location = 0) in vec4 stereoshiftSeed;\n";
  std::ostringstream body;
  for (const auto& s : inputs) {
    if (s.patch) continue;
    vs << declaration(first, s, "out", slotName("stereoshiftVarying", s));
    uint32_t k = 0;
    body << "  " << slotName("stereoshiftVarying", s) << " = "
         << valueExpression(first, s.type, "stereoshiftSeed", s.location * 4 + s.component, k) << ";\n";
  }
  // w > 1 and growing with depth: a clip position that the cutoff does not leave alone and that a
  // later matrix (view-like: z < 0 in front) keeps in front of the camera.
  vs << "void main() {\n" << body.str()
     << "  gl_Position = vec4(stereoshiftSeed.xyz, 1.0 - 0.05 * stereoshiftSeed.z);\n}\n";
  Result<Module> vertex = compileStage(vs.str(), Stage::Vertex, "synthesized vertex stage");
  if (!vertex) return vertex.error();
  leading.modules.push_back(std::move(*vertex));
  leading.names.push_back("vertex (synthesized pass-through)");
  if (model != spv::ExecutionModelTessellationEvaluation) return leading;

  // The tessellation-control stage: per-vertex varyings forwarded, patch ones derived from the
  // first control point, tessellation levels 2 (a few vertices per patch, enough to see the shift).
  std::ostringstream tcs, copy, patch;
  tcs << "#version 450\n// synthesized by stereoshift verify: passes every control point through\n"
      << "layout(vertices = " << controlPointsFor(first) << ") out;\n";
  for (const auto& s : inputs) {
    if (s.patch) {
      tcs << declaration(first, s, "patch out", slotName("stereoshiftPatch", s));
      uint32_t k = 0;
      patch << "    " << slotName("stereoshiftPatch", s) << " = "
            << valueExpression(first, s.type, "gl_in[0].gl_Position", s.location * 4 + s.component + 1, k) << ";\n";
      continue;
    }
    tcs << declaration(first, s, "in", slotName("stereoshiftVarying", s), "[]")
        << declaration(first, s, "out", slotName("stereoshiftControl", s), "[]");
    copy << "  " << slotName("stereoshiftControl", s) << "[gl_InvocationID] = " << slotName("stereoshiftVarying", s)
         << "[gl_InvocationID];\n";
  }
  tcs << "void main() {\n" << copy.str()
      << "  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;\n"
      << "  if (gl_InvocationID == 0) {\n"
      << "    gl_TessLevelOuter[0] = 2.0; gl_TessLevelOuter[1] = 2.0; gl_TessLevelOuter[2] = 2.0;\n"
      << "    gl_TessLevelOuter[3] = 2.0; gl_TessLevelInner[0] = 2.0; gl_TessLevelInner[1] = 2.0;\n"
      << patch.str() << "  }\n}\n";
  Result<Module> control = compileStage(tcs.str(), Stage::TessControl, "synthesized tessellation-control stage");
  if (!control) return control.error();
  leading.modules.push_back(std::move(*control));
  leading.names.push_back("tessellation-control (synthesized pass-through)");
  return leading;
}

uint32_t patchControlPoints(const std::vector<Module>& stages) {
  for (const auto& m : stages) {
    if (m.executionModel() != spv::ExecutionModelTessellationControl) continue;
    for (const auto& mode : m.executionModes)
      if (mode.operand(1) == uint32_t(spv::ExecutionModeOutputVertices)) return mode.operand(2);
  }
  return 3;
}

}  // namespace stereoshift::harness
