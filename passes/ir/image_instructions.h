// The one list of image instructions the IR knows: which read texels at a coordinate, which
// compare against a depth reference instead, and where their optional image-operands mask sits.
// Passes ask it instead of keeping their own opcode lists (which used to disagree).
#pragma once

#include "passes/ir/module.h"

#include <optional>

namespace stereoshift::spirv {

// An image instruction that addresses an image at a coordinate (always operand word 1, after the
// image or sampled image at word 0).
struct ImageAccess {
  bool readsTexels = false;      // sample, fetch, gather, read and their sparse forms
  bool depthComparison = false;  // the Dref forms: the result compares texels with a reference
  int imageOperandsMask = -1;    // operand word of the optional image-operands mask; -1: none
};

// What `op` does with an image; nullopt for anything that is not an image access at a coordinate.
std::optional<ImageAccess> imageAccess(spv::Op op);

// Every instruction that reads an image at a coordinate: samples (implicit and explicit lod,
// projective, depth comparison), fetches, gathers, storage-image reads, sparse forms included.
bool isImageSampleOrFetch(spv::Op op);

// The same, without the depth comparisons: the result is texel data.
bool isTexelRead(spv::Op op);

// The coordinate an image read addresses; 0 when `inst` is not one (see isImageSampleOrFetch).
uint32_t imageCoordinateOperand(const Instruction& inst);

}  // namespace stereoshift::spirv
