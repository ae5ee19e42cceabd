// The SPIR-V module IR: parse/encode round trips, find-or-create, decorations.
#include "passes/ir/module.h"
#include "test/unit/spirv_text.h"

#include <gtest/gtest.h>

using namespace stereoshift::spirv;

namespace {

const char* kVertex = R"(
               OpCapability Shader
          %1 = OpExtInstImport "GLSL.std.450"
               OpMemoryModel Logical GLSL450
               OpEntryPoint Vertex %main "main" %pos
               OpName %main "main"
               OpName %pos "pos"
               OpDecorate %pos BuiltIn Position
       %void = OpTypeVoid
          %3 = OpTypeFunction %void
      %float = OpTypeFloat 32
    %v4float = OpTypeVector %float 4
     %ptr_v4 = OpTypePointer Output %v4float
        %pos = OpVariable %ptr_v4 Output
     %float1 = OpConstant %float 1
        %vec = OpConstantComposite %v4float %float1 %float1 %float1 %float1
       %main = OpFunction %void None %3
          %5 = OpLabel
               OpStore %pos %vec
               OpReturn
               OpFunctionEnd
)";

using stereoshift::spirv::test::parseOrDie;

TEST(SpirvModule, RoundTripIsWordExact) {
  std::string error;
  auto words = assemble(kVertex, &error);
  ASSERT_FALSE(words.empty()) << error;
  auto m = Module::parse(words, &error);
  ASSERT_TRUE(m) << error;
  EXPECT_EQ(m->encode(), words);
}

TEST(SpirvModule, SectionsAndEntryPoint) {
  Module m = parseOrDie(kVertex);
  EXPECT_EQ(m.executionModel(), spv::ExecutionModelVertex);
  EXPECT_EQ(m.entryPointName(), "main");
  ASSERT_EQ(m.entryInterface().size(), 1u);
  uint32_t pos = m.entryInterface()[0];
  EXPECT_EQ(m.name(pos), "pos");
  EXPECT_EQ(m.decorationValue(pos, spv::DecorationBuiltIn), uint32_t(spv::BuiltInPosition));
  ASSERT_EQ(m.functions.size(), 1u);
  EXPECT_EQ(m.functions[0].blocks.size(), 1u);
  EXPECT_EQ(m.functions[0].blocks[0].terminator()->opcode, spv::OpReturn);
}

TEST(SpirvModule, FindOrCreateReusesExistingTypes) {
  Module m = parseOrDie(kVertex);
  uint32_t bound = m.bound();
  uint32_t f = m.typeFloat(32);
  EXPECT_EQ(m.typeVector(f, 4), m.pointeeType(m.definition(m.entryInterface()[0])->typeId));
  EXPECT_EQ(m.constantFloat(1.0f), m.constantFloat(1.0f));
  EXPECT_EQ(m.bound(), bound);  // nothing new: all existed
  uint32_t two = m.constantFloat(2.0f);
  EXPECT_EQ(m.bound(), bound + 1);
  EXPECT_EQ(m.constantFloat(2.0f), two);
  uint32_t i32 = m.typeInt(32, true);
  EXPECT_NE(i32, m.typeInt(32, false));
}

TEST(SpirvModule, EditedModuleStillValidates) {
  Module m = parseOrDie(kVertex);
  uint32_t f = m.typeFloat(32);
  uint32_t block = m.newStruct({f, f, f});
  m.decorate(block, spv::DecorationBlock);
  for (uint32_t i = 0; i < 3; ++i) m.decorateMember(block, i, spv::DecorationOffset, {4 * i});
  uint32_t var = m.addGlobalVariable(m.typePointer(spv::StorageClassUniform, block), spv::StorageClassUniform);
  m.decorate(var, spv::DecorationDescriptorSet, {0});
  m.decorate(var, spv::DecorationBinding, {3});
  m.setName(var, "stereo");
  m.setMemberName(block, 0, "eyeSign");
  EXPECT_EQ(m.name(var), "stereo");
  EXPECT_EQ(m.memberName(block, 0), "eyeSign");
  std::string text = disassemble(m.encode());
  EXPECT_NE(text.find("OpMemberName %_struct_"), std::string::npos) << text;
  std::string error;
  EXPECT_FALSE(assemble(text, &error).empty()) << error;
}

TEST(SpirvModule, RejectsGarbage) {
  std::string error;
  EXPECT_FALSE(Module::parse({1, 2, 3}, &error));
  EXPECT_NE(error.find("header"), std::string::npos);
  EXPECT_FALSE(Module::parse({0x07230203, 0x10000, 0, 10, 0, 0xFFFF0011}, &error));
  EXPECT_NE(error.find("overruns"), std::string::npos);
}

TEST(SpirvModule, StringsRoundTrip) {
  auto words = encodeString("abcd");
  EXPECT_EQ(words.size(), 2u);  // 4 chars + terminator word
  Instruction name(spv::OpName, 0, 0, {7});
  name.operands.insert(name.operands.end(), words.begin(), words.end());
  EXPECT_EQ(name.stringOperand(1), "abcd");
}

}  // namespace
