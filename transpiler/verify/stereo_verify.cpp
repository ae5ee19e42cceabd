// This turns a shader (or the pre-rasterization stages of a pipeline) into a run on the device:
// the original and the transpiled SPIR-V, with inputs generated from the module's own reflection —
// every buffer, image, sampler and texel-buffer descriptor it declares, every vertex input, push
// constants (as a uniform buffer when over the device limit), pass-through stages in front of a lone
// tese or geometry shader — captured through transform feedback and compared per eye with the
// exact shift computed in double. Where a shader cannot run, the result's `error` says why in one line.
//
// The generated data decide what "equal outputs" mean, so they are distinct: every scalar, vector
// and matrix value is seeded by its resource (set, binding, array element) and its byte offset, and
// no two uniforms hold the same numbers. Matrices: no heuristic guesses which mat4 is the projection.
// Each is instead its own member of a family that maps points in front of a camera (z < 0, w > 0)
// to points in front again, with a projective last row so w leaves 1 (see matrixEntry): any
// product of them, in either multiplication order, keeps the geometry in front with w spread from
// near to far. So a shadow-map coordinate `DepthBiasMVP * p` and the position `MVP * p` differ, and a
// pass that used the wrong operand shows.
#include "transpiler/verify/stereo_verify.h"

#include "transpiler/verify/capture_instrument.h"
#include "transpiler/verify/stage_synthesis.h"
#include "passes/ir/module.h"
#include "passes/pass.h"
#include "transpiler/source/stage_rules.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>

namespace stereoshift::harness {

using spirv::Instruction;
using spirv::Module;

nlohmann::json VerifyResult::json() const {
  nlohmann::json j = {{"ok", ok},
          {"error", error},
          {"mode", mode == EyeSelect::ViewIndex ? "multiview" : mode == EyeSelect::InstanceIndex ? "instanced" : "two-pass"},
          {"vertices", vertices},
          {"max_stereo_error_ulps", maxStereoUlps},
          {"cutoff_vertices", cutoffVertices},
          {"other_outputs_unchanged", otherOutputsUnchanged},
          {"halo_components_changed", haloComponentsChanged},
          {"new_nans", newNaNs},
          {"synthesized_stages", synthesizedStages},
          {"push_constants_as_buffer", pushConstantsAsBuffer},
          {"problems", problems}};
  if (mode == EyeSelect::Parameter) {
    j["mono_identical"] = monoIdentical;
    j["checked"] = {"eyeSign 0: every output bit for bit the original's",
                    "eyeSign -1 and +1: x against x + e*S*(w - C), every other output unchanged"};
    return j;
  }
  // The eye comes from the view or the instance: there is no eyeSign = 0 run to compare.
  j["mono_run"] = false;
  j["eye_sign_declared"] = eyeSignDeclared;
  j["eye_sign_ignored"] = eyeSignIgnored;
  if (mode == EyeSelect::ViewIndex)
    j["checked"] = {"view 0 and view 1: x against x + e*S*(w - C) for the view's eye, every other output unchanged",
                    "no eyeSign 0 run: a junk eyeSign parameter changes no output"};
  if (mode == EyeSelect::InstanceIndex) {
    j["checked"] = {"instance 2k+e against the original's instance k: x against x + e*S*(w - C) for eye e, every "
                    "other output unchanged",
                    "the layer / viewport index and the eye varying equal e",
                    "no eyeSign 0 run: a junk eyeSign parameter changes no output"};
    j["instances"] = instances;
    j["stereo_instances"] = 2 * instances;
    j["eye_routed"] = eyeRouted;
    j["eye_varying_written"] = eyeVaryingWritten;
  }
  return j;
}

namespace {

// --- generated data --------------------------------------------------------------------------
// Every value is a function of a seed: the resource's (set, binding, array element) — or the push
// constant block — mixed with the value's byte offset inside it, so two members, two elements or
// two resources never get the same data, while an original and its transpiled copy (whose shared
// resources keep their offsets) get exactly the same.

uint32_t mix(uint32_t a, uint32_t b) {
  uint32_t h = a * 0x9E3779B1u ^ (b + 0x7F4A7C15u + (a << 6) + (a >> 2));
  h ^= h >> 15;
  h *= 0x2C1B3C6Du;
  h ^= h >> 12;
  h *= 0x297A2D39u;
  h ^= h >> 15;
  return h;
}
double unit(uint32_t h) { return double(h >> 8) / double(1u << 24); }  // [0, 1)
uint32_t resourceSeed(uint32_t set, uint32_t binding, uint32_t element) { return mix(mix(set + 1, binding + 1), element); }
constexpr uint32_t kPushConstantSeed = 0x5055u;

// Entry (row, column) of the 4x4 matrix of `seed` (column-vector convention, M * p):
//   row 0  s*cos t  -s*sin t  sigma   tx
//   row 1  s*sin t   s*cos t    0     ty
//   row 2     0         0     gamma  -delta
//   row 3     0         0     -beta   alpha
// a turn t about z, a scale s, a small shear sigma of x by z, a shift (tx, ty) and a projective
// last row. For a point in front of a camera looking down -z (z < 0, w > 0) it gives again z' < 0
// and w' = alpha*w - beta*z > 0, so every product of such matrices keeps points in front, whatever
// order a shader multiplies them in and whichever of them is "the projection": no heuristic has
// to guess which uniform is which. Over the generated depths (z in [-60, -0.5]) one matrix spreads
// w over [alpha + beta/2, alpha + 60 beta], so near and far vertices both get shifted. The
// transposed reading (HLSL mul(v, M)) keeps w > 0 too: its w row is (tx, ty, -delta, alpha) with
// |tx|, |ty| <= 0.05. A matrix with fewer rows or columns (mat3 normal matrices, mat4x3 affine
// transforms, mat2) is the top-left part. Arrays of matrices (bone palettes, instance transforms)
// are affine — the same without the projective row and with t, s close to a rigid motion — so
// weighted blends of them stay plausible transforms.
double matrixEntry(uint32_t seed, uint32_t row, uint32_t column, bool affine) {
  const double t = (unit(mix(seed, 1)) - 0.5) * (affine ? 0.2 : 0.6);
  const double s = affine ? 0.95 + 0.1 * unit(mix(seed, 2)) : 0.8 + 0.4 * unit(mix(seed, 2));
  const double tx = (unit(mix(seed, 3)) - 0.5) * 0.1, ty = (unit(mix(seed, 4)) - 0.5) * 0.1;
  const double sigma = affine ? 0.0 : (unit(mix(seed, 5)) - 0.5) * 0.1;
  const double gamma = affine ? 1.0 : 0.9 + 0.2 * unit(mix(seed, 6));
  const double delta = affine ? (unit(mix(seed, 7)) - 0.5) * 0.2 : 0.2 + 0.8 * unit(mix(seed, 7));
  const double beta = affine ? 0.0 : 0.05 + 0.45 * unit(mix(seed, 8));
  const double alpha = affine ? 1.0 : 0.6 + 0.8 * unit(mix(seed, 9));
  const double m[4][4] = {{s * std::cos(t), -s * std::sin(t), sigma, tx},
                          {s * std::sin(t), s * std::cos(t), 0, ty},
                          {0, 0, gamma, -delta},
                          {0, 0, -beta, alpha}};
  return row < 4 && column < 4 ? m[row][column] : 0.0;
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
  uint32_t arrayLength(const Instruction* d) const {
    const Instruction* length = d && d->opcode == spv::OpTypeArray ? def(d->operand(1)) : nullptr;
    return length ? length->operand(0) : 0;
  }

  void putFloat(std::vector<uint8_t>& bytes, size_t at, float v) const {
    if (bytes.size() < at + 4) bytes.resize(at + 4, 0);
    std::memcpy(bytes.data() + at, &v, 4);
  }
  void putU32(std::vector<uint8_t>& bytes, size_t at, uint32_t v) const {
    if (bytes.size() < at + 4) bytes.resize(at + 4, 0);
    std::memcpy(bytes.data() + at, &v, 4);
  }
  void putDouble(std::vector<uint8_t>& bytes, size_t at, double v) const {
    if (bytes.size() < at + 8) bytes.resize(at + 8, 0);
    std::memcpy(bytes.data() + at, &v, 8);
  }
  bool isDouble(uint32_t type) const {
    const Instruction* d = def(type);
    while (d && (d->opcode == spv::OpTypeVector || d->opcode == spv::OpTypeMatrix)) d = def(d->operand(0));
    return d && d->opcode == spv::OpTypeFloat && d->operand(0) == 64;
  }
  void putReal(std::vector<uint8_t>& bytes, size_t at, double v, bool wide) const {
    wide ? putDouble(bytes, at, v) : putFloat(bytes, at, float(v));
  }

  // Fills one value of `type` at byte `at` of a resource with seed `seed` (see "generated data").
  // Floats are in [0.5, 1.5), vector components in [0.25 (i+1), 0.25 (i+1) + 0.5) with the fourth
  // of a vec4 1 (a point, a colour), integers 1 (safe as a count, an index or a divisor), bools false.
  void fill(std::vector<uint8_t>& bytes, uint32_t type, size_t at, uint32_t matrixStride, bool rowMajor,
            uint32_t seed, bool inArray = false) const {
    const Instruction* d = def(type);
    if (!d) return;
    const uint32_t here = mix(seed, uint32_t(at));
    switch (d->opcode) {
      case spv::OpTypeFloat:
        putReal(bytes, at, 0.5 + unit(here), d->operand(0) == 64);
        break;
      case spv::OpTypeInt:
        putU32(bytes, at, 1);
        break;
      case spv::OpTypeBool:
        putU32(bytes, at, 0);
        break;
      case spv::OpTypeVector: {
        const Instruction* component = def(d->operand(0));
        const bool isFloat = component && component->opcode == spv::OpTypeFloat;
        const bool wide = isFloat && component->operand(0) == 64;
        for (uint32_t i = 0; i < d->operand(1); ++i) {
          double v = (d->operand(1) == 4 && i == 3) ? 1.0 : 0.25 * (i + 1) + 0.5 * unit(mix(here, i));
          isFloat ? putReal(bytes, at + (wide ? 8 : 4) * i, v, wide) : putU32(bytes, at + 4 * i, i);
        }
        break;
      }
      case spv::OpTypeMatrix: {
        const uint32_t columns = d->operand(1), rows = scalarCount(d->operand(0));
        const bool wide = isDouble(type);
        const uint32_t scalar = wide ? 8 : 4;
        const uint32_t stride = matrixStride ? matrixStride : 4 * scalar;
        for (uint32_t c = 0; c < columns; ++c)
          for (uint32_t r = 0; r < rows; ++r) {
            size_t offset = rowMajor ? r * stride + c * scalar : c * stride + r * scalar;
            putReal(bytes, at + offset, matrixEntry(here, r, c, inArray), wide);
          }
        break;
      }
      case spv::OpTypeArray:
      case spv::OpTypeRuntimeArray: {
        uint32_t count = d->opcode == spv::OpTypeArray ? arrayLength(d) : 64;  // a runtime array gets 64 elements
        uint32_t stride = m.decorationValue(type, spv::DecorationArrayStride).value_or(16);
        for (uint32_t i = 0; i < count; ++i) fill(bytes, d->operand(0), at + i * stride, matrixStride, rowMajor, seed, true);
        break;
      }
      case spv::OpTypeStruct:
        for (uint32_t i = 0; i < d->operands.size(); ++i) {
          uint32_t offset = m.memberDecorationValue(type, i, spv::DecorationOffset).value_or(0);
          uint32_t ms = m.memberDecorationValue(type, i, spv::DecorationMatrixStride).value_or(0);
          bool rm = m.hasMemberDecoration(type, i, spv::DecorationRowMajor);
          fill(bytes, d->operands[i], at + offset, ms, rm, seed, inArray);
        }
        break;
      default:
        break;
    }
  }

  // The vertex format of one attribute location's worth of `type` (a scalar or vector); 0 size
  // and VK_FORMAT_UNDEFINED when it has none (bool, 8/16-bit).
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
    static const VkFormat dbl[] = {VK_FORMAT_R64_SFLOAT, VK_FORMAT_R64G64_SFLOAT, VK_FORMAT_R64G64B64_SFLOAT,
                                   VK_FORMAT_R64G64B64A64_SFLOAT};
    if (d->opcode == spv::OpTypeFloat && d->operand(0) == 32) return f[n - 1];
    if (d->opcode == spv::OpTypeFloat && d->operand(0) == 64) {
      *size = 8 * n;
      return dbl[n - 1];
    }
    if (d->opcode == spv::OpTypeInt && d->operand(0) == 32) return d->operand(1) ? s[n - 1] : u[n - 1];
    *size = 0;
    return VK_FORMAT_UNDEFINED;
  }

  // Locations one scalar or vector takes (64-bit three- and four-component vectors take two).
  uint32_t locations(uint32_t type) const { return isDouble(type) && scalarCount(type) > 2 ? 2 : 1; }
};

// Vertex data. Attribute i of vertex v: a point spread over x, y in [-2, 2] and z in [-60, -0.5]
// (in front of a camera looking down -z, which every generated matrix keeps in front), moved a
// little per location so that two attributes never hold the same values; the fourth component of
// a four-component vector is 1. Integer attributes get small values (v + location) mod 4 in the
// first component (bone and instance indices), 0 or 1 in the others. Matrices take one location
// per column, arrays one per element, dvec3/dvec4 two, fed as 64-bit formats.
bool buildVertices(const Module& m, uint32_t count, VertexBuffer* vb, std::string* error) {
  Reflector r{m};
  struct Leaf {
    uint32_t location, type;
    std::string name;
  };
  std::vector<Leaf> leaves;
  std::function<bool(uint32_t, uint32_t, const std::string&)> expand = [&](uint32_t location, uint32_t type,
                                                                           const std::string& name) {
    const Instruction* d = m.definition(type);
    if (d && (d->opcode == spv::OpTypeMatrix || d->opcode == spv::OpTypeArray)) {
      uint32_t n = d->opcode == spv::OpTypeMatrix ? d->operand(1) : r.arrayLength(d);
      uint32_t element = d->operand(0), step = 1;
      for (uint32_t i = 0; i < n; ++i) {
        const size_t before = leaves.size();
        if (!expand(location, element, name)) return false;
        step = 0;
        for (size_t k = before; k < leaves.size(); ++k) step += r.locations(leaves[k].type);
        location += step;
      }
      return true;
    }
    uint32_t size = 0;
    if (r.formatOf(type, &size) == VK_FORMAT_UNDEFINED) {
      *error = "vertex input '" + name + "' at location " + std::to_string(location) +
               " has a type the harness cannot feed (only 32-bit scalars and vectors, doubles, and "
               "matrices and arrays of them are vertex formats)";
      return false;
    }
    leaves.push_back({location, type, name});
    return true;
  };
  for (uint32_t id : m.entryInterface()) {
    const Instruction* var = m.definition(id);
    if (!var || var->operand(0) != spv::StorageClassInput || m.hasDecoration(id, spv::DecorationBuiltIn)) continue;
    auto location = m.decorationValue(id, spv::DecorationLocation);
    if (!location) continue;
    if (!expand(*location, m.pointeeType(var->typeId), m.name(id))) return false;
  }
  if (leaves.empty()) return true;  // no vertex inputs (a full-screen triangle from gl_VertexIndex): no buffer
  std::sort(leaves.begin(), leaves.end(), [](const Leaf& a, const Leaf& b) { return a.location < b.location; });
  uint32_t offset = 0;
  for (const Leaf& leaf : leaves) {
    uint32_t size = 0;
    VkFormat format = r.formatOf(leaf.type, &size);
    const uint32_t align = r.isDouble(leaf.type) ? 8 : 4;
    offset = (offset + align - 1) & ~(align - 1);
    vb->attributes.push_back({leaf.location, format, offset});
    offset += size;
  }
  vb->stride = std::max<uint32_t>((offset + 7) & ~7u, 4);
  vb->bytes.assign(size_t(vb->stride) * count, 0);
  std::vector<uint8_t>& bytes = vb->bytes;
  for (uint32_t v = 0; v < count; ++v) {
    float t = count > 1 ? float(v) / float(count - 1) : 0.f;
    const double point[3] = {-2.0 + 4.0 * std::fmod(t * 7.f, 1.f), -2.0 + 4.0 * std::fmod(t * 3.f, 1.f),
                             -0.5 - 59.5 * t};
    for (size_t i = 0; i < leaves.size(); ++i) {
      const VertexAttribute& a = vb->attributes[i];
      const uint32_t n = r.scalarCount(leaves[i].type), L = a.location;
      const bool wide = r.isDouble(leaves[i].type);
      const Instruction* scalar = m.definition(leaves[i].type);
      if (scalar && scalar->opcode == spv::OpTypeVector) scalar = m.definition(scalar->operand(0));
      const bool isFloat = scalar && scalar->opcode == spv::OpTypeFloat;
      for (uint32_t c = 0; c < n; ++c) {
        size_t at = size_t(v) * vb->stride + a.offset + (wide ? 8 : 4) * c;
        if (isFloat) {
          const double perLocation[3] = {0.03125 * L, -0.046875 * L, 0.0};
          double value = c == 3 ? 1.0 : c == 2 ? point[2] * (1.0 + L / 64.0) : point[c] + perLocation[c];
          Reflector{m}.putReal(bytes, at, value, wide);
        } else {
          uint32_t value = c == 0 ? (v + L) % 4 : (v + c) % 2;
          std::memcpy(bytes.data() + at, &value, 4);
        }
      }
    }
  }
  return true;
}

// The VkFormat a shader's image format names (storage images must be bound with exactly it);
// Unknown takes the four-channel 32-bit format of the sampled type.
VkFormat imageFormat(uint32_t spirvFormat, char kind) {
  switch (spirvFormat) {
    case spv::ImageFormatRgba32f: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case spv::ImageFormatRgba16f: return VK_FORMAT_R16G16B16A16_SFLOAT;
    case spv::ImageFormatR32f: return VK_FORMAT_R32_SFLOAT;
    case spv::ImageFormatRgba8: return VK_FORMAT_R8G8B8A8_UNORM;
    case spv::ImageFormatRgba8Snorm: return VK_FORMAT_R8G8B8A8_SNORM;
    case spv::ImageFormatRg32f: return VK_FORMAT_R32G32_SFLOAT;
    case spv::ImageFormatRg16f: return VK_FORMAT_R16G16_SFLOAT;
    case spv::ImageFormatR16f: return VK_FORMAT_R16_SFLOAT;
    case spv::ImageFormatR11fG11fB10f: return VK_FORMAT_B10G11R11_UFLOAT_PACK32;
    case spv::ImageFormatRgba16: return VK_FORMAT_R16G16B16A16_UNORM;
    case spv::ImageFormatRg8: return VK_FORMAT_R8G8_UNORM;
    case spv::ImageFormatR8: return VK_FORMAT_R8_UNORM;
    case spv::ImageFormatRgba32i: return VK_FORMAT_R32G32B32A32_SINT;
    case spv::ImageFormatR32i: return VK_FORMAT_R32_SINT;
    case spv::ImageFormatRgba8i: return VK_FORMAT_R8G8B8A8_SINT;
    case spv::ImageFormatRgba32ui: return VK_FORMAT_R32G32B32A32_UINT;
    case spv::ImageFormatR32ui: return VK_FORMAT_R32_UINT;
    case spv::ImageFormatRgba8ui: return VK_FORMAT_R8G8B8A8_UINT;
    default:
      return kind == 'i' ? VK_FORMAT_R32G32B32A32_SINT : kind == 'u' ? VK_FORMAT_R32G32B32A32_UINT
                                                       : VK_FORMAT_R32G32B32A32_SFLOAT;
  }
}

// One image, sampler or texel-buffer descriptor (or array of them) from the OpTypeImage /
// OpTypeSampledImage / OpTypeSampler it is declared with. Texels: small deterministic images
// (4 texels a side, 4 layers, 6 faces a cube) of seeded values in [0, 1), integers in [0, 4).
bool describeImage(const Module& m, uint32_t type, uint32_t set, uint32_t binding, uint32_t count,
                   const std::string& name, SampledTexture* tex, std::string* error) {
  const Instruction* d = m.definition(type);
  const std::string where = "'" + name + "' (set " + std::to_string(set) + ", binding " + std::to_string(binding) + ")";
  tex->set = set;
  tex->binding = binding;
  tex->arrayCount = count;
  if (d && d->opcode == spv::OpTypeSampler) {
    tex->type = VK_DESCRIPTOR_TYPE_SAMPLER;
    tex->width = tex->height = 1;
    tex->rgba.assign(4 * count, 0.f);
    return true;
  }
  bool combined = d && d->opcode == spv::OpTypeSampledImage;
  if (combined) d = m.definition(d->operand(0));
  if (!d || d->opcode != spv::OpTypeImage) {
    *error = "resource " + where + " is not a buffer, image or sampler the harness can bind";
    return false;
  }
  const Instruction* sampled = m.definition(d->operand(0));
  const char kind = sampled && sampled->opcode == spv::OpTypeInt ? (sampled->operand(1) ? 'i' : 'u') : 'f';
  const uint32_t dim = d->operand(1), arrayed = d->operand(3), multisampled = d->operand(4), usage = d->operand(5);
  if (multisampled) {
    *error = "multisampled texture " + where + ": the harness binds single-sampled images only";
    return false;
  }
  const bool storage = usage == 2;
  tex->format = imageFormat(storage ? d->operand(6) : uint32_t(spv::ImageFormatUnknown), kind);
  tex->width = tex->height = 4;
  switch (dim) {
    case spv::Dim1D:
      tex->height = 1;
      tex->viewType = arrayed ? VK_IMAGE_VIEW_TYPE_1D_ARRAY : VK_IMAGE_VIEW_TYPE_1D;
      break;
    case spv::Dim2D:
    case spv::DimRect:
      tex->viewType = arrayed ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
      break;
    case spv::Dim3D:
      tex->depth = 4;
      tex->viewType = VK_IMAGE_VIEW_TYPE_3D;
      break;
    case spv::DimCube:
      tex->layers = 6;
      tex->viewType = arrayed ? VK_IMAGE_VIEW_TYPE_CUBE_ARRAY : VK_IMAGE_VIEW_TYPE_CUBE;
      break;
    case spv::DimBuffer:
      tex->width = 64;
      tex->height = 1;
      tex->type = storage ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER : VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
      break;
    default:
      *error = "texture " + where + " has a dimension the harness cannot bind (subpass inputs are fragment-only)";
      return false;
  }
  if (arrayed && dim != spv::DimBuffer) tex->layers *= dim == spv::DimCube ? 2 : 4;
  if (dim != spv::DimBuffer)
    tex->type = combined  ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER
                : storage ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE
                          : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
  const size_t values = tex->texelsPerElement() * 4 * count;
  tex->rgba.resize(values);
  for (size_t i = 0; i < values; ++i) {
    uint32_t h = mix(resourceSeed(set, binding, uint32_t(i / (tex->texelsPerElement() * 4))), uint32_t(i));
    if (kind == 'f') {
      tex->rgba[i] = float(unit(h));
    } else {
      uint32_t bits = h % 4;
      std::memcpy(&tex->rgba[i], &bits, 4);
    }
  }
  return true;
}

// Buffers, images, samplers and push constants of one module (merged across stages by the caller:
// a (set, binding) already present keeps its data).
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
    if (storage == spv::StorageClassPushConstant) {
      std::vector<uint8_t> bytes;
      r.fill(bytes, type, 0, 0, false, kPushConstantSeed);
      if (bytes.size() > in->pushConstants.size()) in->pushConstants = bytes;
      in->pushConstants.resize((in->pushConstants.size() + 3) & ~size_t(3), 0);
      continue;
    }
    if (storage != spv::StorageClassUniform && storage != spv::StorageClassStorageBuffer &&
        storage != spv::StorageClassUniformConstant)
      continue;
    // A separate texture and sampler at one (set, binding) (HLSL `[[vk::binding(1)]]` on both) are
    // the two halves of one combined image sampler descriptor.
    if (storage == spv::StorageClassUniformConstant)
      for (auto& t : in->textures)
        if (t.set == set && t.binding == binding) {
          SampledTexture other;
          std::string ignored;
          const Instruction* d = m.definition(type);
          uint32_t element = d && (d->opcode == spv::OpTypeArray || d->opcode == spv::OpTypeRuntimeArray) ? d->operand(0) : type;
          if (describeImage(m, element, set, binding, t.arrayCount, m.name(inst.resultId), &other, &ignored) &&
              ((t.type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE && other.type == VK_DESCRIPTOR_TYPE_SAMPLER) ||
               (t.type == VK_DESCRIPTOR_TYPE_SAMPLER && other.type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE))) {
            if (t.type == VK_DESCRIPTOR_TYPE_SAMPLER) t = std::move(other);
            t.type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
          }
        }
    if (present(set, binding)) {
      // The same (set, binding) in two stages, or in the original and its transpiled copy, is the
      // same resource; two different kinds of resource there cannot be bound at all.
      const bool image = storage == spv::StorageClassUniformConstant;
      bool clash = false;
      for (const auto& u : in->uniformBuffers) clash |= u.set == set && u.binding == binding && image;
      for (const auto& t : in->textures) clash |= t.set == set && t.binding == binding && !image;
      if (clash) {
        *error = "resource '" + m.name(inst.resultId) + "' (set " + std::to_string(set) + ", binding " +
                 std::to_string(binding) + ") shares its binding with a resource of another kind";
        return false;
      }
      continue;
    }
    // A descriptor array: `uniform Light { ... } lights[4]`, `sampler2D shadowMaps[3]`, or a
    // runtime-sized `texture2D textures[]` (bound with 4 elements).
    uint32_t count = 1, element = type;
    const Instruction* d = m.definition(type);
    if (d && (d->opcode == spv::OpTypeArray || d->opcode == spv::OpTypeRuntimeArray)) {
      count = d->opcode == spv::OpTypeArray ? std::max(1u, r.arrayLength(d)) : 4;
      element = d->operand(0);
    }
    if (storage == spv::StorageClassUniformConstant) {
      SampledTexture tex;
      if (!describeImage(m, element, set, binding, count, m.name(inst.resultId), &tex, error)) return false;
      in->textures.push_back(std::move(tex));
      continue;
    }
    const bool storageBuffer = storage == spv::StorageClassStorageBuffer || m.hasDecoration(element, spv::DecorationBufferBlock);
    UniformBuffer ub{set, binding, {}, storageBuffer, count};
    std::vector<std::vector<uint8_t>> elements(count);
    size_t size = 16;
    for (uint32_t e = 0; e < count; ++e) {
      r.fill(elements[e], element, 0, 0, false, resourceSeed(set, binding, e));
      size = std::max(size, (elements[e].size() + 15) & ~size_t(15));
    }
    for (auto& bytes : elements) {
      bytes.resize(size, 0);
      ub.bytes.insert(ub.bytes.end(), bytes.begin(), bytes.end());
    }
    in->uniformBuffers.push_back(std::move(ub));
  }
  return true;
}

// Where the transpiled module reads eyeSign / separation / convergence.
bool applyEyeParameters(const Module& m, const VerifySettings& s, float eyeSign, PipelineInputs* in,
                        std::string* error, bool* eyeSignFound = nullptr) {
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
        if (k == 0 && eyeSignFound) *eyeSignFound = true;
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
          if (k == 0 && eyeSignFound) *eyeSignFound = true;
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

// A push-constant block larger than the device allows (lavapipe: maxPushConstantsSize) cannot be
// pushed; the harness turns it into a uniform buffer at (set, 0) instead — the same bytes, read
// through the same offsets (the device's uniformBufferStandardLayout lets the std430 layout of
// push constants stand), identically in the original and the transpiled module.
void pushConstantsToUniformBuffer(Module& m, uint32_t set) {
  for (auto& inst : m.typesValues) {
    if (inst.opcode == spv::OpTypePointer && inst.operand(0) == uint32_t(spv::StorageClassPushConstant))
      inst.operands[0] = spv::StorageClassUniform;
    if (inst.opcode == spv::OpVariable && inst.operand(0) == uint32_t(spv::StorageClassPushConstant)) {
      inst.operands[0] = spv::StorageClassUniform;
      m.decorate(inst.resultId, spv::DecorationDescriptorSet, {set});
      m.decorate(inst.resultId, spv::DecorationBinding, {0});
    }
  }
  m.invalidateDefinitions();
}

uint32_t pushConstantBytes(const Module& m) {
  uint32_t bytes = 0;
  for (const auto& inst : m.typesValues)
    if (inst.opcode == spv::OpVariable && inst.operand(0) == uint32_t(spv::StorageClassPushConstant)) {
      std::vector<uint8_t> scratch;
      Reflector{m}.fill(scratch, m.pointeeType(inst.typeId), 0, 0, false, kPushConstantSeed);
      bytes = std::max(bytes, uint32_t(scratch.size()));
    }
  return bytes;
}

// The device features a module's capabilities need; empty when the device has them all.
std::string missingFeature(const Module& m, const VkPhysicalDeviceFeatures& f) {
  struct Need {
    spv::Capability capability;
    VkBool32 VkPhysicalDeviceFeatures::*feature;
    const char* capabilityName;
    const char* featureName;
  };
  static const Need needs[] = {
      {spv::CapabilityFloat64, &VkPhysicalDeviceFeatures::shaderFloat64, "Float64", "shaderFloat64"},
      {spv::CapabilityInt64, &VkPhysicalDeviceFeatures::shaderInt64, "Int64", "shaderInt64"},
      {spv::CapabilityInt16, &VkPhysicalDeviceFeatures::shaderInt16, "Int16", "shaderInt16"},
      {spv::CapabilityGeometryPointSize, &VkPhysicalDeviceFeatures::shaderTessellationAndGeometryPointSize,
       "GeometryPointSize", "shaderTessellationAndGeometryPointSize"},
      {spv::CapabilityTessellationPointSize, &VkPhysicalDeviceFeatures::shaderTessellationAndGeometryPointSize,
       "TessellationPointSize", "shaderTessellationAndGeometryPointSize"},
      {spv::CapabilityClipDistance, &VkPhysicalDeviceFeatures::shaderClipDistance, "ClipDistance", "shaderClipDistance"},
      {spv::CapabilityCullDistance, &VkPhysicalDeviceFeatures::shaderCullDistance, "CullDistance", "shaderCullDistance"},
      {spv::CapabilitySampledCubeArray, &VkPhysicalDeviceFeatures::imageCubeArray, "SampledCubeArray", "imageCubeArray"},
      {spv::CapabilityImageCubeArray, &VkPhysicalDeviceFeatures::imageCubeArray, "ImageCubeArray", "imageCubeArray"},
      {spv::CapabilityStorageImageReadWithoutFormat, &VkPhysicalDeviceFeatures::shaderStorageImageReadWithoutFormat,
       "StorageImageReadWithoutFormat", "shaderStorageImageReadWithoutFormat"},
      {spv::CapabilityStorageImageWriteWithoutFormat, &VkPhysicalDeviceFeatures::shaderStorageImageWriteWithoutFormat,
       "StorageImageWriteWithoutFormat", "shaderStorageImageWriteWithoutFormat"},
      {spv::CapabilityStorageImageExtendedFormats, &VkPhysicalDeviceFeatures::shaderStorageImageExtendedFormats,
       "StorageImageExtendedFormats", "shaderStorageImageExtendedFormats"},
      {spv::CapabilityMultiViewport, &VkPhysicalDeviceFeatures::multiViewport, "MultiViewport", "multiViewport"},
      {spv::CapabilityImageGatherExtended, &VkPhysicalDeviceFeatures::shaderImageGatherExtended,
       "ImageGatherExtended", "shaderImageGatherExtended"},
  };
  for (const Need& n : needs)
    if (m.hasCapability(n.capability) && !(f.*n.feature))
      return std::string("the ") + executionModelName(m.executionModel()) + " shader needs the " + n.featureName +
             " device feature (SPIR-V capability " + n.capabilityName + "), which this device lacks";
  return {};
}

// Double-precision vertex inputs (dvec3 positions of CAD-style samples) need 64-bit vertex
// formats, which lavapipe does not have. The harness feeds them as 32-bit floats instead: each
// such input becomes a float input at the same location whose loads are converted to double, in
// the original and the transpiled module alike (the generated data are floats anyway).
void feedDoubleInputsAsFloats(Module& m) {
  if (m.executionModel() != spv::ExecutionModelVertex) return;
  for (uint32_t id : m.entryInterface()) {
    const Instruction* var = m.definition(id);
    if (!var || var->operand(0) != spv::StorageClassInput || m.hasDecoration(id, spv::DecorationBuiltIn)) continue;
    const uint32_t doubleType = m.pointeeType(var->typeId);
    const Instruction* d = m.definition(doubleType);
    const uint32_t n = d && d->opcode == spv::OpTypeVector ? d->operand(1) : 1;
    const Instruction* scalar = d && d->opcode == spv::OpTypeVector ? m.definition(d->operand(0)) : d;
    if (!scalar || scalar->opcode != spv::OpTypeFloat || scalar->operand(0) != 64) continue;
    const uint32_t doubleScalar = scalar->resultId;
    const uint32_t floatScalar = m.typeFloat(32);
    const uint32_t floatType = n > 1 ? m.typeVector(floatScalar, n) : floatScalar;
    const uint32_t floatVar = m.addGlobalVariable(m.typePointer(spv::StorageClassInput, floatType), spv::StorageClassInput);
    const uint32_t floatScalarPointer = m.typePointer(spv::StorageClassInput, floatScalar);
    for (auto decoration : {spv::DecorationLocation, spv::DecorationComponent})
      if (auto value = m.decorationValue(id, decoration)) m.decorate(floatVar, decoration, {*value});
    m.setName(floatVar, m.name(id));
    // Out of the interface: the double variable is no longer read.
    for (auto& entry : m.entryPoints) {
      const size_t first = 2 + entry.stringWordCount(2);
      for (size_t i = first; i < entry.operands.size(); ++i)
        if (entry.operands[i] == id) {
          entry.operands.erase(entry.operands.begin() + long(i));
          break;
        }
    }
    std::vector<uint32_t> chains;  // access chains into the old variable, now into the float one
    for (auto& f : m.functions)
      for (auto& b : f.blocks) {
        std::vector<Instruction> rewritten;
        for (auto& inst : b.instructions) {
          if ((inst.opcode == spv::OpAccessChain || inst.opcode == spv::OpInBoundsAccessChain) && inst.operand(0) == id) {
            inst.typeId = floatScalarPointer;
            inst.operands[0] = floatVar;
            chains.push_back(inst.resultId);
          } else if (inst.opcode == spv::OpLoad &&
                     (inst.operand(0) == id ||
                      std::find(chains.begin(), chains.end(), inst.operand(0)) != chains.end())) {
            const bool whole = inst.operand(0) == id;
            const uint32_t loaded = m.takeId();
            rewritten.emplace_back(spv::OpLoad, whole ? floatType : floatScalar, loaded,
                                   std::vector<uint32_t>{whole ? floatVar : inst.operand(0)});
            rewritten.emplace_back(spv::OpFConvert, whole ? doubleType : doubleScalar, inst.resultId,
                                   std::vector<uint32_t>{loaded});
            continue;
          }
          rewritten.push_back(std::move(inst));
        }
        b.instructions = std::move(rewritten);
      }
    m.invalidateDefinitions();
  }
}

// Vertices per input primitive of a geometry shader, and the list topology that feeds it.
uint32_t geometryInput(const Module& geometry, VkPrimitiveTopology* topology) {
  for (const auto& mode : geometry.executionModes) switch (mode.operand(1)) {
      case spv::ExecutionModeInputPoints: *topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST; return 1;
      case spv::ExecutionModeInputLines: *topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST; return 2;
      case spv::ExecutionModeInputLinesAdjacency: *topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST_WITH_ADJACENCY; return 4;
      case spv::ExecutionModeInputTrianglesAdjacency:
        *topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST_WITH_ADJACENCY;
        return 6;
      case spv::ExecutionModeTriangles: *topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST; return 3;
      default: break;
    }
  *topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  return 3;
}

// The transpiled shader marks its position Invariant (the shift must not be contracted differently
// per eye); a driver then compiles everything feeding the position without FMA contraction
// (llvmpipe does), so the original — contracted — would differ from it in the last bits at
// eyeSign = 0 for reasons that are not the injected code. The harness marks the same outputs
// Invariant in its copy of the original, so that both compile alike and eyeSign = 0 is compared bit
// for bit against the same arithmetic.
void matchInvariance(Module& original, const Module& transpiled) {
  auto builtIn = [](const Module& m, uint32_t id) { return m.decorationValue(id, spv::DecorationBuiltIn); };
  std::vector<std::pair<uint32_t, uint32_t>> memberBuiltIns;  // (struct, member) -> BuiltIn, in the original
  for (const auto& inst : transpiled.annotations) {
    if (inst.opcode == spv::OpDecorate && inst.operand(1) == uint32_t(spv::DecorationInvariant)) {
      const uint32_t target = inst.operand(0);
      auto b = builtIn(transpiled, target);
      for (const auto& v : original.typesValues)
        if (v.opcode == spv::OpVariable && v.operand(0) == uint32_t(spv::StorageClassOutput) &&
            !original.hasDecoration(v.resultId, spv::DecorationInvariant) &&
            (b ? builtIn(original, v.resultId) == b : original.name(v.resultId) == transpiled.name(target))) {
          original.decorate(v.resultId, spv::DecorationInvariant);
          break;
        }
    } else if (inst.opcode == spv::OpMemberDecorate && inst.operand(2) == uint32_t(spv::DecorationInvariant)) {
      auto b = transpiled.memberDecorationValue(inst.operand(0), inst.operand(1), spv::DecorationBuiltIn);
      if (!b) continue;
      for (const auto& d : original.annotations)
        if (d.opcode == spv::OpMemberDecorate && d.operand(2) == uint32_t(spv::DecorationBuiltIn) && d.operand(3) == *b &&
            !original.hasMemberDecoration(d.operand(0), d.operand(1), spv::DecorationInvariant))
          memberBuiltIns.push_back({d.operand(0), d.operand(1)});
    }
  }
  for (auto [structId, member] : memberBuiltIns) original.decorateMember(structId, member, spv::DecorationInvariant);
}

// Takes `variable` out of every entry point's interface list (nothing reads it any more).
void dropFromInterface(Module& m, uint32_t variable) {
  for (auto& entry : m.entryPoints) {
    const size_t first = 2 + entry.stringWordCount(2);
    for (size_t i = first; i < entry.operands.size(); ++i)
      if (entry.operands[i] == variable) {
        entry.operands.erase(entry.operands.begin() + long(i));
        break;
      }
  }
}

// Multiview: transform feedback must not be active in a multiview render pass, so the harness
// draws each view on its own, in a copy of the module whose reads of the view index (ViewIndex)
// read that view's number as a constant (harness-only, like the capture decorations): the shader's
// code computes exactly what it computes in that view of a view-mask-0b11 draw.
bool bindViewIndex(Module& m, uint32_t view, std::string* error) {
  uint32_t variable = 0;
  for (const auto& inst : m.typesValues)
    if (inst.opcode == spv::OpVariable &&
        m.decorationValue(inst.resultId, spv::DecorationBuiltIn) == uint32_t(spv::BuiltInViewIndex))
      variable = inst.resultId;
  if (!variable) return true;  // this stage does not read the view
  const uint32_t type = m.pointeeType(m.definition(variable)->typeId);
  const Instruction* typeDef = m.definition(type);
  const bool isSigned = typeDef && typeDef->opcode == spv::OpTypeInt && typeDef->operand(1) == 1;
  const uint32_t value = m.constantInt(int32_t(view));
  for (auto& f : m.functions)
    for (auto& b : f.blocks)
      for (auto& inst : b.instructions) {
        if (inst.opcode == spv::OpLoad && inst.operand(0) == variable) {
          inst.opcode = isSigned ? spv::OpCopyObject : spv::OpBitcast;  // HLSL's SV_ViewID is a uint
          inst.operands = {value};
          continue;
        }
        const bool pointerUse =
            (inst.opcode == spv::OpCopyMemory && inst.operand(1) == variable) ||
            ((inst.opcode == spv::OpAccessChain || inst.opcode == spv::OpInBoundsAccessChain) && inst.operand(0) == variable) ||
            (inst.opcode == spv::OpFunctionCall &&
             std::find(inst.operands.begin() + 1, inst.operands.end(), variable) != inst.operands.end());
        if (pointerUse) {
          *error = "the " + std::string(executionModelName(m.executionModel())) +
                   " shader reads the view index other than by a load; the harness cannot run it per view";
          return false;
        }
      }
  dropFromInterface(m, variable);
  m.invalidateDefinitions();
  return true;
}

// Instanced: the vertex stage writes the eye to gl_Layer / gl_ViewportIndex, built-ins that the
// capture does not decorate for transform feedback. The harness's copy writes that same value to
// an ordinary int output instead, one location past every output the shader has, which the capture
// then reads like any other. Returns the output's name, empty when the shader writes no such built-in.
std::string exposeEyeRoute(Module& m, EyeRoute route) {
  const uint32_t builtIn = uint32_t(route == EyeRoute::Layer ? spv::BuiltInLayer : spv::BuiltInViewportIndex);
  uint32_t variable = 0, location = 0;
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable || inst.operand(0) != uint32_t(spv::StorageClassOutput)) continue;
    if (m.decorationValue(inst.resultId, spv::DecorationBuiltIn) == builtIn) variable = inst.resultId;
    if (auto l = m.decorationValue(inst.resultId, spv::DecorationLocation)) location = std::max(location, *l + 1);
  }
  if (!variable) return {};
  m.removeDecorations(variable, spv::DecorationBuiltIn);
  m.decorate(variable, spv::DecorationLocation, {location});
  const std::string name = route == EyeRoute::Layer ? "gl_Layer" : "gl_ViewportIndex";
  if (m.name(variable).empty()) m.setName(variable, name);
  return m.name(variable);
}

double ulpOf(double magnitude) {
  float m = static_cast<float>(std::max(magnitude, double(FLT_MIN)));
  return double(std::nextafter(m, INFINITY)) - double(m);
}

}  // namespace

// See stereo_verify.h. The ranges: b (constant buffers) 0-15, s (samplers) 16-31, u (unordered
// access: RW buffers and textures) 32-95, t (shader resources: textures, read-only structured /
// byte-address buffers) 96 and up.
void separateRegisterClasses(Module& m) {
  constexpr uint32_t kSamplerShift = 16, kUavShift = 32, kTextureShift = 96;
  std::map<uint32_t, uint32_t> shiftOf;
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable) continue;
    auto storage = static_cast<spv::StorageClass>(inst.operand(0));
    uint32_t type = m.pointeeType(inst.typeId);
    const Instruction* def = m.definition(type);
    while (def && (def->opcode == spv::OpTypeArray || def->opcode == spv::OpTypeRuntimeArray)) def = m.definition(def->operand(0));
    if (!def) continue;
    if (storage == spv::StorageClassUniform || storage == spv::StorageClassStorageBuffer) {
      bool buffer = storage == spv::StorageClassStorageBuffer || m.hasDecoration(def->resultId, spv::DecorationBufferBlock);
      if (!buffer) continue;  // a cbuffer: b, unmoved
      bool readOnly = m.hasDecoration(inst.resultId, spv::DecorationNonWritable) ||
                      (def->opcode == spv::OpTypeStruct && !def->operands.empty() &&
                       m.hasMemberDecoration(def->resultId, 0, spv::DecorationNonWritable));
      shiftOf[inst.resultId] = readOnly ? kTextureShift : kUavShift;
    } else if (storage == spv::StorageClassUniformConstant) {
      if (def->opcode == spv::OpTypeSampler) shiftOf[inst.resultId] = kSamplerShift;
      else if (def->opcode == spv::OpTypeImage) shiftOf[inst.resultId] = def->operand(5) == 2 ? kUavShift : kTextureShift;
      else if (def->opcode == spv::OpTypeSampledImage) shiftOf[inst.resultId] = kTextureShift;
    }
  }
  for (auto& inst : m.annotations)
    if (inst.opcode == spv::OpDecorate && inst.operand(1) == uint32_t(spv::DecorationBinding))
      if (auto it = shiftOf.find(inst.operand(0)); it != shiftOf.end()) inst.operands[2] += it->second;
}

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
    // The single-pass modes refuse what the output language cannot express (ESSL vertex shaders
    // and gl_Layer, OpenGL multiview and geometry stages, ...): verify runs SPIR-V, so it first
    // converts for the output the user asked for and reports that conversion's refusal as its own.
    if (options.eye.select != EyeSelect::Parameter && options.target != TargetLanguage::Spirv) {
      TranspileOptions asAsked = options;
      asAsked.shiftThisStage = i + 1 == ordered.size();
      TranspileResult check = transpile(*ordered[i], asAsked);
      if (!check.ok) {
        diags.append(check.diagnostics);
        return false;
      }
    }
    TranspileOptions o = options;
    o.target = TargetLanguage::Spirv;
    o.forceReemit = true;
    o.shiftThisStage = i + 1 == ordered.size();
    TranspileResult result = transpile(*ordered[i], o);
    diags.append(result.diagnostics);
    if (!result.ok) return false;
    *classification = result.record.classification ? toString(*result.record.classification) : "";
    std::vector<uint32_t> words(result.output.size() / 4);
    std::memcpy(words.data(), result.output.data(), words.size() * 4);
    std::string error;
    auto original = spirv::Module::parse(result.originalSpirv, &error);
    if (!original) {
      diags.error(ordered[i]->path, error);
      return false;
    }
    const RunRecord& passes = result.record.passes;
    std::vector<std::string> halo = passes.halo.shiftedOutputs.value_or(std::vector<std::string>{});
    // Outputs computed from the per-eye camera (per-eye-view: relief view vectors) differ between
    // the eyes by design, like re-derived halo outputs; eyeSign = 0 still has to be bit for bit.
    halo.insert(halo.end(), passes.perEyeView.perEyeOutputs.begin(), passes.perEyeView.perEyeOutputs.end());
    // D3D register classes (b, t, s, u) each count from 0; HLSL written for Vulkan ([[vk::binding]])
    // and GLSL share one binding space.
    const bool d3dRegisters = perClassRegisters(result.source);
    stages->push_back({toVk(original->executionModel()), std::move(result.originalSpirv), std::move(words),
                       original->entryPointName(), std::move(halo), d3dRegisters});
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
    if (s.d3dRegisters) {
      separateRegisterClasses(*a);
      separateRegisterClasses(*b);
    }
    // OpenGL shaders run through the same Vulkan-compatible rewrite, original and transpiled alike.
    const uint32_t blockBinding = 16 + static_cast<uint32_t>(originals.size());
    if (!convertOpenGLForVulkan(*a, blockBinding, &error) && !error.empty()) {
      result.error = error;
      return result;
    }
    convertOpenGLForVulkan(*b, blockBinding, &error);
    matchInvariance(*a, *b);
    feedDoubleInputsAsFloats(*a);
    feedDoubleInputsAsFloats(*b);
    originals.push_back(std::move(*a));
    transpiled.push_back(std::move(*b));
  }
  // A tessellation-evaluation or geometry shader given alone runs behind synthesized pass-through
  // stages, the same in front of the original and the transpiled one.
  std::vector<Module> leading;
  std::vector<std::string> leadingNames;
  std::string error;
  if (!synthesizeLeadingStages(originals.front(), &leading, &leadingNames, &error)) {
    result.error = error;
    return result;
  }
  originals.insert(originals.begin(), leading.begin(), leading.end());
  if (settings.eyeSource == EyeSelect::InstanceIndex) {
    // Instanced: in front of the transpiled stage the synthesized stages hand the eye on, as
    // stereoshift converts them in a pipeline (the vertex stage takes it from the instance).
    for (size_t i = 0; i < leading.size(); ++i) {
      TranspileOptions o;
      o.target = TargetLanguage::Spirv;
      o.shiftThisStage = false;
      o.eye.select = EyeSelect::InstanceIndex;
      o.eye.eyeVaryingName = settings.eyeVaryingName;
      o.eye.eyeVaryingLocation = settings.eyeVaryingLocation;
      std::vector<uint32_t> words = leading[i].encode();
      TranspileResult converted = transpile(
          SourceFile{leadingNames[i], std::string(reinterpret_cast<const char*>(words.data()), words.size() * 4)}, o);
      std::optional<Module> m;
      if (converted.ok && converted.output.size() % 4 == 0) {
        std::vector<uint32_t> out(converted.output.size() / 4);
        std::memcpy(out.data(), converted.output.data(), converted.output.size());
        m = Module::parse(out, &error);
      }
      if (!m) {
        result.error = "the synthesized " + leadingNames[i] + " could not hand the eye on: " +
                       (converted.ok ? error : converted.diagnostics.format());
        return result;
      }
      leading[i] = std::move(*m);
    }
  }
  transpiled.insert(transpiled.begin(), leading.begin(), leading.end());
  result.synthesizedStages = leadingNames;
  for (size_t i = 0; i + 1 < originals.size(); ++i)
    if (!checkStageInterface(originals[i], originals[i + 1], &error)) {
      result.error = error;
      return result;
    }
  for (const auto& m : transpiled) {
    std::string missing = missingFeature(m, context.features());
    if (!missing.empty()) {
      result.error = missing;
      return result;
    }
  }
  // Push constants over the device limit: a uniform buffer one set beyond every set in use.
  const uint32_t pushLimit = context.properties().limits.maxPushConstantsSize;
  uint32_t pushBytes = 0, freeSet = 0;
  for (const auto* list : {&originals, &transpiled})
    for (const auto& m : *list) {
      pushBytes = std::max(pushBytes, pushConstantBytes(m));
      for (const auto& inst : m.annotations)
        if (inst.opcode == spv::OpDecorate && inst.operand(1) == uint32_t(spv::DecorationDescriptorSet))
          freeSet = std::max(freeSet, inst.operand(2) + 1);
    }
  if (pushBytes > pushLimit) {
    if (freeSet >= context.properties().limits.maxBoundDescriptorSets) {
      result.error = "the push constants (" + std::to_string(pushBytes) + " bytes) exceed the device's " +
                     std::to_string(pushLimit) + "-byte limit and no descriptor set is free to hold them instead";
      return result;
    }
    for (auto* list : {&originals, &transpiled})
      for (auto& m : *list) pushConstantsToUniformBuffer(m, freeSet);
    result.pushConstantsAsBuffer = true;
  }
  const EyeSelect mode = settings.eyeSource;
  result.mode = mode;
  std::string routeName;  // instanced: the harness's output carrying what the shader writes to the layer / viewport
  if (mode == EyeSelect::InstanceIndex) routeName = exposeEyeRoute(transpiled.back(), settings.eyeRoute);
  CaptureLayout layoutA, layoutB;
  if (!instrumentForCapture(originals.back(), &layoutA, nullptr, &error) ||
      !instrumentForCapture(transpiled.back(), &layoutB, nullptr, &error)) {
    result.error = error;
    return result;
  }
  // Each captured component of the original, at its place in the transpiled capture (instanced mode
  // adds the eye outputs, which the original does not have).
  std::vector<uint32_t> inStereo(layoutA.stride / 4, UINT32_MAX);
  int eyeVaryingComponent = -1, routeComponent = -1;
  std::vector<bool> matched(layoutA.fields.size(), false);
  for (const auto& g : layoutB.fields) {
    const CapturedField* match = nullptr;
    for (size_t i = 0; i < layoutA.fields.size() && !match; ++i) {
      const auto& f = layoutA.fields[i];
      if (!matched[i] && f.isPosition == g.isPosition && f.location == g.location && f.components == g.components) {
        matched[i] = true;
        match = &f;
      }
    }
    if (match) {
      for (uint32_t k = 0; k < g.components; ++k) inStereo[match->offset / 4 + k] = g.offset / 4 + k;
    } else if (mode == EyeSelect::InstanceIndex && g.name == settings.eyeVaryingName && g.components == 1) {
      eyeVaryingComponent = int(g.offset / 4);
    } else if (mode == EyeSelect::InstanceIndex && !routeName.empty() && g.name == routeName && g.components == 1) {
      routeComponent = int(g.offset / 4);
    } else {
      result.error = "original and transpiled shaders have different outputs";
      return result;
    }
  }
  if (std::find(inStereo.begin(), inStereo.end(), UINT32_MAX) != inStereo.end()) {
    result.error = "original and transpiled shaders have different outputs";
    return result;
  }
  // Multiview: one copy of the transpiled stages per view, each reading its view's index.
  std::vector<std::vector<Module>> perView;
  if (mode == EyeSelect::ViewIndex)
    for (uint32_t view = 0; view < 2; ++view) {
      perView.push_back(transpiled);
      for (auto& m : perView.back())
        if (!bindViewIndex(m, view, &error)) {
          result.error = error;
          return result;
        }
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
  const Module* geometry = nullptr;
  for (const auto& m : originals) {
    tessellation |= m.executionModel() == spv::ExecutionModelTessellationControl;
    if (m.executionModel() == spv::ExecutionModelGeometry) geometry = &m;
  }
  uint32_t count = settings.vertexCount;
  if (tessellation) {
    base.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
    base.patchControlPoints = patchControlPoints(originals);
    if (base.patchControlPoints == 0) base.patchControlPoints = 3;
    count -= count % base.patchControlPoints;
  } else if (geometry) {
    count -= count % geometryInput(*geometry, &base.topology);
  } else {
    base.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    count -= count % 3;
  }
  base.vertexCount = count;
  // Instanced: the original draws a few instances (so a shader whose outputs depend on the instance
  // shows whether the rewrite reads the right one), the stereo draw twice as many.
  const uint32_t instances = mode == EyeSelect::InstanceIndex ? std::max(1u, settings.originalInstances) : 1;
  base.instanceCount = instances;
  result.instances = instances;
  stereoBase.topology = base.topology;
  stereoBase.patchControlPoints = base.patchControlPoints;
  stereoBase.vertexCount = base.vertexCount;
  stereoBase.instanceCount = mode == EyeSelect::InstanceIndex ? 2 * instances : 1;

  auto run = [&](std::vector<Module>& modules, const PipelineInputs& inputs, CaptureResult* out) {
    const bool original = &modules == &originals;
    CaptureRequest request;
    request.pipeline = inputs;
    for (size_t i = 0; i < modules.size(); ++i)
      request.pipeline.stages.push_back({toVk(modules[i].executionModel()), modules[i].encode(), modules[i].entryPointName()});
    request.xfbStride = original ? layoutA.stride : layoutB.stride;
    // Room for tessellation / geometry amplification.
    request.expectedVertices = count * 64 * inputs.instanceCount;
    *out = context.capture(request);
    return out->ok();
  };
  // The transpiled stages run with eyeSign = `eye` (the single-pass modes: a value they must ignore).
  auto runStereo = [&](std::vector<Module>& modules, float eye, CaptureResult* out) {
    PipelineInputs inputs = stereoBase;
    // A shader without a shift (a 2D one in instanced mode) may have no parameters at all.
    if (!applyEyeParameters(modules.back(), settings, eye, &inputs, &error) && settings.shifted) {
      result.error = error;
      return false;
    }
    if (!run(modules, inputs, out)) {
      result.error = "transpiled: " + out->error;
      return false;
    }
    return true;
  };

  CaptureResult mono;
  if (!run(originals, base, &mono)) {
    result.error = "original: " + mono.error;
    return result;
  }
  result.vertices = mono.vertexCount();
  const CapturedField* position = layoutA.position();
  const uint32_t px = position->offset / 4, pxStereo = inStereo[px];
  result.otherOutputsUnchanged = true;

  // A captured component as the shader wrote it: a float, or an integer (instance ids, eyes).
  std::vector<bool> integerComponent(layoutA.stride / 4, false);
  for (const auto& f : layoutA.fields)
    for (uint32_t k = 0; k < f.components; ++k) integerComponent[f.offset / 4 + k] = !f.isFloat;
  auto valueText = [&](const CaptureResult& capture, uint32_t vertex, uint32_t component) {
    const uint32_t original = &capture == &mono ? component
                              : uint32_t(std::find(inStereo.begin(), inStereo.end(), component) - inStereo.begin());
    return original < integerComponent.size() && integerComponent[original]
               ? std::to_string(int32_t(capture.u32(vertex, component)))
               : std::to_string(capture.f32(vertex, component));
  };
  // Captured vertex `vm` of the original against vertex `vs` of a stereo run of eye sign `eye`: x
  // against the exact reference, every other component unchanged (halo outputs excepted).
  auto compareVertex = [&](const CaptureResult& stereo, uint32_t vm, uint32_t vs, float eye, const std::string& run) {
    double x = mono.f32(vm, px), w = mono.f32(vm, px + 3);
    float got = stereo.f32(vs, pxStereo);
    // The shader's guard, in its own fp32 terms: ordered comparisons (a NaN w is not shifted)
    // and never an infinite w.
    bool far = settings.cutoffEpsilon > 0 ? std::fabs(float(w) - 1.0f) > settings.cutoffEpsilon : float(w) != 1.0f;
    bool unshifted = !settings.shifted || (settings.cutoff && (!far || std::isnan(w) || std::isinf(w)));
    double shift = double(eye) * settings.separation * (w - settings.convergence);
    double reference = unshifted ? x : x + shift;
    if (unshifted && settings.shifted && eye > 0) ++result.cutoffVertices;
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
      const uint32_t cs = inStereo[c];
      bool staleCopy = false;
      for (const auto& f : layoutA.fields)
        staleCopy |= !f.isPosition && f.components == 4 && c == f.offset / 4 && mono.u32(vm, c) == mono.u32(vm, px) &&
                     stereo.u32(vs, cs) != stereo.u32(vs, pxStereo);
      if (staleCopy) {  // a copy of the position left mono: the 3Dmigoto "halo"
        result.otherOutputsUnchanged = false;
        if (result.problems.size() < 8)
          result.problems.push_back("vertex " + std::to_string(vs) + ": a copy of the position (component " +
                                    std::to_string(c) + ") was not shifted with it (halo) in " + run);
        continue;
      }
      if (mono.u32(vm, c) == stereo.u32(vs, cs)) continue;
      bool haloCopy = false, haloDerived = false;
      for (const auto& f : layoutA.fields) {
        if (f.isPosition || c < f.offset / 4 || c >= f.offset / 4 + f.components) continue;
        // A copied position must carry exactly the shifted x of gl_Position; other outputs the
        // halo pass re-derived may move (their formula is the shader's own).
        if (f.components == 4 && c == f.offset / 4 && mono.u32(vm, c) == mono.u32(vm, px)) {
          haloCopy = stereo.u32(vs, cs) == stereo.u32(vs, pxStereo);
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
          result.problems.push_back("vertex " + std::to_string(vs) + " component " + std::to_string(c) + " changed for " +
                                    run + " (" + valueText(mono, vm, c) + " became " + valueText(stereo, vs, cs) + ")");
      }
    }
  };
  // The eye sign of view / instance eye `e` (0 or 1): the left eye first unless the eyes are swapped.
  auto signOf = [&](uint32_t e) { return (e == 0 ? -1.0f : 1.0f) * (settings.swapEyes ? -1.0f : 1.0f); };
  // Single-pass: eyeSign is no longer an input. A junk value there (far from -1, 0, +1, so a shader
  // that still read it would shift by several separations) must leave every captured bit as it was.
  constexpr float kJunkEyeSign = 7.5f;
  auto checkIgnoresEyeSign = [&](std::vector<Module>& modules, const CaptureResult& withZero, const std::string& run) {
    {
      PipelineInputs scratch = stereoBase;
      std::string ignored;
      applyEyeParameters(modules.back(), settings, kJunkEyeSign, &scratch, &ignored, &result.eyeSignDeclared);
    }
    if (!result.eyeSignDeclared) {
      result.eyeSignIgnored = true;  // nothing to set: the shader cannot read it
      return true;
    }
    CaptureResult junk;
    if (!runStereo(modules, kJunkEyeSign, &junk)) return false;
    const bool same = junk.bytes == withZero.bytes;
    result.eyeSignIgnored = result.eyeSignIgnored && same;
    if (!same) result.problems.push_back(run + ": eyeSign = " + std::to_string(kJunkEyeSign) + " changed the outputs: the shader still reads the eyeSign parameter");
    return true;
  };

  if (mode == EyeSelect::Parameter) {
    result.monoIdentical = true;
    for (float eye : {0.0f, -1.0f, 1.0f}) {
      CaptureResult stereo;
      if (!runStereo(transpiled, eye, &stereo)) return result;
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
      for (uint32_t v = 0; v < result.vertices; ++v) compareVertex(stereo, v, v, eye, "eye " + std::to_string(int(eye)));
    }
  } else if (mode == EyeSelect::ViewIndex) {
    result.eyeSignIgnored = true;
    for (uint32_t view = 0; view < 2; ++view) {
      const std::string name = "view " + std::to_string(view);
      CaptureResult stereo;
      if (!runStereo(perView[view], 0.0f, &stereo)) return result;
      if (stereo.vertexCount() != mono.vertexCount()) {
        result.problems.push_back(name + ": captured a different number of vertices");
        continue;
      }
      for (uint32_t v = 0; v < result.vertices; ++v) compareVertex(stereo, v, v, signOf(view), name);
      if (!checkIgnoresEyeSign(perView[view], stereo, name)) return result;
    }
  } else {
    result.eyeSignIgnored = true;
    CaptureResult stereo;
    if (!runStereo(transpiled, 0.0f, &stereo)) return result;
    const uint32_t perInstance = result.vertices / instances;
    if (stereo.vertexCount() != 2 * result.vertices || perInstance * instances != result.vertices) {
      result.problems.push_back(std::to_string(2 * instances) + " instances captured " +
                                std::to_string(stereo.vertexCount()) + " vertices, not twice the " +
                                std::to_string(result.vertices) + " of the original's " + std::to_string(instances));
    } else {
      result.eyeRouted = routeComponent >= 0;
      result.eyeVaryingWritten = eyeVaryingComponent >= 0;
      if (routeComponent < 0)
        result.problems.push_back(std::string("the vertex shader writes no ") +
                                  (settings.eyeRoute == EyeRoute::Layer ? "gl_Layer" : "gl_ViewportIndex"));
      if (eyeVaryingComponent < 0) result.problems.push_back("the vertex shader writes no '" + settings.eyeVaryingName + "' output");
      for (uint32_t vs = 0; vs < stereo.vertexCount(); ++vs) {
        // Instance 2k+e of the stereo draw is the original's instance k seen by eye e.
        const uint32_t instance = vs / perInstance, k = instance >> 1, e = instance & 1;
        const uint32_t vm = k * perInstance + vs % perInstance;
        const std::string name = "instance " + std::to_string(instance) + " (eye " + std::to_string(e) + ")";
        compareVertex(stereo, vm, vs, signOf(e), name);
        auto checkEye = [&](int component, const std::string& what, bool* ok) {
          if (component < 0 || stereo.u32(vs, uint32_t(component)) == e) return;
          if (*ok && result.problems.size() < 8)
            result.problems.push_back("vertex " + std::to_string(vs) + ": " + what + " is " +
                                      std::to_string(int32_t(stereo.u32(vs, uint32_t(component)))) + ", not the eye " +
                                      std::to_string(e) + " of " + name);
          *ok = false;
        };
        checkEye(routeComponent, routeName, &result.eyeRouted);
        checkEye(eyeVaryingComponent, settings.eyeVaryingName, &result.eyeVaryingWritten);
      }
    }
    if (!checkIgnoresEyeSign(transpiled, stereo, "instanced draw")) return result;
  }
  if (result.maxStereoUlps > settings.maxUlps)
    result.problems.push_back("stereo error " + std::to_string(result.maxStereoUlps) + " ULP exceeds the bound of " +
                              std::to_string(settings.maxUlps));
  if (result.newNaNs) result.problems.push_back(std::to_string(result.newNaNs) + " new NaN x values");
  const bool eyeChecks = mode == EyeSelect::Parameter    ? result.monoIdentical
                         : mode == EyeSelect::ViewIndex ? result.eyeSignIgnored
                                                        : result.eyeSignIgnored && result.eyeRouted && result.eyeVaryingWritten;
  result.ok = eyeChecks && result.otherOutputsUnchanged && result.maxStereoUlps <= settings.maxUlps &&
              result.newNaNs == 0 && result.problems.empty();
  return result;
}

}  // namespace stereoshift::harness
