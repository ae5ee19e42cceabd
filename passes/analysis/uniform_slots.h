// Uniform slots: a uniform value named by where it lives, a Uniform / PushConstant /
// UniformConstant variable and the constant member indices of the access chain to it. Global
// variable ids are shared between a module and its folded copy, so a slot found in one names the
// same value in the other. per-eye-view names camera positions and the matrices next to them this
// way; the next-stage facts name what a stage passes on.
#pragma once

#include "passes/ir/module.h"

#include <glslang/SPIRV/GLSL.std.450.h>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace stereoshift::analysis {

// `inverseTranslation`: the slot is a mat4 (a view matrix) and the value meant is the translation
// column of its inverse, `inverse(view)[3]`: the camera position of a shader that has no uniform
// for it.
struct Slot {
  uint32_t variable = 0;
  std::vector<uint32_t> indices;
  bool inverseTranslation = false;
  bool operator<(const Slot& o) const {
    return std::tie(variable, indices, inverseTranslation) < std::tie(o.variable, o.indices, o.inverseTranslation);
  }
  bool operator==(const Slot& o) const {
    return variable == o.variable && indices == o.indices && inverseTranslation == o.inverseTranslation;
  }
};

// The value of an OpConstant (32-bit), nullopt for anything else.
std::optional<uint32_t> constantValue(const spirv::Module& m, uint32_t id);
bool isUniformStorage(spv::StorageClass s);
bool isMat4(const spirv::Module& m, uint32_t type);
// A GLSL.std.450 instruction among `which`.
bool isGlslExtInst(const spirv::Module& m, const spirv::Instruction& inst, std::initializer_list<GLSLstd450> which);

// The slot a pointer addresses (constant indices only), if it addresses one.
std::optional<Slot> slotOfPointer(const spirv::Module& m, uint32_t pointer);
// The slot an OpLoad reads, if it reads one.
std::optional<Slot> loadedSlot(const spirv::Module& m, uint32_t value);
// The slot a value reads: a load of it, a member of a whole-struct load (`Camera c = camera;
// c.position`), or the translation column of the inverse of a loaded matrix (`inverse(view)[3]`).
std::optional<Slot> valueSlot(const spirv::Module& m, uint32_t value);
// A value that is a float vec3/vec4 slot (or the .xyz of one): a camera position candidate.
std::optional<Slot> cameraSide(const spirv::Module& m, uint32_t value);

// Type of the value a slot holds.
uint32_t slotType(const spirv::Module& m, const Slot& slot);
// "instance.member" (block type name when the instance is unnamed, as in HLSL cbuffers), or the
// loose uniform's name. Array and vector indices are written as [i].
std::string slotName(const spirv::Module& m, const Slot& slot);
// The slot as GLSL source reads it: `viewPos`, `ubo.camPos`, `camPos` (a member of an anonymous
// block), `cam.pos` (a uniform struct); none for an array element, the translation column of an
// inverse, or a name the front end made (`gl_`, `stereoshift_`).
std::optional<std::string> slotSourceAccess(const spirv::Module& m, const Slot& slot);
// The innermost name of a slot: the member name, or the loose uniform's name.
std::string slotLeafName(const spirv::Module& m, const Slot& slot);
// Whether `wanted` (--camera-uniform) names the slot: its full name, its leaf or "Block.member".
bool slotMatchesName(const spirv::Module& m, const Slot& slot, const std::string& wanted);

}  // namespace stereoshift::analysis
