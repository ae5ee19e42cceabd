// Harness-only instrumentation: turns a copy of a shader's last pre-rasterization stage into one
// that writes every output through transform feedback (ExecutionMode Xfb, XfbBuffer 0, Offsets),
// so the harness can read back each output of each vertex. The shader's own code is not touched.
#pragma once

#include "core/result.h"
#include "passes/ir/module.h"

#include <string>
#include <vector>

namespace stereoshift::harness {

struct CapturedField {
  std::string name;       // output variable name (or "gl_Position")
  uint32_t location = 0;  // interface location, UINT32_MAX for the position
  uint32_t offset = 0;    // byte offset inside one captured vertex
  uint32_t components = 0;
  bool isPosition = false;
  bool isFloat = true;
};

struct CaptureLayout {
  std::vector<CapturedField> fields;
  uint32_t stride = 0;
  const CapturedField* position() const;
};

// Adds the transform-feedback decorations. The position is always the first field (offset 0);
// other outputs follow in location order. Outputs that are not 32-bit scalars or vectors (matrices,
// arrays, structs) are not captured and are listed in `skipped`. Returns where each captured
// field is; the error when the module has no entry point or writes no position.
Result<CaptureLayout> instrumentForCapture(spirv::Module& module, std::vector<std::string>* skipped = nullptr);

// OpenGL SPIR-V (ARB_gl_spirv) cannot run on Vulkan as is: its loose uniforms become members of one
// std140 uniform block (set 0, binding `blockBinding` — one per stage of a pipeline, since each stage
// has its own default block —, members in declaration order, so an original and its transpiled
// copy share the layout of their common prefix; a `uniform bool` stored as a uint whose loads
// compare it with 0, since SPIR-V has no bool in memory), gl_VertexID /
// gl_InstanceID become VertexIndex / InstanceIndex, and uniform Locations are dropped. Returns true
// when the module needed (and got) the conversion.
bool convertOpenGLForVulkan(spirv::Module& module, uint32_t blockBinding, std::string* error);

}  // namespace stereoshift::harness
