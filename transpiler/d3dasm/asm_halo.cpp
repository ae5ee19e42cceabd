// The halos of vertex- and domain-shader assembly (asm_halo.h): output lanes linear in the
// position's x, found on the evaluation of asm_evaluation.h.
#include "transpiler/d3dasm/asm_halo.h"

#include "transpiler/d3dasm/asm_evaluation.h"
#include "transpiler/d3dasm/asm_interpreter.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

namespace stereoshift::d3dasm {

namespace {

using namespace evaluation;

// A part's key: its term and its coefficient's element (a constant on its own has none).
using PartKey = std::tuple<int, std::optional<Element>, bool>;

std::map<PartKey, float> partsOf(const Linear& form, float* constant) {
  std::map<PartKey, float> parts;
  for (const Part& part : form) {
    if (part.term < 0 && !part.coefficient.element) {
      *constant += part.coefficient.scale;
      continue;
    }
    parts[{part.term, part.coefficient.element, part.coefficient.inverse}] += part.coefficient.scale;
  }
  return parts;
}

// How lane `lane` moves with x: its coefficient, a copy, or nothing.
struct Move {
  float coefficient = 0.0f;
  bool copy = false;
};

std::optional<Move> moveOf(const Evaluator& evaluation, int lane, int x) {
  if (lane == x) return Move{1.0f, true};
  const auto& values = evaluation.values();
  float xConstant = 0.0f, laneConstant = 0.0f;
  const std::map<PartKey, float> xParts = partsOf(values[x].form, &xConstant);
  std::map<PartKey, float> rest = partsOf(values[lane].form, &laneConstant);
  // x must vary: at least one part with a term.
  bool varies = false;
  for (const auto& [key, scale] : xParts) varies |= std::get<0>(key) >= 0;
  if (!varies) return std::nullopt;
  std::optional<float> a;
  for (const auto& [key, scale] : xParts) {
    auto it = rest.find(key);
    if (it == rest.end() || scale == 0.0f) return std::nullopt;
    const float ratio = it->second / scale;
    if (!a) a = ratio;
    // The same constant for every part, to float rounding of the product each part went through.
    if (!(std::fabs(it->second - *a * scale) <= 1e-6f * std::fabs(it->second))) return std::nullopt;
    rest.erase(it);
  }
  if (!a || *a == 0.0f || !std::isfinite(*a)) return std::nullopt;
  for (const auto& [key, scale] : rest)
    if (std::get<0>(key) >= 0 && evaluation.mayDependOn(std::get<0>(key), x)) return std::nullopt;
  return Move{*a, false};
}

}  // namespace

std::vector<AsmMovedLane> findAsmMovedLanes(const Program& program) {
  const Program::Impl& p = program.decoded();
  if (!p.position) return {};
  for (const Op& op : p.ops)
    for (uint8_t k = 0; k < op.dstCount; ++k)
      if (op.dst[k].file == File::Output && op.dst[k].index.relative) return {};
  Evaluator evaluation(p);
  evaluation.run();
  const auto& exits = evaluation.exits();
  if (exits.empty()) return {};
  for (const auto& exit : exits)
    if (!exit.outputs.count({*p.position, 0})) return {};
  // How lane `at` moves at one return, if it does.
  auto moveAt = [&](const Evaluator::Exit& exit, std::pair<uint32_t, uint32_t> at) -> std::optional<Move> {
    auto written = exit.outputs.find(at);
    if (written == exit.outputs.end()) return std::nullopt;
    return moveOf(evaluation, written->second, exit.outputs.at({*p.position, 0}));
  };
  std::vector<AsmMovedLane> lanes;
  for (const auto& output : p.outputMasks) {
    const uint32_t reg = output.first, mask = output.second;  // (clang 14 captures no structured binding)
    if (reg == *p.position) continue;
    for (uint32_t lane = 0; lane < 4; ++lane) {
      if (!(mask & (1u << lane))) continue;
      const std::optional<Move> move = moveAt(exits.front(), {reg, lane});
      // Taken only where it moves the same way at every return.
      const bool everywhere = move && std::all_of(exits.begin() + 1, exits.end(), [&](const Evaluator::Exit& exit) {
                                auto there = moveAt(exit, {reg, lane});
                                return there && there->copy == move->copy && there->coefficient == move->coefficient;
                              });
      if (!everywhere) continue;
      const size_t op = evaluation.values()[exits.front().outputs.at({reg, lane})].op;
      lanes.push_back({reg, lane, move->coefficient, move->copy, op == SIZE_MAX ? 0 : p.ops[op].line});
    }
  }
  return lanes;
}

}  // namespace stereoshift::d3dasm
