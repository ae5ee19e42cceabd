#include "transpiler/verify/stereo_verify.h"

#include "transpiler/verify/capture_instrument.h"
#include "passes/ir/module.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>

namespace stereoshift::harness {

using spirv::Instruction;
using spirv::Module;

nlohmann::json VerifyResult::json() const {
  return {{"ok", ok},
          {"error", error},
          {"vertices", vertices},
          {"mono_identical", monoIdentical},
          {"max_stereo_error_ulps", maxStereoUlps},
          {"cutoff_vertices", cutoffVertices},
          {"other_outputs_unchanged", otherOutputsUnchanged},
          {"halo_components_changed", haloComponentsChanged},
          {"new_nans", newNaNs},
          {"problems", problems}};
}

namespace {

// The "scene" every matrix uniform gets: a perspective projection (60 degrees, near 0.1, far 200)
// times a view 6 units back, column-major. Any matrix would do for comparing original and
// transpiled on identical inputs; this one spreads w over the comfortable depth range.
void sceneMatrix(float out[16]) {
  const double f = 1.0 / std::tan(std::numbers::pi / 6.0), n = 0.1, fa = 200.0;
  double p[16] = {f, 0, 0, 0, 0, f, 0, 0, 0, 0, fa / (n - fa), -1, 0, 0, fa * n / (n - fa), 0};
  double t[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.3, -0.2, -6, 1};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += p[k * 4 + r] * t[c * 4 + k];
      out[c * 4 + r] = static_cast<float>(s);
    }
}

struct Reflector {
  const Module& m;

  const Instruction* def(uint32_t id) const { return m.definition(id); }

  uint32_t scalarCount(uint32_t type) const {
    const Instruction* d = def(type);
    if (!d) return 0;
    if (d->opcode == spv::OpTypeVector) return d->operand(1);
    return 1;
  }

  void putFloat(std::vector<uint8_t>& bytes, size_t at, float v) const {
    if (bytes.size() < at + 4) bytes.resize(at + 4, 0);
    std::memcpy(bytes.data() + at, &v, 4);
  }
  void putU32(std::vector<uint8_t>& bytes, size_t at, uint32_t v) const {
    if (bytes.size() < at + 4) bytes.resize(at + 4, 0);
    std::memcpy(bytes.data() + at, &v, 4);
  }

  // Fills one value of `type` at `at` with plausible data.
  void fill(std::vector<uint8_t>& bytes, uint32_t type, size_t at, uint32_t matrixStride, bool rowMajor) const {
    const Instruction* d = def(type);
    if (!d) return;
    switch (d->opcode) {
      case spv::OpTypeFloat:
        putFloat(bytes, at, 0.5f);
        break;
      case spv::OpTypeInt:
        putU32(bytes, at, 1);
        break;
      case spv::OpTypeBool:
        putU32(bytes, at, 0);
        break;
      case spv::OpTypeVector: {
        const float values[4] = {0.25f, 0.5f, 0.75f, 1.0f};
        bool isFloat = def(d->operand(0)) && def(d->operand(0))->opcode == spv::OpTypeFloat;
        for (uint32_t i = 0; i < d->operand(1); ++i)
          isFloat ? putFloat(bytes, at + 4 * i, values[i]) : putU32(bytes, at + 4 * i, i);
        break;
      }
      case spv::OpTypeMatrix: {
        uint32_t columns = d->operand(1);
        uint32_t rows = scalarCount(d->operand(0));
        float scene[16];
        sceneMatrix(scene);
        uint32_t stride = matrixStride ? matrixStride : 16;
        for (uint32_t c = 0; c < columns; ++c)
          for (uint32_t r = 0; r < rows; ++r) {
            float v = (columns == 4 && rows == 4) ? scene[c * 4 + r] : (c == r ? 1.0f : 0.0f);
            size_t offset = rowMajor ? r * stride + c * 4 : c * stride + r * 4;
            putFloat(bytes, at + offset, v);
          }
        break;
      }
      case spv::OpTypeArray:
      case spv::OpTypeRuntimeArray: {
        const Instruction* length = d->opcode == spv::OpTypeArray ? def(d->operand(1)) : nullptr;
        uint32_t count = length ? length->operand(0) : 64;  // a runtime array gets 64 elements
        uint32_t stride = m.decorationValue(type, spv::DecorationArrayStride).value_or(16);
        const Instruction* element = def(d->operand(0));
        for (uint32_t i = 0; i < count; ++i) {
          // Arrays of matrices (bone palettes): identity, so skinning keeps the mesh in view.
          if (element && element->opcode == spv::OpTypeMatrix) {
            uint32_t columns = element->operand(1), rows = scalarCount(element->operand(0));
            uint32_t ms = matrixStride ? matrixStride : 16;
            for (uint32_t c = 0; c < columns; ++c)
              for (uint32_t r = 0; r < rows; ++r)
                putFloat(bytes, at + i * stride + (rowMajor ? r * ms + c * 4 : c * ms + r * 4), c == r ? 1.f : 0.f);
          } else {
            fill(bytes, d->operand(0), at + i * stride, matrixStride, rowMajor);
          }
        }
        break;
      }
      case spv::OpTypeStruct:
        for (uint32_t i = 0; i < d->operands.size(); ++i) {
          uint32_t offset = m.memberDecorationValue(type, i, spv::DecorationOffset).value_or(0);
          uint32_t ms = m.memberDecorationValue(type, i, spv::DecorationMatrixStride).value_or(0);
          bool rm = m.hasMemberDecoration(type, i, spv::DecorationRowMajor);
          fill(bytes, d->operands[i], at + offset, ms, rm);
        }
        break;
      default:
        break;
    }
  }

  VkFormat formatOf(uint32_t type, uint32_t* size) const {
    const Instruction* d = def(type);
    uint32_t n = 1;
    if (d && d->opcode == spv::OpTypeVector) {
      n = d->operand(1);
      d = def(d->operand(0));
    }
    *size = 4 * n;
    if (!d) return VK_FORMAT_UNDEFINED;
    static const VkFormat f[] = {VK_FORMAT_R32_SFLOAT, VK_FORMAT_R32G32_SFLOAT, VK_FORMAT_R32G32B32_SFLOAT,
                                 VK_FORMAT_R32G32B32A32_SFLOAT};
    static const VkFormat s[] = {VK_FORMAT_R32_SINT, VK_FORMAT_R32G32_SINT, VK_FORMAT_R32G32B32_SINT,
                                 VK_FORMAT_R32G32B32A32_SINT};
    static const VkFormat u[] = {VK_FORMAT_R32_UINT, VK_FORMAT_R32G32_UINT, VK_FORMAT_R32G32B32_UINT,
                                 VK_FORMAT_R32G32B32A32_UINT};
    if (d->opcode == spv::OpTypeFloat && d->operand(0) == 32) return f[n - 1];
    if (d->opcode == spv::OpTypeInt && d->operand(0) == 32) return d->operand(1) ? s[n - 1] : u[n - 1];
    return VK_FORMAT_UNDEFINED;
  }
};

// Vertex data: attribute 0..n, vertex i spread over x, y in [-2, 2] and z in [-60, 5].
bool buildVertices(const Module& m, uint32_t count, VertexBuffer* vb, std::string* error) {
  Reflector r{m};
  uint32_t offset = 0;
  std::vector<std::pair<uint32_t, uint32_t>> attributes;  // location, type
  for (uint32_t id : m.entryInterface()) {
    const Instruction* var = m.definition(id);
    if (!var || var->operand(0) != spv::StorageClassInput || m.hasDecoration(id, spv::DecorationBuiltIn)) continue;
    auto location = m.decorationValue(id, spv::DecorationLocation);
    if (!location) continue;
    attributes.push_back({*location, m.pointeeType(var->typeId)});
  }
  std::sort(attributes.begin(), attributes.end());
  // A matrix attribute takes one location per column.
  std::vector<std::pair<uint32_t, uint32_t>> expanded;
  for (auto [location, type] : attributes) {
    const Instruction* d = m.definition(type);
    if (d && d->opcode == spv::OpTypeMatrix)
      for (uint32_t c = 0; c < d->operand(1); ++c) expanded.push_back({location + c, d->operand(0)});
    else
      expanded.push_back({location, type});
  }
  attributes = expanded;
  for (auto [location, type] : attributes) {
    uint32_t size = 0;
    VkFormat format = r.formatOf(type, &size);
    if (format == VK_FORMAT_UNDEFINED) {
      *error = "vertex input at location " + std::to_string(location) + " has a type the harness cannot feed";
      return false;
    }
    vb->attributes.push_back({location, format, offset});
    offset += size;
  }
  vb->stride = std::max<uint32_t>(offset, 4);
  vb->bytes.assign(size_t(vb->stride) * count, 0);
  for (uint32_t v = 0; v < count; ++v) {
    float t = count > 1 ? float(v) / float(count - 1) : 0.f;
    const float values[4] = {-2.f + 4.f * std::fmod(t * 7.f, 1.f), -2.f + 4.f * std::fmod(t * 3.f, 1.f),
                             5.f - 65.f * t, 1.f};
    for (const auto& a : vb->attributes) {
      uint32_t size = 0;
      VkFormat format = r.formatOf(attributes[&a - vb->attributes.data()].second, &size);
      bool isFloat = format == VK_FORMAT_R32_SFLOAT || format == VK_FORMAT_R32G32_SFLOAT ||
                     format == VK_FORMAT_R32G32B32_SFLOAT || format == VK_FORMAT_R32G32B32A32_SFLOAT;
      for (uint32_t c = 0; c < size / 4; ++c) {
        size_t at = size_t(v) * vb->stride + a.offset + 4 * c;
        if (isFloat) {
          float value = values[c];
          std::memcpy(vb->bytes.data() + at, &value, 4);
        } else {
          uint32_t value = c == 0 ? v % 4 : 0;
          std::memcpy(vb->bytes.data() + at, &value, 4);
        }
      }
    }
  }
  return true;
}

// Uniform buffers, textures and push constants of one module (merged across stages by the caller).
bool buildResources(const Module& m, PipelineInputs* in, std::string* error) {
  Reflector r{m};
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable) continue;
    auto storage = static_cast<spv::StorageClass>(inst.operand(0));
    uint32_t type = m.pointeeType(inst.typeId);
    uint32_t set = m.decorationValue(inst.resultId, spv::DecorationDescriptorSet).value_or(0);
    uint32_t binding = m.decorationValue(inst.resultId, spv::DecorationBinding).value_or(0);
    auto present = [&](uint32_t s, uint32_t b) {
      for (const auto& u : in->uniformBuffers)
        if (u.set == s && u.binding == b) return true;
      for (const auto& t : in->textures)
        if (t.set == s && t.binding == b) return true;
      return false;
    };
    bool storageBuffer = storage == spv::StorageClassStorageBuffer ||
                         (storage == spv::StorageClassUniform && m.hasDecoration(type, spv::DecorationBufferBlock));
    if (storageBuffer) {  // e.g. an HLSL StructuredBuffer: 64 elements of plausible data
      if (present(set, binding)) continue;
      UniformBuffer sb{set, binding, {}, true};
      r.fill(sb.bytes, type, 0, 0, false);
      sb.bytes.resize((sb.bytes.size() + 15) & ~size_t(15), 0);
      in->uniformBuffers.push_back(std::move(sb));
      continue;
    }
    if (storage == spv::StorageClassUniform) {
      if (present(set, binding)) continue;
      UniformBuffer ub{set, binding, {}};
      r.fill(ub.bytes, type, 0, 0, false);
      ub.bytes.resize((ub.bytes.size() + 15) & ~size_t(15), 0);
      in->uniformBuffers.push_back(std::move(ub));
    } else if (storage == spv::StorageClassPushConstant) {
      std::vector<uint8_t> bytes;
      r.fill(bytes, type, 0, 0, false);
      if (bytes.size() > in->pushConstants.size()) in->pushConstants = bytes;
      in->pushConstants.resize((in->pushConstants.size() + 3) & ~size_t(3), 0);
    } else if (storage == spv::StorageClassUniformConstant) {
      const Instruction* d = m.definition(type);
      if (d && d->opcode == spv::OpTypeSampledImage) {
        if (present(set, binding)) continue;
        SampledTexture tex{set, binding, 4, 4, std::vector<float>(64, 0.5f)};
        in->textures.push_back(std::move(tex));
      } else {
        *error = "resource '" + m.name(inst.resultId) + "' is not a uniform buffer or combined image sampler";
        return false;
      }
    }
  }
  return true;
}

// Where the transpiled module reads eyeSign / separation / convergence.
bool applyEyeParameters(const Module& m, const VerifySettings& s, float eyeSign, PipelineInputs* in,
                        std::string* error) {
  const float values[3] = {eyeSign, s.separation, s.convergence};
  const std::string names[3] = {s.eyeSignName, s.separationName, s.convergenceName};
  bool found = false;
  // Block members (uniform block or push constants).
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable) continue;
    auto storage = static_cast<spv::StorageClass>(inst.operand(0));
    uint32_t type = m.pointeeType(inst.typeId);
    const Instruction* d = m.definition(type);
    if (!d || d->opcode != spv::OpTypeStruct) continue;
    for (uint32_t i = 0; i < d->operands.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        if (m.memberName(type, i) != names[k]) continue;
        uint32_t offset = m.memberDecorationValue(type, i, spv::DecorationOffset).value_or(0);
        std::vector<uint8_t>* bytes = nullptr;
        if (storage == spv::StorageClassPushConstant) {
          bytes = &in->pushConstants;
        } else if (storage == spv::StorageClassUniform) {
          uint32_t set = m.decorationValue(inst.resultId, spv::DecorationDescriptorSet).value_or(0);
          uint32_t binding = m.decorationValue(inst.resultId, spv::DecorationBinding).value_or(0);
          for (auto& ub : in->uniformBuffers)
            if (ub.set == set && ub.binding == binding) bytes = &ub.bytes;
        }
        if (!bytes) continue;
        if (bytes->size() < offset + 4) bytes->resize(((offset + 4) + 15) & ~size_t(15), 0);
        std::memcpy(bytes->data() + offset, &values[k], 4);
        found = true;
      }
  }
  // Specialization constants.
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpSpecConstant) continue;
    for (int k = 0; k < 3; ++k)
      if (m.name(inst.resultId) == names[k])
        if (auto id = m.decorationValue(inst.resultId, spv::DecorationSpecId)) {
          uint32_t bits;
          std::memcpy(&bits, &values[k], 4);
          in->specConstants.push_back({*id, bits});
          found = true;
        }
  }
  if (!found) *error = "the transpiled shader has no eye parameters the harness can set";
  return found;
}

VkShaderStageFlagBits toVk(spv::ExecutionModel model) {
  switch (model) {
    case spv::ExecutionModelTessellationControl: return VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
    case spv::ExecutionModelTessellationEvaluation: return VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
    case spv::ExecutionModelGeometry: return VK_SHADER_STAGE_GEOMETRY_BIT;
    default: return VK_SHADER_STAGE_VERTEX_BIT;
  }
}

double ulpOf(double magnitude) {
  float m = static_cast<float>(std::max(magnitude, double(FLT_MIN)));
  return double(std::nextafter(m, INFINITY)) - double(m);
}

}  // namespace

bool buildStageModules(const std::vector<SourceFile>& sources, const TranspileOptions& options,
                       std::vector<StageModules>* stages, std::string* classification, Diagnostics& diags) {
  std::vector<const SourceFile*> ordered;
  for (const auto& s : sources) {
    auto stage = decideStage(s.path, s.contents, options.stage, options.stageExtensions).stage;
    if (stage && isPreRasterization(*stage)) ordered.push_back(&s);
  }
  if (ordered.empty()) {
    diags.error(sources.empty() ? std::string() : sources.front().path,
                "nothing to verify: no vertex, tessellation or geometry stage");
    return false;
  }
  std::stable_sort(ordered.begin(), ordered.end(), [&](const SourceFile* a, const SourceFile* b) {
    auto of = [&](const SourceFile* f) { return decideStage(f->path, f->contents, options.stage, options.stageExtensions).stage; };
    return static_cast<int>(*of(a)) < static_cast<int>(*of(b));
  });
  for (size_t i = 0; i < ordered.size(); ++i) {
    TranspileOptions o = options;
    o.target = TargetLanguage::Spirv;
    o.forceReemit = true;
    o.shiftThisStage = i + 1 == ordered.size();
    TranspileResult result = transpile(*ordered[i], o);
    diags.append(result.diagnostics);
    if (!result.ok) return false;
    *classification = result.report.value("classification", "");
    std::vector<uint32_t> words(result.output.size() / 4);
    std::memcpy(words.data(), result.output.data(), words.size() * 4);
    std::string error;
    auto original = spirv::Module::parse(result.originalSpirv, &error);
    if (!original) {
      diags.error(ordered[i]->path, error);
      return false;
    }
    std::vector<std::string> halo;
    for (const auto& n : result.report["passes"]["halo"].value("shifted_outputs", nlohmann::json::array()))
      halo.push_back(n.get<std::string>());
    // Outputs computed from the per-eye camera (per-eye-view: relief view vectors) differ between
    // the eyes by design, like re-derived halo outputs; eyeSign = 0 still has to be bit for bit.
    for (const auto& n : result.report["passes"]["per-eye-view"].value("per_eye_outputs", nlohmann::json::array()))
      halo.push_back(n.get<std::string>());
    stages->push_back({toVk(original->executionModel()), std::move(result.originalSpirv), std::move(words),
                       original->entryPointName(), std::move(halo)});
  }
  return true;
}

VerifyResult verifyStereo(VulkanContext& context, const std::vector<StageModules>& stages,
                          const VerifySettings& settings) {
  VerifyResult result;
  if (stages.empty()) {
    result.error = "no stages";
    return result;
  }
  std::vector<Module> originals, transpiled;
  for (const auto& s : stages) {
    std::string error;
    auto a = Module::parse(s.original, &error);
    auto b = Module::parse(s.transpiled, &error);
    if (!a || !b) {
      result.error = "unparsable SPIR-V: " + error;
      return result;
    }
    // OpenGL shaders run through the same Vulkan-compatible rewrite, original and transpiled alike.
    const uint32_t blockBinding = 16 + static_cast<uint32_t>(originals.size());
    if (!convertOpenGLForVulkan(*a, blockBinding, &error) && !error.empty()) {
      result.error = error;
      return result;
    }
    convertOpenGLForVulkan(*b, blockBinding, &error);
    originals.push_back(std::move(*a));
    transpiled.push_back(std::move(*b));
  }
  CaptureLayout layoutA, layoutB;
  std::string error;
  if (!instrumentForCapture(originals.back(), &layoutA, nullptr, &error) ||
      !instrumentForCapture(transpiled.back(), &layoutB, nullptr, &error)) {
    result.error = error;
    return result;
  }
  if (layoutA.stride != layoutB.stride) {
    result.error = "original and transpiled shaders have different outputs";
    return result;
  }

  // Inputs, identical for both runs except for the eye parameters.
  PipelineInputs base;
  if (settings.vertices) {
    base.vertices = *settings.vertices;
  } else if (!buildVertices(originals.front(), settings.vertexCount, &base.vertices, &error)) {
    result.error = error;
    return result;
  }
  for (const auto& m : originals)
    if (!buildResources(m, &base, &error)) {
      result.error = error;
      return result;
    }
  // The transpiled stages add the eye-parameter block: same inputs plus that one.
  PipelineInputs stereoBase = base;
  for (const auto& m : transpiled)
    if (!buildResources(m, &stereoBase, &error)) {
      result.error = error;
      return result;
    }
  if (const char* dump = std::getenv("STEREOSHIFT_VERIFY_DUMP")) {
    for (size_t i = 0; i < originals.size(); ++i) {
      auto a = originals[i].encode(), b = transpiled[i].encode();
      std::ofstream(std::string(dump) + "/original" + std::to_string(i) + ".spv", std::ios::binary)
          .write(reinterpret_cast<const char*>(a.data()), std::streamsize(a.size() * 4));
      std::ofstream(std::string(dump) + "/transpiled" + std::to_string(i) + ".spv", std::ios::binary)
          .write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size() * 4));
    }
  }
  bool tessellation = false;
  for (const auto& m : originals) tessellation |= m.executionModel() == spv::ExecutionModelTessellationControl;
  uint32_t count = settings.vertexCount;
  if (tessellation) {
    base.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
    for (const auto& inst : originals[1].executionModes)
      if (inst.operand(1) == uint32_t(spv::ExecutionModeOutputVertices)) base.patchControlPoints = inst.operand(2);
    if (base.patchControlPoints == 0) base.patchControlPoints = 3;
    count -= count % base.patchControlPoints;
  } else {
    base.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    count -= count % 3;
  }
  base.vertexCount = count;
  stereoBase.topology = base.topology;
  stereoBase.patchControlPoints = base.patchControlPoints;
  stereoBase.vertexCount = base.vertexCount;

  auto run = [&](std::vector<Module>& modules, const PipelineInputs& inputs, CaptureResult* out) {
    CaptureRequest request;
    request.pipeline = inputs;
    for (size_t i = 0; i < modules.size(); ++i)
      request.pipeline.stages.push_back({toVk(modules[i].executionModel()), modules[i].encode(), modules[i].entryPointName()});
    request.xfbStride = layoutA.stride;
    request.expectedVertices = count * 64;  // room for tessellation / geometry amplification
    *out = context.capture(request);
    return out->ok();
  };

  CaptureResult mono;
  if (!run(originals, base, &mono)) {
    result.error = "original: " + mono.error;
    return result;
  }
  result.vertices = mono.vertexCount();
  const CapturedField* position = layoutA.position();
  uint32_t px = position->offset / 4;
  result.monoIdentical = true;
  result.otherOutputsUnchanged = true;
  for (float eye : {0.0f, -1.0f, 1.0f}) {
    PipelineInputs inputs = stereoBase;
    if (!applyEyeParameters(transpiled.back(), settings, eye, &inputs, &error)) {
      result.error = error;
      return result;
    }
    CaptureResult stereo;
    if (!run(transpiled, inputs, &stereo)) {
      result.error = "transpiled: " + stereo.error;
      return result;
    }
    if (stereo.bytes.size() != mono.bytes.size()) {
      result.problems.push_back("eye " + std::to_string(int(eye)) + ": captured a different number of vertices");
      continue;
    }
    if (eye == 0.0f) {
      result.monoIdentical = stereo.bytes == mono.bytes;
      if (!result.monoIdentical) {
        std::string where;
        for (uint32_t v = 0; v < result.vertices && where.empty(); ++v)
          for (uint32_t c = 0; c < layoutA.stride / 4 && where.empty(); ++c)
            if (mono.u32(v, c) != stereo.u32(v, c))
              where = ": first at vertex " + std::to_string(v) + " component " + std::to_string(c) + " (" +
                      std::to_string(mono.f32(v, c)) + " became " + std::to_string(stereo.f32(v, c)) + ")";
        result.problems.push_back("eyeSign = 0 output differs from the original" + where);
      }
      continue;
    }
    for (uint32_t v = 0; v < result.vertices; ++v) {
      double x = mono.f32(v, px), w = mono.f32(v, px + 3);
      float got = stereo.f32(v, px);
      // The shader's guard, in its own fp32 terms: ordered comparisons (a NaN w is not shifted)
      // and never an infinite w.
      bool far = settings.cutoffEpsilon > 0 ? std::fabs(float(w) - 1.0f) > settings.cutoffEpsilon : float(w) != 1.0f;
      bool unshifted = settings.cutoff && (!far || std::isnan(w) || std::isinf(w));
      double shift = double(eye) * settings.separation * (w - settings.convergence);
      double reference = unshifted ? x : x + shift;
      if (unshifted && eye > 0) ++result.cutoffVertices;
      double scale = std::max(std::fabs(x), std::fabs(double(settings.separation) * (w - settings.convergence)));
      if (std::isnan(got) && !std::isnan(x) && !std::isnan(w)) ++result.newNaNs;
      double ulps;
      if (std::isnan(reference) || std::isinf(reference) || std::isinf(got))
        ulps = (std::isnan(reference) && std::isnan(got)) || double(got) == reference ? 0 : INFINITY;
      else
        ulps = std::fabs(got - reference) / ulpOf(scale);
      result.maxStereoUlps = std::max(result.maxStereoUlps, ulps);
      // y, z, w and every other captured component: unchanged, except halo copies of the position.
      for (uint32_t c = 0; c < layoutA.stride / 4; ++c) {
        if (c == px) continue;
        bool staleCopy = false;
        for (const auto& f : layoutA.fields)
          staleCopy |= !f.isPosition && f.components == 4 && c == f.offset / 4 &&
                       mono.u32(v, c) == mono.u32(v, px) && stereo.u32(v, c) != stereo.u32(v, px);
        if (staleCopy) {  // a copy of the position left mono: the 3Dmigoto "halo"
          result.otherOutputsUnchanged = false;
          if (result.problems.size() < 8)
            result.problems.push_back("vertex " + std::to_string(v) + ": a copy of the position (component " +
                                      std::to_string(c) + ") was not shifted with it (halo)");
          continue;
        }
        if (mono.u32(v, c) == stereo.u32(v, c)) continue;
        bool haloCopy = false, haloDerived = false;
        for (const auto& f : layoutA.fields) {
          if (f.isPosition || c < f.offset / 4 || c >= f.offset / 4 + f.components) continue;
          // A copied position must carry exactly the shifted x of gl_Position; other outputs the
          // halo pass re-derived may move (their formula is the shader's own).
          if (f.components == 4 && c == f.offset / 4 && mono.u32(v, c) == mono.u32(v, px)) {
            haloCopy = stereo.u32(v, c) == stereo.u32(v, px);
          } else {
            const auto& halo = stages.back().haloOutputs;
            haloDerived = std::find(halo.begin(), halo.end(), f.name) != halo.end();
          }
        }
        if (haloCopy || haloDerived) {
          ++result.haloComponentsChanged;
        } else {
          result.otherOutputsUnchanged = false;
          if (result.problems.size() < 8)
            result.problems.push_back("vertex " + std::to_string(v) + " component " + std::to_string(c) +
                                      " changed for eye " + std::to_string(int(eye)));
        }
      }
    }
  }
  if (result.maxStereoUlps > settings.maxUlps)
    result.problems.push_back("stereo error " + std::to_string(result.maxStereoUlps) + " ULP exceeds the bound of " +
                              std::to_string(settings.maxUlps));
  if (result.newNaNs) result.problems.push_back(std::to_string(result.newNaNs) + " new NaN x values");
  result.ok = result.monoIdentical && result.otherOutputsUnchanged && result.maxStereoUlps <= settings.maxUlps &&
              result.newNaNs == 0 &&
              result.problems.empty();
  return result;
}

}  // namespace stereoshift::harness
