// The halos of assembly vertex shaders (transpiler/d3dasm/asm_halo.h): which output lanes move with
// the position's x, and, by execution on the assembly interpreter, that the converted text moves
// them by exactly that (the copy bit for bit with the shifted x, the others within the bound
// asm_verify.cpp derives), with and without the position's own shift.
#include "transpiler/d3dasm/asm_halo.h"
#include "transpiler/d3dasm/asm_interpreter.h"
#include "transpiler/d3dasm/asm_shift.h"
#include "transpiler/d3dasm/asm_text.h"
#include "transpiler/d3dasm/asm_verify.h"

#include <gtest/gtest.h>

#include <bit>
#include <memory>

namespace stereoshift::d3dasm {
namespace {

// Written here in fxc's row-major spelling (dp4 per row): an engine's screen position handed to the
// pixel shader as a copy of the clip position (o1), a grab-pass UV `(x + w) * 0.5` (o2.x; its y is
// flipped by a cbuffer sign and does not move), a lane of x times a cbuffer element and one of x
// over w (o3: not a constant times x, left as they are), with an early return for a flag.
const char* kScreenPositionsVs5 = R"(vs_5_0
dcl_globalFlags refactoringAllowed
dcl_constantbuffer cb0[7], immediateIndexed
dcl_input v0.xyzw
dcl_input v1.xy
dcl_output_siv o0.xyzw, position
dcl_output o1.xyzw
dcl_output o2.xyzw
dcl_output o3.xy
dcl_output o4.xy
dcl_temps 3
dp4 r0.x, v0.xyzw, cb0[0].xyzw
dp4 r0.y, v0.xyzw, cb0[1].xyzw
dp4 r0.z, v0.xyzw, cb0[2].xyzw
dp4 r0.w, v0.xyzw, cb0[3].xyzw
mov o0.xyzw, r0.xyzw
mov o1.xyzw, r0.xyzw
mul r1.y, r0.y, cb0[4].x
mov r1.xz, r0.xxwx
add r1.xy, r1.zzzz, r1.xyxx
mul o2.xy, r1.xyxx, l(0.500000, 0.500000, 0.000000, 0.000000)
mov o2.zw, r0.zzzw
mad o3.x, r0.x, cb0[5].x, cb0[5].y
div o3.y, r0.x, r0.w
mov o4.xy, v1.xyxx
lt r2.x, cb0[6].x, l(0.000000)
retc_nz r2.x
ret
)";

std::unique_ptr<Program> decoded(const std::string& text) {
  Result<AsmText> parsed = parseAssembly(text);
  EXPECT_TRUE(parsed.ok());
  AsmError error;
  auto program = parsed.ok() ? Program::decode(*parsed, &error, DecodeFor::Analysis) : nullptr;
  EXPECT_TRUE(program) << error.line << ": " << error.message;
  return program;
}

std::string replacedAll(std::string text, const std::string& from, const std::string& to) {
  EXPECT_NE(text.find(from), std::string::npos) << from;
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

TEST(AsmHalo, CopiesAndLanesLinearInXAreFoundAtEveryReturn) {
  auto program = decoded(kScreenPositionsVs5);
  ASSERT_TRUE(program);
  std::vector<AsmMovedLane> lanes = findAsmMovedLanes(*program);
  ASSERT_EQ(lanes.size(), 2u);
  EXPECT_EQ(lanes[0].reg, 1u);  // o1.x: the copy
  EXPECT_EQ(lanes[0].lane, 0u);
  EXPECT_TRUE(lanes[0].copy);
  EXPECT_EQ(lanes[1].reg, 2u);  // o2.x: (x + w) * 0.5
  EXPECT_EQ(lanes[1].lane, 0u);
  EXPECT_FALSE(lanes[1].copy);
  EXPECT_EQ(lanes[1].coefficient, 0.5f);
}

TEST(AsmHalo, ALaneThatMovesAtOneReturnOnlyIsNotTaken) {
  // After the early return o1.x is written again from the texture coordinate: at the final return it
  // does not move, and one block per return cannot tell them apart.
  std::string text = replacedAll(kScreenPositionsVs5, "retc_nz r2.x\nret\n", "retc_nz r2.x\nmov o1.x, v1.x\nret\n");
  auto program = decoded(text);
  ASSERT_TRUE(program);
  std::vector<AsmMovedLane> lanes = findAsmMovedLanes(*program);
  ASSERT_EQ(lanes.size(), 1u);
  EXPECT_EQ(lanes[0].reg, 2u);
}

TEST(AsmHalo, ALaneThroughAnInstructionNotLookedIntoIsNotTaken) {
  // x saturated, x through a movc, and x plus a value computed from x by rsq: none is a constant
  // times x plus something free of x.
  const std::string text = replacedAll(kScreenPositionsVs5, "mov o4.xy, v1.xyxx\n",
                                       "mov_sat o4.x, r0.x\nrsq r2.y, |r0.x|\nadd o4.y, r0.x, r2.y\n");
  auto program = decoded(text);
  ASSERT_TRUE(program);
  for (const AsmMovedLane& lane : findAsmMovedLanes(*program)) EXPECT_NE(lane.reg, 4u) << lane.lane;
}

AsmVerifyResult verified(const std::string& converted, const std::vector<AsmMovedLane>& lanes) {
  AsmVerifyOptions options;
  options.samples = 1024;
  options.movedLanes = lanes;
  return verifyAssemblyConversion(kScreenPositionsVs5, converted, options);
}

TEST(AsmHalo, TheMovedLanesFollowTheShiftByExecution) {
  AsmShiftResult shifted = shiftAssembly(kScreenPositionsVs5, {});
  ASSERT_TRUE(shifted.ok) << shifted.error.message;
  ASSERT_EQ(shifted.movedLanes.size(), 2u);
  EXPECT_EQ(shifted.sites, 2);  // the early return and the last one
  AsmVerifyResult r = verified(shifted.output, shifted.movedLanes);
  ASSERT_TRUE(r.ran) << r.error;
  EXPECT_TRUE(r.ok) << r.firstFailure;
  EXPECT_EQ(r.monoMismatches, 0);
  EXPECT_EQ(r.movedLaneRuns, 2 * 2 * 1024);
  EXPECT_EQ(r.movedLaneFailures, 0);
  EXPECT_GT(r.worstMovedLaneRatio, 0.0);
  EXPECT_LE(r.worstMovedLaneRatio, 1.0);
  // The lanes really move: held to the original's bits, the same output fails.
  AsmVerifyResult asIfUnmoved = verified(shifted.output, {});
  EXPECT_FALSE(asIfUnmoved.ok);
  EXPECT_GT(asIfUnmoved.otherOutputMismatches, 0);
  // The text before this change (the lanes written out unmoved) fails the moved-lane check.
  const std::string rS = shifted.scratchTemp;
  std::string unmoved = replacedAll(shifted.output, "movc o2.x, " + rS + ".x, " + rS + ".y, ", "movc o2.x, l(0), " + rS + ".y, ");
  unmoved = replacedAll(unmoved, "movc o1.x, " + rS + ".x, " + rS + ".w, ", "movc o1.x, l(0), " + rS + ".w, ");
  AsmVerifyResult before = verified(unmoved, shifted.movedLanes);
  EXPECT_FALSE(before.ok);
  EXPECT_GT(before.movedLaneFailures, 1000);
  // Undoing the marked edits gives the dump back.
  EXPECT_EQ(undoAssemblyEdits(shifted.output), kScreenPositionsVs5);
}

std::map<uint32_t, Vec4> run(const std::string& text, float separation, float convergence) {
  Result<AsmText> parsed = parseAssembly(text);
  AsmError error;
  auto program = Program::decode(*parsed, &error);
  EXPECT_TRUE(program) << error.line << ": " << error.message;
  if (!program) return {};
  Machine machine;
  machine.inputs[0] = {std::bit_cast<uint32_t>(0.75f), std::bit_cast<uint32_t>(-0.5f), std::bit_cast<uint32_t>(1.25f),
                       std::bit_cast<uint32_t>(1.0f)};
  machine.inputs[1] = {std::bit_cast<uint32_t>(0.25f), std::bit_cast<uint32_t>(0.5f), 0, 0};
  std::vector<Vec4> cb(7);
  for (uint32_t row = 0; row < 7; ++row)
    for (uint32_t k = 0; k < 4; ++k) cb[row][k] = std::bit_cast<uint32_t>(0.3f * float(row + 1) - 0.7f * float(k) + 0.1f);
  machine.cbuffers[0] = cb;
  const Vec4 stereo{std::bit_cast<uint32_t>(separation), std::bit_cast<uint32_t>(convergence), std::bit_cast<uint32_t>(1.0f), 0};
  machine.resource = [&](uint32_t, const Vec4&, const std::string&) { return stereo; };
  machine.instructionLimit = 10000;
  EXPECT_TRUE(program->run(machine).ok);
  return machine.outputs;
}

TEST(AsmHalo, CorrectionsOnlyMovesTheLanesAndLeavesThePositionToTheDriver) {
  AsmShiftResult full = shiftAssembly(kScreenPositionsVs5, {});
  AsmShiftResult lanesOnly = shiftAssembly(kScreenPositionsVs5, {}, true, /*shiftPosition=*/false);
  ASSERT_TRUE(full.ok && lanesOnly.ok);
  EXPECT_TRUE(lanesOnly.shifted);
  EXPECT_FALSE(lanesOnly.positionShifted);
  EXPECT_EQ(lanesOnly.movedLanes.size(), 2u);
  const auto original = run(kScreenPositionsVs5, 0.06f, 1.5f);
  const auto withShift = run(full.output, 0.06f, 1.5f);
  const auto withoutShift = run(lanesOnly.output, 0.06f, 1.5f);
  ASSERT_TRUE(original.count(0) && original.count(1) && original.count(2));
  EXPECT_EQ(withoutShift.at(0), original.at(0));  // the driver's to shift
  EXPECT_NE(withShift.at(0)[0], original.at(0)[0]);
  EXPECT_EQ(withoutShift.at(1), withShift.at(1));  // the lanes as the full conversion moves them
  EXPECT_EQ(withoutShift.at(2), withShift.at(2));
  EXPECT_NE(withoutShift.at(2)[0], original.at(2)[0]);
  EXPECT_EQ(withoutShift.at(3), original.at(3));
  // A stage with nothing that moves with x is copied under --corrections-only.
  const std::string plain = "vs_5_0\ndcl_input v0.xyzw\ndcl_output_siv o0.xyzw, position\nmov o0.xyzw, v0.xyzw\nret\n";
  AsmShiftResult copied = shiftAssembly(plain, {}, true, false);
  EXPECT_TRUE(copied.ok);
  EXPECT_FALSE(copied.shifted);
  EXPECT_EQ(copied.output, plain);
}

}  // namespace
}  // namespace stereoshift::d3dasm
