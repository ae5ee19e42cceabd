// replaceAllUses: value operands change, literal operands that happen to hold the same number, result
// ids and global references (names, decorations, interfaces) do not.
#include "passes/ir/def_use.h"
#include "passes/ir/module.h"
#include "passes/ir/replace_uses.h"
#include "test/unit/spirv_text.h"

#include <gtest/gtest.h>

using namespace stereoshift::spirv;

namespace {

// %2 is used as a value four times, and the number 2 also appears as literals: extract indices,
// a shuffle component and the image-operands mask of an explicit-lod sample (Lod = 0x2).
const char* kFragment = R"(
               OpCapability Shader
          %1 = OpExtInstImport "GLSL.std.450"
               OpMemoryModel Logical GLSL450
               OpEntryPoint Fragment %4 "main" %10 %11
               OpExecutionMode %4 OriginUpperLeft
               OpName %2 "value"
               OpDecorate %2 RelaxedPrecision
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
          %4 = OpFunction %3 None %5
         %18 = OpLabel
          %2 = OpLoad %7 %10
         %19 = OpFAdd %7 %2 %2
         %20 = OpCompositeExtract %6 %19 2
         %21 = OpVectorShuffle %17 %2 %19 2 5
         %22 = OpLoad %15 %13
         %23 = OpImageSampleExplicitLod %7 %22 %21 Lod %20
         %24 = OpCompositeExtract %6 %2 2
         %25 = OpVectorTimesScalar %7 %23 %24
               OpStore %11 %25
               OpReturn
               OpFunctionEnd
)";

using stereoshift::spirv::test::parseOrDie;

const Instruction& defining(const Module& m, uint32_t id) {
  const Instruction* def = m.definition(id);
  EXPECT_NE(def, nullptr) << "%" << id;
  return *def;
}

TEST(ReplaceAllUses, ReplacesValueOperandsOnly) {
  Module m = parseOrDie(kFragment);
  const uint32_t replacement = m.takeId();
  EXPECT_EQ(replaceAllUses(m, 2, replacement), 4u);

  EXPECT_EQ(defining(m, 19).operands, (std::vector<uint32_t>{replacement, replacement}));
  EXPECT_EQ(defining(m, 20).operands, (std::vector<uint32_t>{19, 2}));                    // index literal
  EXPECT_EQ(defining(m, 21).operands, (std::vector<uint32_t>{replacement, 19, 2, 5}));   // component literal
  EXPECT_EQ(defining(m, 23).operands, (std::vector<uint32_t>{22, 21, 2, 20}));            // Lod mask literal
  EXPECT_EQ(defining(m, 24).operands, (std::vector<uint32_t>{replacement, 2}));

  // The definition keeps its id; names, decorations and the interface still refer to %2 / %10.
  EXPECT_EQ(defining(m, 2).opcode, spv::OpLoad);
  EXPECT_EQ(m.name(2), "value");
  EXPECT_TRUE(m.hasDecoration(2, spv::DecorationRelaxedPrecision));
  EXPECT_EQ(m.entryInterface(), (std::vector<uint32_t>{10, 11}));
}

TEST(ReplaceAllUses, LeavesNoUseBehindAndTouchesNothingElse) {
  Module m = parseOrDie(kFragment);
  const uint32_t replacement = m.takeId();
  Module before = m;
  replaceAllUses(m, 2, replacement);
  DefUse defUse(m);
  EXPECT_TRUE(defUse.uses(2).empty());
  EXPECT_EQ(defUse.uses(replacement).size(), 4u);
  // Every other word of the module is as it was: putting %2 back restores it exactly.
  EXPECT_EQ(replaceAllUses(m, replacement, 2), 4u);
  EXPECT_EQ(m.encode(), before.encode());
}

TEST(ReplaceAllUses, ImageOperandsAfterTheMaskAreValues) {
  Module m = parseOrDie(kFragment);
  const uint32_t replacement = m.takeId();
  EXPECT_EQ(replaceAllUses(m, 20, replacement), 1u);  // the Lod value, after the mask
  EXPECT_EQ(defining(m, 23).operands, (std::vector<uint32_t>{22, 21, 2, replacement}));
}

TEST(ReplaceAllUses, UnusedIdChangesNothing) {
  Module m = parseOrDie(kFragment);
  auto words = m.encode();
  EXPECT_EQ(replaceAllUses(m, 25 + 100, 3), 0u);
  EXPECT_EQ(m.encode(), words);
}

}  // namespace
