// A deliberately small, editable SPIR-V module representation for instrumentation passes.
//
// Debian ships only SPIRV-Tools' public API, not its internal opt IR, so stereoshift carries its
// own: words are split into the logical-layout sections of the SPIR-V spec (2.4), functions into
// blocks, blocks into instructions. Passes add instructions, types and constants; nothing here tries
// to be an optimizer. Validation is SPIRV-Tools' job (see pipeline.cpp).
#pragma once

#define SPV_ENABLE_UTILITY_CODE
#include <glslang/SPIRV/spirv.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

// disassemble() / assemble() used to live here; callers that include module.h keep them.
#include "passes/ir/disassemble.h"

namespace stereoshift::spirv {

// One instruction. `operands` holds every word after the (optional) result type and result id.
struct Instruction {
  spv::Op opcode = spv::OpNop;
  uint32_t typeId = 0;    // 0 when the opcode has no result type
  uint32_t resultId = 0;  // 0 when the opcode has no result id
  std::vector<uint32_t> operands;

  Instruction() = default;
  Instruction(spv::Op op, uint32_t type, uint32_t result, std::vector<uint32_t> ops = {})
      : opcode(op), typeId(type), resultId(result), operands(std::move(ops)) {}

  uint32_t operand(size_t i) const { return i < operands.size() ? operands[i] : 0; }
  // A literal string starting at operand index `first` (null-terminated, packed little-endian).
  std::string stringOperand(size_t first) const;
  // Number of operand words used by the literal string starting at `first`.
  size_t stringWordCount(size_t first) const;
  void appendTo(std::vector<uint32_t>& words) const;
};

// Encodes a string as SPIR-V literal words (null-terminated, zero padded).
std::vector<uint32_t> encodeString(std::string_view text);

struct Block {
  uint32_t labelId = 0;
  std::vector<Instruction> instructions;  // OpPhi .. terminator; the OpLabel itself is implied

  const Instruction* terminator() const { return instructions.empty() ? nullptr : &instructions.back(); }
  // The OpSelectionMerge / OpLoopMerge right before the terminator, if any.
  const Instruction* mergeInstruction() const;
};

struct Function {
  Instruction definition;            // OpFunction
  std::vector<Instruction> parameters;  // OpFunctionParameter
  std::vector<Block> blocks;
  uint32_t id() const { return definition.resultId; }
};

class Module {
 public:
  // Parses a binary module; on failure returns nullopt and sets *error.
  static std::optional<Module> parse(const std::vector<uint32_t>& words, std::string* error);
  std::vector<uint32_t> encode() const;

  // --- header ---
  uint32_t version = 0x00010000;
  uint32_t generator = 0;
  uint32_t schema = 0;

  // --- sections, in logical-layout order ---
  std::vector<Instruction> capabilities;
  std::vector<Instruction> extensions;
  std::vector<Instruction> extInstImports;
  std::vector<Instruction> memoryModel;
  std::vector<Instruction> entryPoints;
  std::vector<Instruction> executionModes;
  std::vector<Instruction> debugSource;     // OpString, OpSource*, OpSourceExtension
  std::vector<Instruction> debugNames;      // OpName, OpMemberName
  std::vector<Instruction> debugModuleProcessed;
  std::vector<Instruction> annotations;     // OpDecorate, OpMemberDecorate, groups, ...
  std::vector<Instruction> typesValues;     // types, constants, global variables, OpUndef, OpLine
  std::vector<Function> functions;

  // --- ids ---
  uint32_t bound() const { return bound_; }
  uint32_t takeId() { return bound_++; }

  // Definition of an id among global instructions and function bodies (rebuilt lazily after edits).
  const Instruction* definition(uint32_t id) const;
  // The value of a 32-bit float OpConstant; nullopt for anything else.
  std::optional<float> floatConstant(uint32_t id) const;
  // The variable a pointer points into, through access chains; 0 when it is not one.
  uint32_t rootVariable(uint32_t pointer) const;
  void invalidateDefinitions() { defsValid_ = false; }

  // --- names ---
  std::string name(uint32_t id) const;
  std::string memberName(uint32_t structId, uint32_t member) const;
  void setName(uint32_t id, std::string_view text);
  void setMemberName(uint32_t structId, uint32_t member, std::string_view text);
  // Every OpName / OpMemberName string in the module (for clash checks).
  std::vector<std::string> allNames() const;

  // --- decorations ---
  bool hasDecoration(uint32_t id, spv::Decoration decoration) const;
  std::optional<uint32_t> decorationValue(uint32_t id, spv::Decoration decoration) const;
  bool hasMemberDecoration(uint32_t structId, uint32_t member, spv::Decoration decoration) const;
  std::optional<uint32_t> memberDecorationValue(uint32_t structId, uint32_t member,
                                                spv::Decoration decoration) const;
  void decorate(uint32_t id, spv::Decoration decoration, std::vector<uint32_t> literals = {});
  void decorateMember(uint32_t structId, uint32_t member, spv::Decoration decoration,
                      std::vector<uint32_t> literals = {});
  void removeDecorations(uint32_t id, spv::Decoration decoration);
  // OpDecorateString (SPV_GOOGLE_decorate_string): `id` decorated with a string literal.
  void decorateString(uint32_t id, spv::Decoration decoration, std::string_view text);
  // OpExtension `name`, unless the module declares it already.
  void addExtension(std::string_view name);
  // Drops the OpName / OpMemberName and the decorations whose target is one of `ids` (ids that are
  // going away: removed variables, the values of removed functions).
  void forgetIds(const std::set<uint32_t>& ids);

  // --- find-or-create types and constants (never duplicates a type the module has) ---
  uint32_t typeBool();
  uint32_t typeInt(uint32_t width, bool isSigned);
  uint32_t typeFloat(uint32_t width);
  uint32_t typeVector(uint32_t componentType, uint32_t count);
  uint32_t typePointer(spv::StorageClass storage, uint32_t pointee);
  uint32_t typeArray(uint32_t elementType, uint32_t length);  // length: a literal, stored as a uint constant
  uint32_t newStruct(const std::vector<uint32_t>& memberTypes);  // structs are always distinct
  // A new array type of `lengthId` elements (a constant's id), distinct from any other (for a type
  // that gets decorations of its own, an ArrayStride).
  uint32_t newArrayType(uint32_t elementType, uint32_t lengthId);
  uint32_t constantNull(uint32_t type);  // find-or-create
  uint32_t constantFloat(float value);
  uint32_t constantInt(int32_t value);
  uint32_t specConstantFloat(float value);  // a new OpSpecConstant each call
  uint32_t extInstImport(std::string_view setName);  // find-or-create, e.g. "GLSL.std.450"

  // Adds a global variable; interface variables are also appended to every entry point whose
  // SPIR-V version needs them (>= 1.4 lists all globals, older versions only Input/Output).
  uint32_t addGlobalVariable(uint32_t pointerType, spv::StorageClass storage);

  // --- capabilities / entry points ---
  bool hasCapability(spv::Capability capability) const;
  void addCapability(spv::Capability capability);
  // OpExecutionMode of the entry point's function.
  void addExecutionMode(spv::ExecutionMode mode, std::vector<uint32_t> literals = {});
  spv::ExecutionModel executionModel() const;  // of the first entry point
  std::string entryPointName() const;
  uint32_t entryFunctionId() const;
  std::vector<uint32_t> entryInterface() const;  // interface ids of the first entry point
  Function* function(uint32_t id);
  const Function* function(uint32_t id) const;

  // Images, samplers, sampled images, acceleration structures, and arrays of them: the types an
  // OpenGL shader may declare as a plain `uniform` that are not default-block data.
  bool isOpaqueType(uint32_t type) const;

  // Storage class and pointee type of a pointer-typed id (variable, access chain).
  std::optional<spv::StorageClass> storageClassOf(uint32_t pointerId) const;
  uint32_t pointeeType(uint32_t pointerTypeId) const;

 private:
  uint32_t bound_ = 1;
  mutable bool defsValid_ = false;
  mutable std::unordered_map<uint32_t, const Instruction*> defs_;
  void rebuildDefinitions() const;
  uint32_t findType(spv::Op op, const std::vector<uint32_t>& operands) const;
  uint32_t findConstant(uint32_t type, spv::Op op, const std::vector<uint32_t>& operands) const;
  uint32_t scalarConstant(uint32_t type, uint32_t bits);  // find-or-create a 32-bit OpConstant
};

// Whether operand word k of an instruction in a function body may hold a value id (literals such
// as extract indices, shuffle components, memory and image operand masks never do). Labels are
// reported as ids or not at will: they are never a value being traced or replaced.
bool isValueOperand(const Instruction& inst, size_t k);

// Locations one value of `type` takes in a shader interface: a matrix one per column, an array one
// per element, a struct the sum of its members, a 64-bit three- or four-component vector two.
uint32_t interfaceLocationCount(const Module& m, uint32_t type);

}  // namespace stereoshift::spirv
