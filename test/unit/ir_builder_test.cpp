// The instruction builder (passes/ir/builder.h): ids in the order of the calls, reserved ids that
// number before what an instruction's operands still create, the definition index kept right when
// the cursor is inside the module, and splitBlock moving the tail and the successors' phis.
#include "passes/ir/builder.h"
#include "passes/ir/module.h"
#include "test/unit/spirv_text.h"

#include <gtest/gtest.h>

using namespace stereoshift::spirv;

namespace {

// A loop whose header %20 is its own latch: its phi names %20 as a predecessor.
const char* kLoop = R"(
               OpCapability Shader
               OpMemoryModel Logical GLSL450
               OpEntryPoint Vertex %4 "main" %10
               OpDecorate %10 BuiltIn Position
          %3 = OpTypeVoid
          %5 = OpTypeFunction %3
          %6 = OpTypeFloat 32
          %7 = OpTypeVector %6 4
          %8 = OpTypePointer Output %7
         %10 = OpVariable %8 Output
         %11 = OpConstant %6 0
         %12 = OpConstant %6 1
         %13 = OpTypeBool
          %4 = OpFunction %3 None %5
         %18 = OpLabel
               OpBranch %20
         %20 = OpLabel
         %21 = OpPhi %6 %11 %18 %22 %20
         %22 = OpFAdd %6 %21 %12
         %23 = OpFOrdLessThan %13 %22 %12
               OpLoopMerge %30 %20 None
               OpBranchConditional %23 %20 %30
         %30 = OpLabel
         %31 = OpCompositeConstruct %7 %22 %22 %22 %12
               OpStore %10 %31
               OpReturn
               OpFunctionEnd
)";

using stereoshift::spirv::test::parseOrDie;

TEST(IrBuilder, IdsFollowTheCallsAndAReservedIdNumbersFirst) {
  Module m = parseOrDie(kLoop);
  const uint32_t bound = m.bound();
  std::vector<Instruction> code;
  Builder b(m, code);
  uint32_t loaded = b.load(7, 10);
  uint32_t reserved = b.reserveId();
  uint32_t two = m.constantFloat(2.0f);  // created after the reservation: numbers after it
  b.addAs(reserved, spv::OpVectorTimesScalar, 7, {loaded, two});
  b.store(10, reserved);
  EXPECT_EQ(loaded, bound);
  EXPECT_EQ(reserved, bound + 1);
  EXPECT_EQ(two, bound + 2);
  ASSERT_EQ(code.size(), 3u);
  EXPECT_EQ(code[0].opcode, spv::OpLoad);
  EXPECT_EQ(code[1].resultId, reserved);
  EXPECT_EQ(code[1].operands, (std::vector<uint32_t>{loaded, two}));
  EXPECT_EQ(code[2].opcode, spv::OpStore);
  EXPECT_EQ(code[2].resultId, 0u);
  EXPECT_EQ(code[2].typeId, 0u);
}

TEST(IrBuilder, InsideTheModuleEveryAdditionIsDefined) {
  Module m = parseOrDie(kLoop);
  ASSERT_NE(m.definition(31), nullptr);  // the index is built
  auto& exit = m.functions[0].blocks[2].instructions;
  Instruction store = exit.back();  // OpReturn comes last: build before it
  exit.pop_back();
  Builder b(m, exit, true);
  uint32_t x = b.extract(6, 31, 0);
  exit.push_back(store);
  const Instruction* def = m.definition(x);
  ASSERT_NE(def, nullptr);
  EXPECT_EQ(def->opcode, spv::OpCompositeExtract);
}

TEST(IrBuilder, SplitBlockMovesTheTailAndTheSuccessorsPhis) {
  Module m = parseOrDie(kLoop);
  Function& fn = m.functions[0];
  const uint32_t restLabel = m.takeId();
  // Split the loop header after its add: the back edge now comes from the new block.
  size_t rest = splitBlock(m, fn, 1, 2, restLabel);
  ASSERT_EQ(rest, 2u);
  ASSERT_EQ(fn.blocks.size(), 4u);
  EXPECT_EQ(fn.blocks[1].labelId, 20u);
  EXPECT_EQ(fn.blocks[1].instructions.size(), 2u);  // the phi and the add stay
  EXPECT_EQ(fn.blocks[2].labelId, restLabel);
  EXPECT_EQ(fn.blocks[2].instructions.front().opcode, spv::OpFOrdLessThan);
  const Instruction& phi = fn.blocks[1].instructions.front();
  EXPECT_EQ(phi.operands, (std::vector<uint32_t>{11, 18, 22, restLabel}));
  // The moved instructions are found where they are now (the index was marked stale).
  const Instruction* moved = m.definition(23);
  ASSERT_NE(moved, nullptr);
  EXPECT_EQ(moved, &fn.blocks[2].instructions.front());
}

}  // namespace
