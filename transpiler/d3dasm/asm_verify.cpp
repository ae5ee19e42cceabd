// The execution check of the assembly route (asm_verify.h): this turns two shader texts into the
// counts of three checks, mono identity, per-eye identity of everything but the position's x, and
// x against the exact stereo reference, over seeded random input sets.
#include "transpiler/d3dasm/asm_verify.h"

#include "transpiler/d3dasm/asm_interpreter.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <memory>
#include <set>
#include <sstream>

namespace stereoshift::d3dasm {

namespace {

uint32_t bitsOf(float f) { return std::bit_cast<uint32_t>(f); }
float floatOf(uint32_t u) { return std::bit_cast<float>(u); }

// splitmix64: small, seedable, the same sequence on every platform.
struct Random {
  uint64_t state;
  uint64_t next() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  float unit() { return static_cast<float>(next() >> 40) * 0x1p-24f; }  // [0, 1)
  float between(float lo, float hi) { return lo + (hi - lo) * unit(); }
};

// The v registers the dump's input signature types as integers (`BLENDINDICES 0 xyzw 3 NONE uint`):
// they get small integers, as a mesh's bone indices are, not float bit patterns.
std::set<uint32_t> integerInputs(const std::string& text) {
  std::set<uint32_t> registers;
  std::istringstream lines(text);
  std::string line;
  bool inInputs = false;
  while (std::getline(lines, line)) {
    if (line.find("Input signature:") != std::string::npos) inInputs = true;
    else if (line.find("signature:") != std::string::npos || !line.starts_with("//")) inInputs = false;
    if (!inInputs) continue;
    std::istringstream words(line.substr(2));
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    if (w.size() >= 6 && !w[3].empty() && std::isdigit(static_cast<unsigned char>(w[3][0])) &&
        (w[5] == "uint" || w[5] == "int"))
      registers.insert(static_cast<uint32_t>(std::stoul(w[3])));
  }
  return registers;
}

std::string vecText(const Vec4& v) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "(%.9g, %.9g, %.9g, %.9g)", floatOf(v[0]), floatOf(v[1]), floatOf(v[2]),
                floatOf(v[3]));
  return buffer;
}

// One input set: the v registers and constant buffers the original declares.
struct Sample {
  int number = 0;
  bool identityRows = false;  // every cb row a unit vector: a matrix chain that yields w = 1
  std::map<uint32_t, Vec4> inputs;
  std::map<uint32_t, std::vector<Vec4>> cbuffers;
};

Sample makeSample(const Program& program, const std::set<uint32_t>& integers, int number, Random& random,
                  const std::vector<std::array<float, 4>>& firstInputValues) {
  Sample sample;
  sample.number = number;
  // A quarter of the sets: unit-vector rows, so that transforms built of cb rows (and the input
  // assembler's w = 1) give w == 1, the vertices the cutoff keeps mono.
  sample.identityRows = number % 4 == 3;
  for (const InputDeclaration& input : program.inputs()) {
    Vec4 v{0, 0, 0, bitsOf(1.0f)};
    for (int k = 0; k < 4; ++k) {
      if (!((input.mask >> k) & 1)) continue;
      if (input.systemValue == "vertex_id" || input.systemValue == "instance_id" || integers.count(input.index))
        v[k] = static_cast<uint32_t>(random.next() % 64);
      else
        v[k] = bitsOf(random.between(-2.0f, 2.0f));
    }
    if (!firstInputValues.empty() && &input == &program.inputs().front()) {
      const auto& chosen = firstInputValues[static_cast<size_t>(number) % firstInputValues.size()];
      for (int k = 0; k < 4; ++k) v[k] = bitsOf(chosen[k]);
    }
    sample.inputs[input.index] = v;
  }
  for (const auto& [slot, rows] : program.cbufferSizes()) {
    std::vector<Vec4>& cb = sample.cbuffers[slot];
    for (uint32_t row = 0; row < rows; ++row) {
      Vec4 v{};
      for (int k = 0; k < 4; ++k)
        v[k] = sample.identityRows ? bitsOf(row % 4 == static_cast<uint32_t>(k) ? 1.0f : 0.0f)
                                   : bitsOf(random.between(-2.0f, 2.0f));
      cb.push_back(v);
    }
  }
  return sample;
}

// A resource other than StereoParams answers a hash of its slot and coordinate: deterministic, so
// both shaders read the same texel.
Vec4 hashedTexel(uint32_t slot, const Vec4& coordinate) {
  Random random{slot * 0x100000001B3ULL ^ coordinate[0] ^ (uint64_t{coordinate[1]} << 21) ^
                (uint64_t{coordinate[2]} << 42) ^ (uint64_t{coordinate[3]} << 13)};
  return {bitsOf(random.unit()), bitsOf(random.unit()), bitsOf(random.unit()), bitsOf(random.unit())};
}

struct Runner {
  const Program& program;
  const Sample& sample;
  bool run(const Vec4& stereoParams, std::map<uint32_t, Vec4>* outputs, bool* limit) const {
    Machine machine;
    machine.inputs = sample.inputs;
    machine.cbuffers = sample.cbuffers;
    machine.resource = [&](uint32_t slot, const Vec4& coordinate, const std::string&) {
      return slot == 125 ? stereoParams : hashedTexel(slot, coordinate);
    };
    machine.instructionLimit = 1u << 16;
    RunResult result = program.run(machine);
    *limit = result.limitReached;
    *outputs = std::move(machine.outputs);
    return result.ok;
  }
};

// Whether the outputs agree bit for bit, leaving out the components of `skipReg` in `skipMask` and
// the lanes in `skipLanes`.
bool sameOutputs(const std::map<uint32_t, Vec4>& a, const std::map<uint32_t, Vec4>& b, uint32_t skipReg,
                 uint32_t skipMask, std::string* where, const std::vector<AsmMovedLane>& skipLanes = {}) {
  std::set<uint32_t> registers;
  for (const auto& [r, v] : a) registers.insert(r);
  for (const auto& [r, v] : b) registers.insert(r);
  for (uint32_t r : registers) {
    auto ia = a.find(r), ib = b.find(r);
    Vec4 va = ia == a.end() ? Vec4{} : ia->second, vb = ib == b.end() ? Vec4{} : ib->second;
    if ((ia == a.end()) != (ib == b.end())) {
      *where = "o" + std::to_string(r) + " is written by one shader only";
      return false;
    }
    for (int k = 0; k < 4; ++k) {
      if (r == skipReg && ((skipMask >> k) & 1)) continue;
      if (std::any_of(skipLanes.begin(), skipLanes.end(),
                      [&](const AsmMovedLane& m) { return m.reg == r && m.lane == static_cast<uint32_t>(k); }))
        continue;
      if (va[k] != vb[k]) {
        *where = "o" + std::to_string(r) + "." + "xyzw"[k] + " is " + vecText(vb).substr(0) + " for the original's " +
                 vecText(va);
        return false;
      }
    }
  }
  return true;
}

struct Checker {
  const AsmVerifyOptions& options;
  uint32_t position;
  AsmVerifyResult& result;

  void failure(const Sample& sample, const std::string& run, const std::string& what) {
    if (!result.firstFailure.empty()) return;
    std::string inputs;
    for (const auto& [reg, v] : sample.inputs) inputs += " v" + std::to_string(reg) + " = " + vecText(v) + ";";
    result.firstFailure = "sample " + std::to_string(sample.number) + " (" + run + "): " + what + "; inputs:" + inputs +
                          " cb rows " + (sample.identityRows ? "unit vectors" : "random");
  }

  bool cutoffKeepsMono(float w) const { return stereoshift::cutoffKeepsMono(options.cutoff, options.cutoffEpsilon, w); }

  // x of one stereo run against the exact reference, from the original's float x and w.
  //
  // The bound. The block computes d = fl(w - c), then m = fl(fl(s*d) + x) (mad, unfused here; a
  // fused mad rounds once less and is within the same bound). With u = 2^-24 and |e_i| <= u:
  //   d = (w - c)(1 + e1),  p = s*d(1 + e2) = s(w - c)(1 + e1)(1 + e2),  m = (x + p)(1 + e3)
  //   m - ref = (p - s(w - c)) + e3 (x + p),  |p - s(w - c)| <= (2u + u^2)|s(w - c)|
  //   |m - ref| <= u|ref| + (2u + 3u^2 + u^3)|s(w - c)|
  // so, to first order, |m - ref| <= 2^-24 (|ref| + 2|s(w - c)|): one rounding each for w - c, the
  // product and the sum. The second-order terms and the double reference's own rounding (at most
  // 2^-52 (|ref| + 2|s(w - c)|)) are below 2^-44 of that and covered by the factor (1 + 2^-20).
  // Where a value is subnormal the relative model fails: each of the three roundings can then be
  // off by half a subnormal step, 2^-150, absolute; 3 * 2^-150 < FLT_MIN, the term added.
  void checkX(const Sample& sample, const std::string& run, float x, float w, float s, float c, float got) {
    if (cutoffKeepsMono(w)) {
      ++result.cutoffRuns;
      if (bitsOf(got) != bitsOf(x)) {
        ++result.cutoffMismatches;
        failure(sample, run, "w = " + std::to_string(w) + " is kept mono by the cutoff but x changed");
      }
      return;
    }
    ++result.shiftedRuns;
    double shift = double(s) * (double(w) - double(c));
    double ref = double(x) + shift;
    if (!std::isfinite(ref) || !std::isfinite(got)) {
      bool same = (std::isnan(ref) && std::isnan(got)) || double(got) == ref;
      if (!same) {
        ++result.shiftedFailures;
        failure(sample, run, "x is " + std::to_string(got) + " for the reference " + std::to_string(ref));
      }
      return;
    }
    double error = std::fabs(double(got) - ref);
    double bound = xBound(ref, shift);
    double ratio = error / bound;
    if (ratio >= result.worstRatio) {
      result.worstRatio = ratio;
      result.worstError = error;
      result.worstBound = bound;
    }
    if (error > bound) {
      ++result.shiftedFailures;
      char buffer[200];
      std::snprintf(buffer, sizeof buffer, "x is %.9g for the reference %.17g (x %.9g, w %.9g): error %.3g > bound %.3g",
                    double(got), ref, double(x), double(w), error, bound);
      failure(sample, run, buffer);
    }
  }

  // checkX's bound at x's reference: 2^-24 (|ref| + 2|s(w - c)|), as derived there.
  static double xBound(double ref, double shift) {
    return 0x1p-24 * (std::fabs(ref) + 2.0 * std::fabs(shift)) * (1.0 + 0x1p-20) + double(FLT_MIN);
  }

  // A moved lane of one stereo run. Where x is shifted: a copy is the converted x bit for bit;
  // another lane, the original's value l plus a times the shift, computed as
  // g = fl(l + fl(a * fl(x' - x))) (the `mad` fused or not) from the converted x', itself within
  // B = xBound of x + s(w - c). With u = 2^-24, to first order:
  //   fl(x' - x) = (x' - x)(1 + e1), |x' - x - s(w - c)| <= B
  //   |g - (l + a s(w - c))| <= |a| B + 2u |a| (|s(w - c)| + B) + u (|l + a s(w - c)| + |a| B)
  // (the difference, the product, the sum; a fused mad rounds once less); the second-order terms
  // are covered by the factor (1 + 2^-20), a subnormal's absolute half-steps (3 * 2^-150) by 2 FLT_MIN.
  // Where x is not shifted (the cutoff, or separation 0): the original's bits.
  void checkMovedLane(const Sample& sample, const std::string& run, const AsmMovedLane& lane, float x, float w, float s,
                      float c, float shiftedX, float original, float got) {
    ++result.movedLaneRuns;
    const std::string name = "o" + std::to_string(lane.reg) + "." + "xyzw"[lane.lane & 3];
    if (cutoffKeepsMono(w) || s == 0.0f) {
      if (bitsOf(got) != bitsOf(original)) {
        ++result.movedLaneFailures;
        failure(sample, run, name + " moved where x is not shifted");
      }
      return;
    }
    if (lane.copy) {
      if (bitsOf(got) != bitsOf(shiftedX)) {
        ++result.movedLaneFailures;
        failure(sample, run, name + " (a copy of x) is " + std::to_string(got) + ", not the shifted x " + std::to_string(shiftedX));
      }
      return;
    }
    const double shift = double(s) * (double(w) - double(c));
    const double a = std::fabs(double(lane.coefficient));
    const double ref = double(original) + double(lane.coefficient) * shift;
    const double b = xBound(double(x) + shift, shift);
    const double bound =
        (a * b + 0x1p-23 * a * (std::fabs(shift) + b) + 0x1p-24 * (std::fabs(ref) + a * b)) * (1.0 + 0x1p-20) +
        2.0 * double(FLT_MIN);
    const double error = std::isfinite(ref) && std::isfinite(got) ? std::fabs(double(got) - ref) : INFINITY;
    if (std::isnan(ref) && std::isnan(got)) return;
    result.worstMovedLaneRatio = std::max(result.worstMovedLaneRatio, error / bound);
    if (!(error <= bound)) {
      ++result.movedLaneFailures;
      char buffer[220];
      std::snprintf(buffer, sizeof buffer, "%s is %.9g for the reference %.17g (moved by %g times the shift): error %.3g > bound %.3g",
                    name.c_str(), double(got), ref, double(lane.coefficient), error, bound);
      failure(sample, run, buffer);
    }
  }

  void checkSample(const Program& original, const Program& converted, const Sample& sample, Random& random) {
    std::map<uint32_t, Vec4> mono, shifted, reference;
    bool limit = false;
    const Vec4 none{};
    if (!Runner{original, sample}.run(none, &reference, &limit) || limit) {
      ++result.runaway;
      return;
    }
    ++result.samples;
    auto positionIt = reference.find(position);
    const Vec4 pos = positionIt == reference.end() ? Vec4{} : positionIt->second;
    if (floatOf(pos[3]) == 1.0f) ++result.samplesWithWOne;
    const float convergence = random.between(0.5f, 5.0f);
    const float separation = 0.1f * (1.0f - random.unit());  // (0, 0.1]
    std::string where;
    // Mono: separation 0, of either sign (the eye's sign times 0).
    const float monoEye = sample.number % 2 ? -1.0f : 1.0f;
    ++result.monoRuns;
    Vec4 monoParams{bitsOf(0.0f * monoEye), bitsOf(convergence), bitsOf(monoEye), 0};
    if (!Runner{converted, sample}.run(monoParams, &mono, &limit) || !sameOutputs(reference, mono, 0, 0, &where) ||
        (!mono.count(position) && reference.count(position))) {
      ++result.monoMismatches;
      failure(sample, "mono, separation " + std::string(monoEye < 0 ? "-0" : "+0"), limit ? "the instruction limit" : where);
    }
    for (float eye : {-1.0f, 1.0f}) {
      ++result.stereoRuns;
      char run[120];
      std::snprintf(run, sizeof run, "eye %+.0f, separation %.9g, convergence %.9g", double(eye), double(separation),
                    double(convergence));
      Vec4 params{bitsOf(separation * eye), bitsOf(convergence), bitsOf(eye), 0};
      if (!Runner{converted, sample}.run(params, &shifted, &limit)) {
        ++result.otherOutputMismatches;
        failure(sample, run, "the converted shader did not finish");
        continue;
      }
      if (!sameOutputs(reference, shifted, position, 0xF, &where, options.movedLanes)) {
        ++result.otherOutputMismatches;
        failure(sample, run, where);
      }
      Vec4 got = shifted.count(position) ? shifted[position] : Vec4{};
      for (const AsmMovedLane& lane : options.movedLanes) {
        auto before = reference.find(lane.reg), after = shifted.find(lane.reg);
        if (before == reference.end() || after == shifted.end()) continue;  // sameOutputs said so
        const float moved = floatOf(after->second[lane.lane & 3]);
        if (options.positionLeftToDriver && lane.copy) {
          // The position is the driver's to shift: its copy carries the shifted x on its own.
          ++result.movedLaneRuns;
          checkX(sample, run, floatOf(pos[0]), floatOf(pos[3]), floatOf(params[0]), convergence, moved);
          continue;
        }
        checkMovedLane(sample, run, lane, floatOf(pos[0]), floatOf(pos[3]), floatOf(params[0]), convergence,
                       floatOf(got[0]), floatOf(before->second[lane.lane & 3]), moved);
      }
      if (options.positionLeftToDriver) {
        if (got != pos) {
          ++result.positionYzwMismatches;
          failure(sample, run, "the position, left to the driver, is " + vecText(got) + " for the original's " + vecText(pos));
        }
        continue;
      }
      if (got[1] != pos[1] || got[2] != pos[2] || got[3] != pos[3]) {
        ++result.positionYzwMismatches;
        failure(sample, run, "the position's y, z, w are " + vecText(got) + " for the original's " + vecText(pos));
      }
      checkX(sample, run, floatOf(pos[0]), floatOf(pos[3]), floatOf(params[0]), convergence, floatOf(got[0]));
    }
  }
};

std::unique_ptr<Program> decodeText(const std::string& text, const char* which, std::string* error) {
  Result<AsmText> parsed = parseAssembly(text);
  AsmError e = parsed.error();
  std::unique_ptr<Program> program;
  if (parsed) program = Program::decode(*parsed, &e);
  if (!program)
    *error = std::string(which) + " shader, line " + std::to_string(e.line) + ":" + std::to_string(e.column) + ": " +
             e.message;
  return program;
}

}  // namespace

AsmVerifyResult verifyAssemblyConversion(const std::string& originalText, const std::string& convertedText,
                                         const AsmVerifyOptions& options) {
  AsmVerifyResult result;
  std::unique_ptr<Program> original = decodeText(originalText, "the original", &result.error);
  if (!original) return result;
  std::unique_ptr<Program> converted = decodeText(convertedText, "the converted", &result.error);
  if (!converted) return result;
  result.ran = true;
  if (!original->positionOutput()) {
    result.nothingToVerify = true;
    result.ok = true;
    return result;
  }
  const uint32_t position = *original->positionOutput();
  result.positionRegister = "o" + std::to_string(position);
  const std::set<uint32_t> integers = integerInputs(originalText);
  Random random{options.seed};
  Checker checker{options, position, result};
  for (int k = 0; k < options.samples; ++k) {
    Sample sample = makeSample(*original, integers, k, random, options.firstInputValues);
    checker.checkSample(*original, *converted, sample, random);
  }
  if (result.samples == 0) {
    result.ran = false;
    result.error = "every input set ran into the instruction limit (" + std::to_string(result.runaway) + " of them)";
    return result;
  }
  result.ok = result.monoMismatches == 0 && result.otherOutputMismatches == 0 && result.positionYzwMismatches == 0 &&
              result.cutoffMismatches == 0 && result.shiftedFailures == 0 && result.movedLaneFailures == 0;
  return result;
}

}  // namespace stereoshift::d3dasm
