// The instruction walkers: visiting order (the module's encoding order), the enclosing function and
// block they report, editing through the mutable walk, and stopping at the first match.
#include "passes/ir/module.h"
#include "passes/ir/walker.h"
#include "test/unit/spirv_text.h"

#include <gtest/gtest.h>

#include <tuple>

using namespace stereoshift::spirv;

namespace {

// Two functions; the first has three blocks, the second a parameter.
const char* kTwoFunctions = R"(
               OpCapability Shader
               OpMemoryModel Logical GLSL450
               OpEntryPoint Vertex %1 "main"
               OpName %1 "main"
          %2 = OpTypeVoid
          %3 = OpTypeFunction %2
          %4 = OpTypeFloat 32
          %5 = OpTypeFunction %4 %4
          %6 = OpConstant %4 1
          %7 = OpTypeBool
          %8 = OpConstantTrue %7
          %1 = OpFunction %2 None %3
         %10 = OpLabel
         %11 = OpFunctionCall %4 %20 %6
               OpSelectionMerge %13 None
               OpBranchConditional %8 %12 %13
         %12 = OpLabel
         %14 = OpFAdd %4 %11 %6
               OpBranch %13
         %13 = OpLabel
               OpReturn
               OpFunctionEnd
         %20 = OpFunction %4 None %5
         %21 = OpFunctionParameter %4
         %22 = OpLabel
         %23 = OpFMul %4 %21 %21
               OpReturnValue %23
               OpFunctionEnd
)";

using stereoshift::spirv::test::parseOrDie;

using Visit = std::tuple<uint32_t, uint32_t, spv::Op, uint32_t>;  // function, block label, opcode, result

TEST(Walker, FunctionBodiesInLayoutOrderWithTheirFunctionAndBlock) {
  const Module m = parseOrDie(kTwoFunctions);
  std::vector<Visit> visits;
  forEachFunctionInstruction(m, [&](const Instruction& inst, const Function& fn, const Block& block) {
    visits.emplace_back(fn.id(), block.labelId, inst.opcode, inst.resultId);
  });
  std::vector<Visit> expected = {
      {1, 10, spv::OpFunctionCall, 11}, {1, 10, spv::OpSelectionMerge, 0}, {1, 10, spv::OpBranchConditional, 0},
      {1, 12, spv::OpFAdd, 14},         {1, 12, spv::OpBranch, 0},         {1, 13, spv::OpReturn, 0},
      {20, 22, spv::OpFMul, 23},        {20, 22, spv::OpReturnValue, 0},
  };
  EXPECT_EQ(visits, expected);
}

TEST(Walker, WholeModuleInEncodingOrder) {
  const Module m = parseOrDie(kTwoFunctions);
  // The opcodes as the binary has them, less what the IR implies (labels, function ends).
  std::vector<spv::Op> encoded;
  auto words = m.encode();
  for (size_t at = 5; at < words.size(); at += words[at] >> 16) {
    auto op = static_cast<spv::Op>(words[at] & 0xffff);
    if (op != spv::OpLabel && op != spv::OpFunctionEnd) encoded.push_back(op);
  }
  std::vector<spv::Op> walked;
  int globals = 0, headers = 0, body = 0;
  forEachInstruction(m, [&](const Instruction& inst, const Function* fn, const Block* block) {
    walked.push_back(inst.opcode);
    if (!fn) {
      EXPECT_EQ(block, nullptr);
      ++globals;
    } else if (!block) {
      EXPECT_TRUE(inst.opcode == spv::OpFunction || inst.opcode == spv::OpFunctionParameter);
      EXPECT_TRUE(&inst == &fn->definition || &inst == &fn->parameters[0]);
      ++headers;
    } else {
      ++body;
    }
  });
  EXPECT_EQ(walked, encoded);
  EXPECT_EQ(globals, 11);  // capability, memory model, entry point, name, 7 types and constants
  EXPECT_EQ(headers, 3);   // two OpFunction, one parameter
  EXPECT_EQ(body, 8);
}

TEST(Walker, MutableWalkEditsTheModule) {
  Module m = parseOrDie(kTwoFunctions);
  forEachFunctionInstruction(m, [](Instruction& inst, Function&, Block&) {
    if (inst.opcode == spv::OpFMul) inst.opcode = spv::OpFAdd;
  });
  int adds = 0;
  forEachInstruction(m, [&](Instruction& inst, Function*, Block*) { adds += inst.opcode == spv::OpFAdd; });
  EXPECT_EQ(adds, 2);
  std::string error;
  auto reparsed = Module::parse(m.encode(), &error);
  ASSERT_TRUE(reparsed) << error;
  EXPECT_EQ(reparsed->functions[1].blocks[0].instructions[0].opcode, spv::OpFAdd);
}

TEST(Walker, AnyStopsAtTheFirstMatch) {
  const Module m = parseOrDie(kTwoFunctions);
  int visited = 0;
  bool found = anyFunctionInstruction(m, [&](const Instruction& inst, const Function&, const Block& block) {
    ++visited;
    return inst.opcode == spv::OpFAdd && block.labelId == 12;
  });
  EXPECT_TRUE(found);
  EXPECT_EQ(visited, 4);
  EXPECT_FALSE(anyFunctionInstruction(m, [](const Instruction& inst, const Function&, const Block&) {
    return inst.opcode == spv::OpFSub;
  }));
}

}  // namespace
