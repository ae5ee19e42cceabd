#include "passes/ir/image_instructions.h"

namespace stereoshift::spirv {

std::optional<ImageAccess> imageAccess(spv::Op op) {
  constexpr bool kTexels = true, kCompare = true;
  switch (op) {
    case spv::OpImageSampleImplicitLod: case spv::OpImageSampleExplicitLod:
    case spv::OpImageSampleProjImplicitLod: case spv::OpImageSampleProjExplicitLod:
    case spv::OpImageFetch: case spv::OpImageRead:
    case spv::OpImageSparseSampleImplicitLod: case spv::OpImageSparseSampleExplicitLod:
    case spv::OpImageSparseSampleProjImplicitLod: case spv::OpImageSparseSampleProjExplicitLod:
    case spv::OpImageSparseFetch: case spv::OpImageSparseRead:
      return ImageAccess{kTexels, !kCompare, 2};
    // A gather names the component to gather at word 2, so its mask comes one word later.
    case spv::OpImageGather: case spv::OpImageSparseGather:
      return ImageAccess{kTexels, !kCompare, 3};
    // The depth reference sits at word 2.
    case spv::OpImageSampleDrefImplicitLod: case spv::OpImageSampleDrefExplicitLod:
    case spv::OpImageSampleProjDrefImplicitLod: case spv::OpImageSampleProjDrefExplicitLod:
    case spv::OpImageDrefGather:
    case spv::OpImageSparseSampleDrefImplicitLod: case spv::OpImageSparseSampleDrefExplicitLod:
    case spv::OpImageSparseSampleProjDrefImplicitLod: case spv::OpImageSparseSampleProjDrefExplicitLod:
    case spv::OpImageSparseDrefGather:
      return ImageAccess{kTexels, kCompare, 3};
    // Not reads, but they address an image at a coordinate: a write (texel at word 2) and a
    // level-of-detail query (no image operands).
    case spv::OpImageWrite:
      return ImageAccess{!kTexels, !kCompare, 3};
    case spv::OpImageQueryLod:
      return ImageAccess{!kTexels, !kCompare, -1};
    default:
      return std::nullopt;
  }
}

bool isImageSampleOrFetch(spv::Op op) {
  auto access = imageAccess(op);
  return access && access->readsTexels;
}

bool isTexelRead(spv::Op op) {
  auto access = imageAccess(op);
  return access && access->readsTexels && !access->depthComparison;
}

uint32_t imageCoordinateOperand(const Instruction& inst) {
  return isImageSampleOrFetch(inst.opcode) ? inst.operand(1) : 0;
}

}  // namespace stereoshift::spirv
