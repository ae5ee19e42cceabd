// The assembly route's evaluation of a pixel shader (asm_unprojection.cpp): every register
// component an instruction writes a value of its own, in program order, each a sum of terms with
// one constant-buffer element (times a constant) or a constant as its coefficient, remembering the
// input lanes and textures it was computed from, the products and quotients it is, and which
// straight stretch of the program (region) wrote it.
#pragma once

#include "transpiler/d3dasm/asm_interpreter_ops.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace stereoshift::d3dasm::evaluation {

// A constant-buffer element: cbN[row].lane.
struct Element {
  uint32_t slot = 0, row = 0, lane = 0;
  auto operator<=>(const Element&) const = default;
};

// A term's coefficient, or a part without a term: an element times `scale`, or the constant `scale`.
struct Coefficient {
  std::optional<Element> element;
  float scale = 1.0f;
  bool inverse = false;  // the element divides: scale / element
};

struct Part {
  int term = -1;  // the value the part multiplies; -1: none (a constant or an element on its own)
  Coefficient coefficient;
};
using Linear = std::vector<Part>;

// What a value was computed from: a lane of an input register, or a texture.
struct Source {
  enum Kind : uint8_t { Input, Texel } kind = Input;
  uint32_t reg = 0, lane = 0;
  auto operator<=>(const Source&) const = default;
};

struct Value {
  Linear form;
  std::set<Source> sources;
  size_t op = SIZE_MAX;          // the instruction that wrote it (SIZE_MAX: an input, or unknown)
  std::optional<std::pair<uint32_t, uint32_t>> at;  // the temporary component it was written to
  std::vector<int> factors;      // a product of values (a new term): the values multiplied
  std::pair<int, int> quotient{-1, -1};  // a division of two values: numerator, denominator
  std::vector<int> from;         // a new term of an instruction looked into no further: the values it read
  // A texel of a `sample*` / `gather*`: the values its coordinate's lanes 0 and 1 are (-1: not one
  // value, a constant or an element).
  std::pair<int, int> sampledAt{-1, -1};
};

// A temporary's component as the text names it: "r2.x".
inline std::string registerText(std::pair<uint32_t, uint32_t> at) { return "r" + std::to_string(at.first) + "." + "xyzw"[at.second]; }

// An operand's component as the evaluation reads it.
struct Read {
  Linear form;
  std::set<Source> sources;
  int value = -1;  // the value it is (-1: a literal or a constant-buffer element)
};

inline bool isConstant(const Linear& f) { return f.empty() || (f.size() == 1 && f[0].term < 0 && !f[0].coefficient.element); }
inline float constantOf(const Linear& f) { return f.empty() ? 0.0f : f[0].coefficient.scale; }
inline bool isElement(const Linear& f) {
  return f.size() == 1 && f[0].term < 0 && f[0].coefficient.element && !f[0].coefficient.inverse;
}

inline Linear scaled(Linear f, float by) {
  for (auto& part : f) part.coefficient.scale *= by;
  return f;
}

inline Linear sum(Linear a, const Linear& b) {
  a.insert(a.end(), b.begin(), b.end());
  // Constants folded into one part; a zero constant dropped.
  float constant = 0.0f;
  Linear folded;
  for (const auto& part : a) {
    if (part.term < 0 && !part.coefficient.element) {
      constant += part.coefficient.scale;
    } else {
      folded.push_back(part);
    }
  }
  if (constant != 0.0f) folded.push_back({-1, {std::nullopt, constant}});
  return folded;
}

constexpr size_t kMaxFactors = 8;

// Depth first from value `start` over what each value was computed from (its linear form's terms, a
// product's factors, a quotient's parts, what an instruction looked into no further read), each
// value once, with a stack of its own (a dump's chains are thousands of values long). `visit(id)`
// says whether to go on into what that value was computed from, past it, or to stop.
enum class Walk { Into, Past, Stop };
template <class Visit>
void walkComputedFrom(const std::vector<Value>& values, int start, Visit visit) {
  std::vector<char> seen(values.size(), 0);
  std::vector<int> stack{start};
  while (!stack.empty()) {
    const int at = stack.back();
    stack.pop_back();
    if (at < 0 || seen[at]) continue;
    seen[at] = 1;
    const Walk next = visit(at);
    if (next == Walk::Stop) return;
    if (next == Walk::Past) continue;
    const Value& v = values[at];
    stack.insert(stack.end(), v.from.begin(), v.from.end());
    stack.insert(stack.end(), v.factors.begin(), v.factors.end());
    stack.push_back(v.quotient.first);
    stack.push_back(v.quotient.second);
    for (const Part& part : v.form)
      if (part.term >= 0 && part.term != at) stack.push_back(part.term);
  }
}

// Output registers are kept beside the temporaries, their numbers offset by this (an output is
// written, never read, in SM4+): what each holds at a return is its value there.
constexpr uint32_t kOutputKey = 1u << 30;
using RegisterState = std::map<std::pair<uint32_t, uint32_t>, int>;

class Evaluator {
 public:
  explicit Evaluator(const Program::Impl& program) : p_(program) {}

  void run() {
    for (size_t k = 0; k < p_.ops.size(); ++k) step(k);
  }
  const std::vector<Value>& values() const { return values_; }
  // Whether temporary component `at` is written by an op after `from`, up to and including `to`.
  bool writtenBetween(std::pair<uint32_t, uint32_t> at, size_t from, size_t to) const {
    auto it = writes_.find(at);
    if (it == writes_.end()) return false;
    return std::any_of(it->second.begin(), it->second.end(), [&](size_t op) { return op > from && op <= to; });
  }
  // Whether `v` is still in the temporary it was written to when op `at` runs (written by an
  // instruction, not rewritten since).
  bool stillIn(const Value& v, size_t at) const { return v.at && v.op != SIZE_MAX && !writtenBetween(*v.at, v.op, at); }
  // Straight-line stretches: ops with the same number have no control flow between them.
  size_t region(size_t op) const { return regions_[op]; }
  // What each output lane holds at each return (`ret`, `retc_nz`, `retc_z`; a program with
  // subroutines is not decoded): the op and the lanes written by then, keyed {reg, lane}.
  struct Exit {
    size_t op = 0;
    RegisterState outputs;
  };
  const std::vector<Exit>& exits() const { return exits_; }
  // Whether value `id` may depend on value `on`: through its linear form's terms, the factors of a
  // product, the parts of a quotient, what an instruction looked into no further read; a value the
  // evaluation lost track of (merged at an endif, written in a loop, read before any write) may
  // depend on anything. Inputs depend on nothing.
  bool mayDependOn(int id, int on) const {
    bool depends = false;
    walkComputedFrom(values_, id, [&](int at) {
      const Value& v = values_[at];
      if (at == on || (v.op == SIZE_MAX && v.from.empty() && v.sources.empty())) {  // or lost track of
        depends = true;
        return Walk::Stop;
      }
      return v.op == SIZE_MAX && v.from.empty() ? Walk::Past : Walk::Into;  // an input: computed from nothing
    });
    return depends;
  }

 private:
  int fresh(std::set<Source> sources, size_t op) {
    const int id = static_cast<int>(values_.size());
    Value v;
    v.form = {{id, {std::nullopt, 1.0f}}};
    v.sources = std::move(sources);
    v.op = op;
    values_.push_back(std::move(v));
    return id;
  }
  int make(Linear form, std::set<Source> sources, size_t op) {
    Value v;
    v.form = std::move(form);
    v.sources = std::move(sources);
    v.op = op;
    values_.push_back(std::move(v));
    return static_cast<int>(values_.size()) - 1;
  }

  Read read(const Src& s, uint32_t component) {
    const uint32_t lane = s.swizzle[component];
    Read r;
    switch (s.file) {
      case File::Temp: {
        auto it = temps_.find({s.reg, lane});
        r.value = it != temps_.end() ? it->second : (temps_[{s.reg, lane}] = fresh({}, SIZE_MAX));
        break;
      }
      case File::Input: {
        auto it = inputs_.find({s.reg, lane});
        r.value = it != inputs_.end() ? it->second : (inputs_[{s.reg, lane}] = fresh({{Source::Input, s.reg, lane}}, SIZE_MAX));
        break;
      }
      case File::ConstantBuffer:
        if (s.index.relative) {
          r.value = fresh({}, SIZE_MAX);
          break;
        }
        r.form = {{-1, {Element{s.reg, static_cast<uint32_t>(s.index.offset), lane}, 1.0f}}};
        break;
      case File::Literal: {
        float f;
        std::memcpy(&f, &s.literal[lane], 4);
        if (f != 0.0f) r.form = {{-1, {std::nullopt, f}}};
        break;
      }
      default:
        r.value = fresh({}, SIZE_MAX);
    }
    if (r.value >= 0) {
      r.form = values_[r.value].form;
      r.sources = values_[r.value].sources;
    }
    if (s.absolute) {
      if (!isConstant(r.form)) {
        const int inner = r.value;
        r.value = fresh(r.sources, SIZE_MAX);
        if (inner >= 0) values_[r.value].from = {inner};
        else for (const Part& part : r.form) if (part.term >= 0) values_[r.value].from.push_back(part.term);
        r.form = values_[r.value].form;
      } else if (!r.form.empty()) {
        r.form[0].coefficient.scale = std::abs(r.form[0].coefficient.scale);
      }
    }
    if (s.negate) {
      r.form = scaled(r.form, -1.0f);
      r.value = -1;  // a new value: the negation's
    }
    return r;
  }

  // a * b, looked through when one factor is a constant or one constant-buffer element.
  std::optional<Linear> product(const Read& a, const Read& b) {
    if (isConstant(a.form)) return scaled(b.form, constantOf(a.form));
    if (isConstant(b.form)) return scaled(a.form, constantOf(b.form));
    for (const auto& [element, other] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
      if (!isElement(element->form)) continue;
      const Coefficient& e = element->form[0].coefficient;
      const Linear& f = other->form;
      if (f.size() == 1 && f[0].term >= 0 && !f[0].coefficient.element)
        return Linear{{f[0].term, {e.element, e.scale * f[0].coefficient.scale}}};
      if (other->value >= 0) return Linear{{other->value, e}};
      return std::nullopt;
    }
    return std::nullopt;
  }

  std::set<Source> joined(std::initializer_list<const Read*> reads) {
    std::set<Source> all;
    for (const Read* r : reads) all.insert(r->sources.begin(), r->sources.end());
    return all;
  }

  void write(const Dst& d, uint32_t component, int value) {
    if (d.file == File::Output && !d.index.relative) {
      temps_[{kOutputKey + d.reg, component}] = value;
      return;
    }
    if (d.file != File::Temp) return;
    const std::pair<uint32_t, uint32_t> at{d.reg, component};
    temps_[at] = value;
    writes_[at].push_back(current_);
    if (values_[value].op == current_ && !values_[value].at) values_[value].at = at;
  }

  void recordExit(size_t op) {
    Exit exit{op, {}};
    for (const auto& [at, value] : temps_)
      if (at.first >= kOutputKey) exit.outputs[{at.first - kOutputKey, at.second}] = value;
    exits_.push_back(std::move(exit));
  }

  void arithmetic(const Op& op) {
    const Dst& d = op.dst[0];
    const bool dot = op.code == Code::Dp2 || op.code == Code::Dp3 || op.code == Code::Dp4;
    if (dot) {
      const uint32_t n = op.code == Code::Dp2 ? 2 : op.code == Code::Dp3 ? 3 : 4;
      std::optional<Linear> total = Linear{};
      std::set<Source> sources;
      std::vector<int> reads;
      for (uint32_t k = 0; k < n; ++k) {
        Read a = read(op.src[0], k), b = read(op.src[1], k);
        sources.merge(joined({&a, &b}));
        readValues({&a, &b}, reads);
        std::optional<Linear> term = product(a, b);
        if (!term || !total) total.reset();
        else total = sum(*total, *term);
      }
      const int value = op.saturate || !total ? fresh(sources, current_) : make(*total, sources, current_);
      if (op.saturate || !total) values_[value].from = std::move(reads);
      for (uint32_t c = 0; c < 4; ++c)
        if (d.mask & (1u << c)) write(d, c, value);
      return;
    }
    for (uint32_t c = 0; c < 4; ++c) {
      if (!(d.mask & (1u << c))) continue;
      Read a = read(op.src[0], c);
      std::optional<Linear> form;
      std::set<Source> sources = a.sources;
      std::vector<int> reads;
      readValues({&a}, reads);
      if (op.code == Code::Mov) {
        if (!op.saturate && a.value >= 0) {
          write(d, c, a.value);  // the same value in another place
          continue;
        }
        form = a.form;
      } else {
        Read b = read(op.src[1], c);
        sources.merge(joined({&b}));
        readValues({&b}, reads);
        if (op.code == Code::Add) {
          form = sum(a.form, b.form);
        } else if (op.code == Code::Mul) {
          form = product(a, b);
          if (!form && !op.saturate && a.value >= 0 && b.value >= 0) {
            // A product of two values: a new term that remembers its factors (a handful at most: a
            // chain that squares a value again and again stays linear in size, its product an atom).
            const int value = fresh(sources, current_);
            values_[value].from = {a.value, b.value};
            std::vector<int> factors;
            for (int factor : {a.value, b.value}) {
              const auto& inner = values_[factor].factors;
              if (inner.empty()) factors.push_back(factor);
              else factors.insert(factors.end(), inner.begin(), inner.end());
            }
            if (factors.size() <= kMaxFactors) values_[value].factors = std::move(factors);
            write(d, c, value);
            continue;
          }
        } else if (op.code == Code::Div && isConstant(b.form) && constantOf(b.form) != 0.0f) {
          form = scaled(a.form, 1.0f / constantOf(b.form));
        } else if (op.code == Code::Div && isElement(b.form) && b.form[0].coefficient.scale != 0.0f) {
          // a / (k * E): a term over one element (the view ray's `x / P00`).
          const Coefficient& e = b.form[0].coefficient;
          const Linear& f = a.form;
          if (f.size() == 1 && f[0].term >= 0 && !f[0].coefficient.element)
            form = Linear{{f[0].term, {e.element, f[0].coefficient.scale / e.scale, true}}};
          else if (a.value >= 0)
            form = Linear{{a.value, {e.element, 1.0f / e.scale, true}}};
        } else if (op.code == Code::Div && !op.saturate && a.value >= 0 && b.value >= 0 && !isConstant(b.form)) {
          // A quotient of two values (the perspective divide `q.xyz / q.w`): a new term that
          // remembers them.
          const int value = fresh(sources, current_);
          values_[value].quotient = {a.value, b.value};
          write(d, c, value);
          continue;
        } else if (op.code == Code::Mad) {
          Read e = read(op.src[2], c);
          sources.merge(joined({&e}));
          readValues({&e}, reads);
          if (auto p = product(a, b)) form = sum(*p, e.form);
        }
      }
      if (op.saturate || !form) {
        const int value = fresh(sources, current_);
        values_[value].from = std::move(reads);
        write(d, c, value);
      } else {
        write(d, c, make(*form, sources, current_));
      }
    }
  }

  // Any other instruction: each component it writes is a new term made from everything it reads;
  // a texture read's from its texture alone (where it is read does not make the texel per pixel
  // in the sense the roles ask: a depth read at the pixel is a depth).
  void opaque(const Op& op, bool texel) {
    std::set<Source> sources;
    std::vector<int> reads;
    for (uint8_t s = 0; s < op.srcCount; ++s) {
      if (op.src[s].file == File::Resource || op.src[s].file == File::Sampler) continue;
      for (uint32_t c = 0; c < 4; ++c) {
        Read r = read(op.src[s], c);
        if (!texel) sources.merge(r.sources);
        readValues({&r}, reads);
      }
    }
    if (texel) sources.insert({Source::Texel, op.src[1].reg, 0});
    std::pair<int, int> sampledAt{-1, -1};
    if (texel && (op.resourceOpcode.starts_with("sample") || op.resourceOpcode.starts_with("gather")))
      sampledAt = {valueOf(read(op.src[0], 0)), valueOf(read(op.src[0], 1))};
    for (uint8_t k = 0; k < op.dstCount; ++k)
      for (uint32_t c = 0; c < 4; ++c)
        if (op.dst[k].mask & (1u << c)) {
          const int value = fresh(sources, current_);
          values_[value].from = reads;
          values_[value].sampledAt = sampledAt;
          write(op.dst[k], c, value);
        }
  }

  // The value a read is: itself, or the one term its form is with coefficient 1; -1 otherwise.
  static int valueOf(const Read& r) {
    if (r.value >= 0) return r.value;
    if (r.form.size() == 1 && r.form[0].term >= 0 && !r.form[0].coefficient.element && r.form[0].coefficient.scale == 1.0f)
      return r.form[0].term;
    return -1;
  }

  // The values a read stands for: the value itself, or the terms of its form.
  static void readValues(std::initializer_list<const Read*> list, std::vector<int>& reads) {
    for (const Read* r : list) {
      if (r->value >= 0) reads.push_back(r->value);
      for (const Part& part : r->form)
        if (part.term >= 0) reads.push_back(part.term);
    }
  }

  // What a loop body writes is unknown at its start and after it.
  void forgetLoopWrites(size_t loop) {
    int depth = 0;
    for (size_t k = loop; k < p_.ops.size(); ++k) {
      const Op& op = p_.ops[k];
      if (op.code == Code::Loop) ++depth;
      if (op.code == Code::Endloop && --depth == 0) break;
      for (uint8_t d = 0; d < op.dstCount; ++d)
        for (uint32_t c = 0; c < 4; ++c)
          if ((op.dst[d].file == File::Temp || op.dst[d].file == File::Output) && (op.dst[d].mask & (1u << c)))
            temps_[{op.dst[d].reg + (op.dst[d].file == File::Output ? kOutputKey : 0), c}] = fresh({}, SIZE_MAX);
    }
  }

  // if/else/endif: the state at endif is what both branches agree on; a branch that returned
  // does not reach it.
  struct Branch {
    std::map<std::pair<uint32_t, uint32_t>, int> before, first;
    bool inElse = false, firstReturned = false;
  };
  void merge(Branch& b) {
    const bool secondReturned = returned_;
    if (!b.inElse) {  // no else: the other way is the state before the if
      b.first = temps_;
      b.firstReturned = secondReturned;
      temps_ = b.before;
      returned_ = false;
    }
    if (b.firstReturned && !returned_) return;           // only this branch reaches endif
    if (returned_ && !b.firstReturned) {                 // only the first does
      temps_ = b.first;
      returned_ = false;
      return;
    }
    for (auto& [at, value] : temps_) {
      auto it = b.first.find(at);
      if (it == b.first.end() || it->second != value) value = fresh({}, SIZE_MAX);
    }
    for (const auto& [at, value] : b.first)
      if (!temps_.count(at)) temps_[at] = fresh({}, SIZE_MAX);
  }

  void step(size_t k) {
    current_ = k;
    const Op& op = p_.ops[k];
    regions_.push_back(region_);
    switch (op.code) {
      case Code::IfNz: case Code::IfZ:
        ++region_;
        branches_.push_back({temps_, {}, false, false});
        returned_ = false;
        return;
      case Code::Else:
        ++region_;
        if (!branches_.empty()) {
          branches_.back().first = temps_;
          branches_.back().firstReturned = returned_;
          branches_.back().inElse = true;
          temps_ = branches_.back().before;
          returned_ = false;
        }
        return;
      case Code::Endif:
        ++region_;
        if (!branches_.empty()) {
          merge(branches_.back());
          branches_.pop_back();
        }
        return;
      case Code::Loop:
        ++region_;
        forgetLoopWrites(k);
        return;
      case Code::Endloop:
        ++region_;
        return;
      case Code::Ret:
        recordExit(k);
        returned_ = true;
        ++region_;
        return;
      case Code::RetcNz: case Code::RetcZ:
        recordExit(k);
        ++region_;
        return;
      case Code::Break: case Code::BreakcNz: case Code::BreakcZ: case Code::Continue: case Code::ContinuecNz:
      case Code::ContinuecZ:
        ++region_;
        return;
      case Code::Nop: return;
      case Code::Mov: case Code::Add: case Code::Mul: case Code::Mad: case Code::Div: case Code::Dp2: case Code::Dp3:
      case Code::Dp4:
        arithmetic(op);
        return;
      // A texture's size (`resinfo`, `sampleinfo`, `bufinfo`) is the same for every pixel, like a
      // cbuffer element: not a texel (a pixel position over it is a UV, as over a screen size).
      case Code::Resource:
        opaque(op, !(op.resourceOpcode.starts_with("resinfo") || op.resourceOpcode.starts_with("sampleinfo") ||
                     op.resourceOpcode.starts_with("bufinfo")));
        return;
      default: opaque(op, false);
    }
  }

  const Program::Impl& p_;
  std::vector<Value> values_;
  std::map<std::pair<uint32_t, uint32_t>, int> temps_, inputs_;
  std::map<std::pair<uint32_t, uint32_t>, std::vector<size_t>> writes_;
  std::vector<Branch> branches_;
  std::vector<size_t> regions_;
  std::vector<Exit> exits_;
  size_t region_ = 0, current_ = 0;
  bool returned_ = false;
};

}  // namespace stereoshift::d3dasm::evaluation
