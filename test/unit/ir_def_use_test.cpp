// DefUse: the definition of every id and the exact (instruction, operand) uses of function bodies;
// literals, result types and global references are not uses.
#include "passes/ir/def_use.h"
#include "passes/ir/module.h"
#include "test/unit/spirv_text.h"

#include <gtest/gtest.h>

using namespace stereoshift::spirv;

namespace {

const char* kFragment = R"(
               OpCapability Shader
          %1 = OpExtInstImport "GLSL.std.450"
               OpMemoryModel Logical GLSL450
               OpEntryPoint Fragment %4 "main" %10 %11
               OpExecutionMode %4 OriginUpperLeft
               OpName %2 "value"
               OpDecorate %10 Location 0
               OpDecorate %11 Location 0
               OpDecorate %13 DescriptorSet 0
               OpDecorate %13 Binding 0
          %3 = OpTypeVoid
          %5 = OpTypeFunction %3
          %6 = OpTypeFloat 32
          %7 = OpTypeVector %6 4
          %8 = OpTypePointer Input %7
          %9 = OpTypePointer Output %7
         %10 = OpVariable %8 Input
         %11 = OpVariable %9 Output
         %14 = OpTypeImage %6 2D 0 0 0 1 Unknown
         %15 = OpTypeSampledImage %14
         %16 = OpTypePointer UniformConstant %15
         %13 = OpVariable %16 UniformConstant
         %17 = OpTypeVector %6 2
         %30 = OpTypeFunction %6 %6
          %4 = OpFunction %3 None %5
         %18 = OpLabel
          %2 = OpLoad %7 %10
         %19 = OpFAdd %7 %2 %2
         %20 = OpCompositeExtract %6 %19 2
         %21 = OpVectorShuffle %17 %2 %19 2 5
         %22 = OpLoad %15 %13
         %23 = OpImageSampleExplicitLod %7 %22 %21 Lod %20
         %24 = OpFunctionCall %6 %31 %20
         %25 = OpVectorTimesScalar %7 %23 %24
               OpStore %11 %25
               OpReturn
               OpFunctionEnd
         %31 = OpFunction %6 None %30
         %32 = OpFunctionParameter %6
         %33 = OpLabel
         %34 = OpFMul %6 %32 %32
               OpReturnValue %34
               OpFunctionEnd
)";

using stereoshift::spirv::test::parseOrDie;

// A use as (user's result id or opcode, operand index), for readable comparisons.
struct Seen {
  uint32_t user;  // result id, or the opcode for instructions without one
  size_t operand;
  bool operator==(const Seen&) const = default;
};

std::vector<Seen> seen(const DefUse& defUse, uint32_t id) {
  std::vector<Seen> out;
  for (const Use& use : defUse.uses(id))
    out.push_back({use.user->resultId ? use.user->resultId : uint32_t(use.user->opcode), use.operand});
  return out;
}

std::ostream& operator<<(std::ostream& os, const Seen& s) { return os << "(" << s.user << ", " << s.operand << ")"; }

TEST(DefUse, DefinitionsOfEverySection) {
  Module m = parseOrDie(kFragment);
  DefUse defUse(m);
  EXPECT_EQ(defUse.definition(1)->opcode, spv::OpExtInstImport);
  EXPECT_EQ(defUse.definition(7)->opcode, spv::OpTypeVector);
  EXPECT_EQ(defUse.definition(10)->opcode, spv::OpVariable);
  EXPECT_EQ(defUse.definition(4), &m.functions[0].definition);
  EXPECT_EQ(defUse.definition(32), &m.functions[1].parameters[0]);
  EXPECT_EQ(defUse.definition(2), &m.functions[0].blocks[0].instructions[0]);
  EXPECT_EQ(defUse.definition(18), nullptr);  // a label: the IR keeps it as Block::labelId
  EXPECT_EQ(defUse.definition(999), nullptr);
  EXPECT_EQ(defUse.definingFunction(2), &m.functions[0]);
  EXPECT_EQ(defUse.definingFunction(32), &m.functions[1]);
  EXPECT_EQ(defUse.definingFunction(10), nullptr);
}

TEST(DefUse, ExactUsesInEncodingOrder) {
  Module m = parseOrDie(kFragment);
  DefUse defUse(m);
  EXPECT_EQ(seen(defUse, 2), (std::vector<Seen>{{19, 0}, {19, 1}, {21, 0}}));
  EXPECT_EQ(seen(defUse, 19), (std::vector<Seen>{{20, 0}, {21, 1}}));
  // The Lod value follows the image-operands mask (operand 2); the call passes it as argument 1.
  EXPECT_EQ(seen(defUse, 20), (std::vector<Seen>{{23, 3}, {24, 1}}));
  EXPECT_EQ(seen(defUse, 31), (std::vector<Seen>{{24, 0}}));  // the function called
  EXPECT_EQ(seen(defUse, 32), (std::vector<Seen>{{34, 0}, {34, 1}}));
  EXPECT_EQ(seen(defUse, 34), (std::vector<Seen>{{uint32_t(spv::OpReturnValue), 0}}));
  EXPECT_EQ(seen(defUse, 11), (std::vector<Seen>{{uint32_t(spv::OpStore), 0}}));
  EXPECT_EQ(seen(defUse, 25), (std::vector<Seen>{{uint32_t(spv::OpStore), 1}}));
  // The uses carry where they are.
  const Use& store = defUse.uses(25).front();
  EXPECT_EQ(store.function, &m.functions[0]);
  EXPECT_EQ(store.block, &m.functions[0].blocks[0]);
  EXPECT_EQ(store.user, &m.functions[0].blocks[0].instructions.back() - 1);  // the OpStore before OpReturn
}

TEST(DefUse, LiteralsTypesAndGlobalReferencesAreNotUses) {
  Module m = parseOrDie(kFragment);
  DefUse defUse(m);
  // %10 is named by decorations and the entry point, loaded once: one use.
  EXPECT_EQ(seen(defUse, 10), (std::vector<Seen>{{2, 0}}));
  // %6 (float) is a result type and a type operand only; 5 appears only as a shuffle literal;
  // the mask literal 2 of the sample is not a use of %2 (its three uses are listed above).
  EXPECT_TRUE(defUse.uses(6).empty());
  EXPECT_TRUE(defUse.uses(5).empty());
  EXPECT_EQ(defUse.uses(2).size(), 3u);
  EXPECT_TRUE(defUse.uses(999).empty());
}

TEST(DefUse, UsersAreDistinct) {
  Module m = parseOrDie(kFragment);
  DefUse defUse(m);
  auto users = defUse.users(2);
  ASSERT_EQ(users.size(), 2u);
  EXPECT_EQ(users[0]->resultId, 19u);
  EXPECT_EQ(users[1]->resultId, 21u);
}

}  // namespace
