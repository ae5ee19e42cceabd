// verify's input synthesis (see verify_inputs.h).
//
// The generated data decide what "equal outputs" mean, so they are distinct: every scalar, vector
// and matrix value is seeded by its resource (set, binding, array element) and its byte offset, and
// no two uniforms hold the same numbers. Matrices: no heuristic guesses which mat4 is the projection.
// Each is instead its own member of a family that maps points in front of a camera (z < 0, w > 0)
// to points in front again, with a projective last row so w leaves 1 (see matrixEntry): any
// product of them, in either multiplication order, keeps the geometry in front with w spread from
// near to far. So a shadow-map coordinate `DepthBiasMVP * p` and the position `MVP * p` differ, and a
// pass that used the wrong operand shows.
#include "transpiler/verify/verify_inputs.h"

#include "passes/ir/module.h"
#include "transpiler/verify/address_inputs.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

namespace stereoshift::harness {

using spirv::Instruction;
using spirv::Module;

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
  // Memory the shader reaches through device addresses (see address_inputs.h): each pointer, or
  // integer cast to one, gets a buffer of its own filled like any other resource.
  std::vector<std::vector<uint8_t>>* addressBuffers = nullptr;
  AddressSources addressSources = {};
  mutable uint32_t addressDepth = 0;
  mutable uint32_t runtimeElements = 64;  // elements given to a runtime-sized array

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

  // A buffer of `pointee` data for an address; its placeholder goes at byte `at` of `bytes`.
  // Runtime arrays in it get 4096 elements (shaders index them by vertex), and the buffer is at
  // least 64 KiB, so reads a little past what the type says stay in memory the draw owns. Three
  // levels down (a linked list) the address is null, as the end of a list is: a cycle would keep
  // a traversal running for ever.
  void putAddress(std::vector<uint8_t>& bytes, size_t at, uint32_t pointee, uint32_t seed) const {
    uint64_t placeholder = 0;
    if (addressBuffers && addressDepth < 3) {
      const uint32_t index = uint32_t(addressBuffers->size());
      addressBuffers->emplace_back();
      const uint32_t savedDepth = addressDepth, savedElements = runtimeElements;
      addressDepth = savedDepth + 1;
      runtimeElements = 4096;
      std::vector<uint8_t> data;
      fill(data, pointee, 0, 0, false, mix(seed, 0xADD5u));
      data.resize(std::max<size_t>((data.size() + 15) & ~size_t(15), 64 * 1024), 0);
      (*addressBuffers)[index] = std::move(data);
      addressDepth = savedDepth;
      runtimeElements = savedElements;
      placeholder = addressPlaceholder(index);
    }
    if (bytes.size() < at + 8) bytes.resize(at + 8, 0);
    std::memcpy(bytes.data() + at, &placeholder, 8);
  }

  // An integer member the shader casts to an address (every element of an array member).
  bool fillIntegerAddress(std::vector<uint8_t>& bytes, uint32_t structType, uint32_t member, uint32_t memberType,
                          size_t at, uint32_t seed) const {
    auto source = addressSources.integerMembers.find({structType, member});
    if (source == addressSources.integerMembers.end()) return false;
    const Instruction* d = def(memberType);
    uint32_t count = 1, stride = 8;
    if (d && (d->opcode == spv::OpTypeArray || d->opcode == spv::OpTypeRuntimeArray)) {
      count = d->opcode == spv::OpTypeArray ? arrayLength(d) : runtimeElements;
      stride = m.decorationValue(memberType, spv::DecorationArrayStride).value_or(8);
    }
    for (uint32_t i = 0; i < count; ++i) putAddress(bytes, at + size_t(i) * stride, source->second, mix(seed, i));
    return true;
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
      case spv::OpTypePointer: {
        uint32_t pointee = 0;
        if (isDeviceAddressPointer(m, type, &pointee)) putAddress(bytes, at, pointee, here);
        break;
      }
      case spv::OpTypeArray:
      case spv::OpTypeRuntimeArray: {
        uint32_t count = d->opcode == spv::OpTypeArray ? arrayLength(d) : runtimeElements;
        uint32_t stride = m.decorationValue(type, spv::DecorationArrayStride).value_or(16);
        for (uint32_t i = 0; i < count; ++i) fill(bytes, d->operand(0), at + i * stride, matrixStride, rowMajor, seed, true);
        break;
      }
      case spv::OpTypeStruct:
        for (uint32_t i = 0; i < d->operands.size(); ++i) {
          uint32_t offset = m.memberDecorationValue(type, i, spv::DecorationOffset).value_or(0);
          uint32_t ms = m.memberDecorationValue(type, i, spv::DecorationMatrixStride).value_or(0);
          bool rm = m.hasMemberDecoration(type, i, spv::DecorationRowMajor);
          if (!fillIntegerAddress(bytes, type, i, d->operands[i], at + offset, mix(here, i)))
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

}  // namespace

// Vertex data. Attribute i of vertex v: a point spread over x, y in [-2, 2] and z in [-60, -0.5]
// (in front of a camera looking down -z, which every generated matrix keeps in front), moved a
// little per location so that two attributes never hold the same values; the fourth component of
// a four-component vector is 1. Integer attributes get small values (v + location) mod 4 in the
// first component (bone and instance indices), 0 or 1 in the others. Matrices take one location
// per column, arrays one per element, dvec3/dvec4 two, fed as 64-bit formats.
Result<VertexBuffer> buildVertices(const Module& m, uint32_t count) {
  VertexBuffer buffer, *vb = &buffer;
  std::string error;
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
      error = "vertex input '" + name + "' at location " + std::to_string(location) +
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
    if (!expand(*location, m.pointeeType(var->typeId), m.name(id))) return plainError(error);
  }
  if (leaves.empty()) return buffer;  // no vertex inputs (a full-screen triangle from gl_VertexIndex): no buffer
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
  return buffer;
}

namespace {

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
Result<SampledTexture> describeImage(const Module& m, uint32_t type, uint32_t set, uint32_t binding, uint32_t count,
                                     const std::string& name) {
  SampledTexture texture, *tex = &texture;
  const Instruction* d = m.definition(type);
  const std::string where = "'" + name + "' (set " + std::to_string(set) + ", binding " + std::to_string(binding) + ")";
  tex->set = set;
  tex->binding = binding;
  tex->arrayCount = count;
  if (d && d->opcode == spv::OpTypeSampler) {
    tex->type = VK_DESCRIPTOR_TYPE_SAMPLER;
    tex->width = tex->height = 1;
    tex->rgba.assign(4 * count, 0.f);
    return texture;
  }
  bool combined = d && d->opcode == spv::OpTypeSampledImage;
  if (combined) d = m.definition(d->operand(0));
  if (!d || d->opcode != spv::OpTypeImage) {
    return plainError("resource " + where + " is not a buffer, image or sampler the harness can bind");
  }
  const Instruction* sampled = m.definition(d->operand(0));
  const char kind = sampled && sampled->opcode == spv::OpTypeInt ? (sampled->operand(1) ? 'i' : 'u') : 'f';
  const uint32_t dim = d->operand(1), arrayed = d->operand(3), multisampled = d->operand(4), usage = d->operand(5);
  if (multisampled) {
    return plainError("multisampled texture " + where + ": the harness binds single-sampled images only");
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
      return plainError("texture " + where + " has a dimension the harness cannot bind (subpass inputs are fragment-only)");
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
  return texture;
}

}  // namespace

// Buffers, images, samplers and push constants of one module (merged across stages by the caller:
// a (set, binding) already present keeps its data).
Status buildResources(const Module& m, PipelineInputs* in) {
  Reflector r{m, &in->addressBuffers, traceAddressSources(m)};
  if (!r.addressSources.problem.empty())
    return plainError("the shader reads memory through a buffer device address, and " + r.addressSources.problem +
                      ": the harness cannot give it valid memory, so it is not run");
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
          const Instruction* d = m.definition(type);
          uint32_t element = d && (d->opcode == spv::OpTypeArray || d->opcode == spv::OpTypeRuntimeArray) ? d->operand(0) : type;
          Result<SampledTexture> other = describeImage(m, element, set, binding, t.arrayCount, m.name(inst.resultId));
          if (other && ((t.type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE && other->type == VK_DESCRIPTOR_TYPE_SAMPLER) ||
                        (t.type == VK_DESCRIPTOR_TYPE_SAMPLER && other->type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE))) {
            if (t.type == VK_DESCRIPTOR_TYPE_SAMPLER) t = std::move(*other);
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
      if (clash)
        return plainError("resource '" + m.name(inst.resultId) + "' (set " + std::to_string(set) + ", binding " +
                          std::to_string(binding) + ") shares its binding with a resource of another kind");
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
      Result<SampledTexture> tex = describeImage(m, element, set, binding, count, m.name(inst.resultId));
      if (!tex) return tex.error();
      in->textures.push_back(std::move(*tex));
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
  return Done{};
}

// Where the transpiled module reads eyeSign / separation / convergence.
Result<bool> applyEyeParameters(const Module& m, const VerifySettings& s, float eyeSign, PipelineInputs* in) {
  bool eyeSignAmong = false, *eyeSignFound = &eyeSignAmong;
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
  // 3Dmigoto's StereoParams texture (--eye-source 3dmigoto): texel (0, 0) holds x = the separation
  // with the eye's sign, y = the convergence, z = the eye; 0 separation in mono.
  for (const auto& inst : m.typesValues) {
    if (inst.opcode != spv::OpVariable || inst.operand(0) != uint32_t(spv::StorageClassUniformConstant) ||
        m.name(inst.resultId) != "StereoParams")
      continue;
    uint32_t set = m.decorationValue(inst.resultId, spv::DecorationDescriptorSet).value_or(0);
    uint32_t binding = m.decorationValue(inst.resultId, spv::DecorationBinding).value_or(0);
    for (auto& tex : in->textures) {
      if (tex.set != set || tex.binding != binding || tex.rgba.size() < 4) continue;
      const float texel[4] = {eyeSign * s.separation, s.convergence, eyeSign, 0.0f};
      std::copy(texel, texel + 4, tex.rgba.begin());
      found = true;
      if (eyeSignFound) *eyeSignFound = true;
    }
  }
  if (!found) return plainError("the transpiled shader has no eye parameters the harness can set");
  return eyeSignAmong;
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

}  // namespace stereoshift::harness
