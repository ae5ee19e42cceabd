// See asm_unprojection.h.
#include "transpiler/d3dasm/asm_unprojection.h"

#include "transpiler/d3dasm/asm_interpreter_ops.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <optional>
#include <set>
#include <tuple>

namespace stereoshift::d3dasm {

namespace {

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
};

// A temporary's component as the text names it: "r2.x".
std::string registerText(std::pair<uint32_t, uint32_t> at) { return "r" + std::to_string(at.first) + "." + "xyzw"[at.second]; }

// An operand's component as the evaluation reads it.
struct Read {
  Linear form;
  std::set<Source> sources;
  int value = -1;  // the value it is (-1: a literal or a constant-buffer element)
};

bool isConstant(const Linear& f) { return f.empty() || (f.size() == 1 && f[0].term < 0 && !f[0].coefficient.element); }
float constantOf(const Linear& f) { return f.empty() ? 0.0f : f[0].coefficient.scale; }
bool isElement(const Linear& f) {
  return f.size() == 1 && f[0].term < 0 && f[0].coefficient.element && !f[0].coefficient.inverse;
}

Linear scaled(Linear f, float by) {
  for (auto& part : f) part.coefficient.scale *= by;
  return f;
}

Linear sum(Linear a, const Linear& b) {
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
        r.value = fresh(r.sources, SIZE_MAX);
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
    if (d.file != File::Temp) return;
    const std::pair<uint32_t, uint32_t> at{d.reg, component};
    temps_[at] = value;
    writes_[at].push_back(current_);
    if (values_[value].op == current_ && !values_[value].at) values_[value].at = at;
  }

  void arithmetic(const Op& op) {
    const Dst& d = op.dst[0];
    const bool dot = op.code == Code::Dp2 || op.code == Code::Dp3 || op.code == Code::Dp4;
    if (dot) {
      const uint32_t n = op.code == Code::Dp2 ? 2 : op.code == Code::Dp3 ? 3 : 4;
      std::optional<Linear> total = Linear{};
      std::set<Source> sources;
      for (uint32_t k = 0; k < n; ++k) {
        Read a = read(op.src[0], k), b = read(op.src[1], k);
        sources.merge(joined({&a, &b}));
        std::optional<Linear> term = product(a, b);
        if (!term || !total) total.reset();
        else total = sum(*total, *term);
      }
      const int value = op.saturate || !total ? fresh(sources, current_) : make(*total, sources, current_);
      for (uint32_t c = 0; c < 4; ++c)
        if (d.mask & (1u << c)) write(d, c, value);
      return;
    }
    for (uint32_t c = 0; c < 4; ++c) {
      if (!(d.mask & (1u << c))) continue;
      Read a = read(op.src[0], c);
      std::optional<Linear> form;
      std::set<Source> sources = a.sources;
      if (op.code == Code::Mov) {
        if (!op.saturate && a.value >= 0) {
          write(d, c, a.value);  // the same value in another place
          continue;
        }
        form = a.form;
      } else {
        Read b = read(op.src[1], c);
        sources.merge(joined({&b}));
        if (op.code == Code::Add) {
          form = sum(a.form, b.form);
        } else if (op.code == Code::Mul) {
          form = product(a, b);
          if (!form && !op.saturate && a.value >= 0 && b.value >= 0) {
            // A product of two values: a new term that remembers its factors (a handful at most: a
            // chain that squares a value again and again stays linear in size, its product an atom).
            const int value = fresh(sources, current_);
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
          if (auto p = product(a, b)) form = sum(*p, e.form);
        }
      }
      write(d, c, op.saturate || !form ? fresh(sources, current_) : make(*form, sources, current_));
    }
  }

  // Any other instruction: each component it writes is a new term made from everything it reads;
  // a texture read's from its texture alone (where it is read does not make the texel per pixel
  // in the sense the roles ask: a depth read at the pixel is a depth).
  void opaque(const Op& op, bool texel) {
    std::set<Source> sources;
    for (uint8_t s = 0; s < op.srcCount && !texel; ++s) {
      if (op.src[s].file == File::Resource) continue;
      for (uint32_t c = 0; c < 4; ++c) {
        Read r = read(op.src[s], c);
        sources.merge(r.sources);
      }
    }
    if (texel) sources.insert({Source::Texel, op.src[1].reg, 0});
    for (uint8_t k = 0; k < op.dstCount; ++k)
      for (uint32_t c = 0; c < 4; ++c)
        if (op.dst[k].mask & (1u << c)) write(op.dst[k], c, fresh(sources, current_));
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
          if (op.dst[d].file == File::Temp && (op.dst[d].mask & (1u << c))) temps_[{op.dst[d].reg, c}] = fresh({}, SIZE_MAX);
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
        returned_ = true;
        ++region_;
        return;
      case Code::Break: case Code::BreakcNz: case Code::BreakcZ: case Code::Continue: case Code::ContinuecNz:
      case Code::ContinuecZ: case Code::RetcNz: case Code::RetcZ:
        ++region_;
        return;
      case Code::Nop: return;
      case Code::Mov: case Code::Add: case Code::Mul: case Code::Mad: case Code::Div: case Code::Dp2: case Code::Dp3:
      case Code::Dp4:
        arithmetic(op);
        return;
      case Code::Resource: opaque(op, true); return;
      default: opaque(op, false);
    }
  }

  const Program::Impl& p_;
  std::vector<Value> values_;
  std::map<std::pair<uint32_t, uint32_t>, int> temps_, inputs_;
  std::map<std::pair<uint32_t, uint32_t>, std::vector<size_t>> writes_;
  std::vector<Branch> branches_;
  std::vector<size_t> regions_;
  size_t region_ = 0, current_ = 0;
  bool returned_ = false;
};

// One component of a candidate q (see the file comment).
struct Member {
  int value = -1;
  std::map<int, Coefficient> byTerm;  // the three terms and their elements
  Element translation;                // the element added on its own
  uint32_t index = 0;                 // which component of q
  std::string matrix;                 // the key of the matrix its elements belong to ("c..." columns, "r..." rows)
};

std::optional<Member> memberOf(const std::vector<Value>& values, int id) {
  Member m;
  m.value = id;
  std::optional<Element> translation;
  for (const Part& part : values[id].form) {
    if (!part.coefficient.element || part.coefficient.inverse) return std::nullopt;
    if (part.term < 0) {
      if (translation || part.coefficient.scale != 1.0f) return std::nullopt;
      translation = part.coefficient.element;
    } else if (!m.byTerm.emplace(part.term, part.coefficient).second) {
      return std::nullopt;
    }
  }
  if (!translation || m.byTerm.size() != 3) return std::nullopt;  // w = 1: a point
  m.translation = *translation;
  std::vector<Element> elements{*translation};
  for (const auto& [term, c] : m.byTerm) elements.push_back(*c.element);
  auto all = [&](auto&& same) {
    return std::all_of(elements.begin(), elements.end(), [&](const Element& e) { return same(e, elements[0]); });
  };
  std::set<std::pair<uint32_t, uint32_t>> vectors;
  for (const Element& e : elements) vectors.insert({e.slot, e.row});
  const bool oneSlot = all([](const Element& a, const Element& b) { return a.slot == b.slot; });
  if (oneSlot && all([](const Element& a, const Element& b) { return a.lane == b.lane; }) && vectors.size() == 4) {
    m.index = elements[0].lane;
    m.matrix = "c" + std::to_string(elements[0].slot);
    for (const auto& [slot, row] : vectors) m.matrix += ":" + std::to_string(row);
  } else if (vectors.size() == 1) {
    std::set<uint32_t> lanes;
    for (const Element& e : elements) lanes.insert(e.lane);
    if (lanes.size() != 4) return std::nullopt;
    m.index = elements[0].row;
    m.matrix = "r" + std::to_string(elements[0].slot);
  } else {
    return std::nullopt;
  }
  return m;
}

// Which term is the pixel's x, its y and the depth, from what each was computed from. In the
// screen-to-world form (q = M * (ndc.x * z, ndc.y * z, z, 1)) x and y are products of the screen
// coordinate and the depth term itself.
struct Roles {
  int x = -1, y = -1, depth = -1;
  uint32_t input = 0, texture = 0;
  bool scaled = false;
};

// What a value was computed from: the texture (if any) and the input lanes.
struct Origin {
  std::optional<uint32_t> texture;
  std::set<std::pair<uint32_t, uint32_t>> lanes;
};
Origin originOf(const Value& v) {
  Origin o;
  for (const Source& s : v.sources) {
    if (s.kind == Source::Texel) o.texture = s.reg;
    else o.lanes.insert({s.reg, s.lane});
  }
  return o;
}

// The screen axis (0: x, 1: y) and input register of lanes from one input, one of lanes 0 and 1.
std::optional<std::pair<int, uint32_t>> screenAxis(const std::set<std::pair<uint32_t, uint32_t>>& lanes) {
  std::set<uint32_t> regs;
  for (const auto& [reg, lane] : lanes) regs.insert(reg);
  if (regs.size() != 1) return std::nullopt;
  const uint32_t reg = *regs.begin();
  const bool has0 = lanes.count({reg, 0}) > 0, has1 = lanes.count({reg, 1}) > 0;
  if (has0 == has1) return std::nullopt;
  return std::pair{has0 ? 0 : 1, reg};
}

// The input lanes a term of a product is computed from besides its texel factor (none if it is the
// depth, or has a texel the way a screen position does not), for telling x from y.
std::optional<std::set<std::pair<uint32_t, uint32_t>>> screenLanes(const std::vector<Value>& values, int term) {
  const Origin o = originOf(values[term]);
  if (o.texture && o.lanes.empty()) return std::nullopt;  // the depth
  if (!o.texture) return std::set<std::pair<uint32_t, uint32_t>>(o.lanes.begin(), o.lanes.end());
  std::set<std::pair<uint32_t, uint32_t>> lanes;
  for (int factor : values[term].factors) {
    const Origin f = originOf(values[factor]);
    if (!f.texture) lanes.insert(f.lanes.begin(), f.lanes.end());
  }
  return lanes;
}

std::optional<Roles> rolesOf(const std::vector<Value>& values, const Member& m) {
  Roles r;
  std::vector<std::pair<int, int>> scaled;  // (term, the texel factor it is scaled by)
  // Lanes every screen term reads (an interpolated w both are divided by: `div r0.xy, v1.xyxx,
  // v2.xxxx`) tell no x from y: left out.
  std::optional<std::set<std::pair<uint32_t, uint32_t>>> common;
  for (const auto& [term, c] : m.byTerm)
    if (auto lanes = screenLanes(values, term)) {
      if (!common) common = *lanes;
      else std::erase_if(*common, [&](const auto& lane) { return !lanes->count(lane); });
    }
  auto withoutCommon = [&](std::set<std::pair<uint32_t, uint32_t>> lanes) {
    if (common) std::erase_if(lanes, [&](const auto& lane) { return common->count(lane) > 0; });
    return lanes;
  };
  auto assign = [&](int axis, uint32_t reg, int term) {
    if ((r.x >= 0 || r.y >= 0) && r.input != reg) return false;  // x and y of one input
    int& role = axis == 0 ? r.x : r.y;
    if (role >= 0) return false;
    role = term;
    r.input = reg;
    return true;
  };
  for (const auto& [term, c] : m.byTerm) {
    const Origin o = originOf(values[term]);
    if (o.texture && o.lanes.empty()) {
      if (r.depth >= 0) return std::nullopt;
      r.depth = term;
      r.texture = *o.texture;
      continue;
    }
    if (!o.texture) {
      auto axis = screenAxis(withoutCommon({o.lanes.begin(), o.lanes.end()}));
      if (!axis || !assign(axis->first, axis->second, term)) return std::nullopt;
      continue;
    }
    // Screen and texel: a product of screen-only factors and one texel-only factor.
    std::set<std::pair<uint32_t, uint32_t>> lanes;
    int depth = -1;
    for (int factor : values[term].factors) {
      const Origin f = originOf(values[factor]);
      if (f.texture && f.lanes.empty() && depth < 0) depth = factor;
      else if (!f.texture) lanes.insert(f.lanes.begin(), f.lanes.end());
      else return std::nullopt;
    }
    auto axis = depth >= 0 ? screenAxis(withoutCommon(lanes)) : std::nullopt;
    if (!axis || !assign(axis->first, axis->second, term)) return std::nullopt;
    scaled.push_back({term, depth});
  }
  if (r.x < 0 || r.y < 0 || r.depth < 0) return std::nullopt;
  // Both scaled or neither, each by the depth term itself.
  if (!scaled.empty()) {
    if (scaled.size() != 2) return std::nullopt;
    for (const auto& [term, depth] : scaled)
      if (depth != r.depth) return std::nullopt;
    r.scaled = true;
  }
  return r;
}

std::string elementText(const Element& e, bool lane = true) {
  std::string text = "cb" + std::to_string(e.slot) + "[" + std::to_string(e.row) + "]";
  return lane ? text + "." + "xyzw"[e.lane] : text;
}

// The input register whose lanes x, y, z the three terms are (one each, no texel), if they are: the
// product is a light-space transform of an interpolated position.
std::optional<uint32_t> interpolatedPosition(const std::vector<Value>& values, const Member& m) {
  std::set<uint32_t> lanes, regs;
  for (const auto& [term, c] : m.byTerm) {
    const Origin o = originOf(values[term]);
    if (o.texture || o.lanes.size() != 1) return std::nullopt;
    regs.insert(o.lanes.begin()->first);
    lanes.insert(o.lanes.begin()->second);
  }
  if (regs.size() != 1 || lanes != std::set<uint32_t>{0, 1, 2}) return std::nullopt;
  return *regs.begin();
}

// One axis of a view ray: a value that is one term times one element, the term a product of the
// screen coordinate (axis 0: x, 1: y) and one texel-only value (the depth).
struct RayCandidate {
  int value = -1, term = -1, depth = -1, screen = -1;
  int axis = 0;
  uint32_t input = 0;
  Coefficient k;
};
std::optional<RayCandidate> rayCandidate(const std::vector<Value>& values, int id) {
  const Linear& f = values[id].form;
  if (f.size() != 1 || f[0].term < 0 || !f[0].coefficient.element) return std::nullopt;
  RayCandidate c{id, f[0].term, -1, -1, 0, 0, f[0].coefficient};
  std::set<std::pair<uint32_t, uint32_t>> lanes;
  for (int factor : values[c.term].factors) {
    const Origin o = originOf(values[factor]);
    if (o.texture && o.lanes.empty() && c.depth < 0) c.depth = factor;
    else if (!o.texture && !o.lanes.empty() && c.screen < 0) c.screen = factor, lanes = o.lanes;
    else return std::nullopt;
  }
  auto axis = c.depth >= 0 && c.screen >= 0 ? screenAxis(lanes) : std::nullopt;
  if (!axis) return std::nullopt;
  c.axis = axis->first;
  c.input = axis->second;
  return c;
}

// Whether the pixel's x term is a screen input as it is, or times one constant or element.
bool notKnownNdc(const std::vector<Value>& values, int term) {
  const Linear& f = values[term].form;
  if (f.size() != 1 || f[0].term < 0) return false;
  const Value& inner = values[f[0].term];
  return inner.op == SIZE_MAX && !inner.sources.empty() &&
         std::all_of(inner.sources.begin(), inner.sources.end(), [](const Source& s) { return s.kind == Source::Input; });
}

// The view vectors c - q.xyz / q.w of a rebuild (AsmUnprojection::Camera): x, y and z written by
// one instruction, each a constant-buffer element minus the quotient of q's component by q.w.
std::vector<AsmUnprojection::Camera> camerasOf(const std::vector<Value>& values, const Program::Impl& p,
                                               const std::map<size_t, size_t>& lineIndex,
                                               const std::array<const Member*, 4>& q, const Roles& role) {
  // InvM's columns of x and z must be plain elements (no constant folded into them).
  std::array<std::string, 4> centre;
  for (size_t i = 0; i < 4; ++i) {
    const Coefficient& x = q[i]->byTerm.at(role.x);
    const Coefficient& z = q[i]->byTerm.at(role.depth);
    if (x.scale != 1.0f || z.scale != 1.0f || x.inverse || z.inverse) return {};
    centre[i] = elementText(*z.element);
  }
  // op -> the value of v.x, v.y, v.z it wrote, and whether each is p - c (the direction from the
  // camera) rather than c - p.
  std::map<size_t, std::array<int, 3>> byOp;
  std::map<size_t, std::set<bool>> fromCamera;
  for (int id = 0; id < static_cast<int>(values.size()); ++id) {
    const Value& v = values[id];
    if (v.op == SIZE_MAX || !v.at || v.form.size() != 2) continue;
    const Part* camera = nullptr;
    const Part* position = nullptr;
    for (const Part& part : v.form) {
      if (part.term < 0 && part.coefficient.element && !part.coefficient.inverse && std::abs(part.coefficient.scale) == 1.0f) camera = &part;
      else if (part.term >= 0 && !part.coefficient.element && std::abs(part.coefficient.scale) == 1.0f) position = &part;
    }
    if (!camera || !position || camera->coefficient.scale != -position->coefficient.scale) continue;
    const auto [numerator, denominator] = values[position->term].quotient;
    if (denominator != q[3]->value) continue;
    for (int i = 0; i < 3; ++i)
      if (numerator == q[i]->value) {
        auto [it, inserted] = byOp.try_emplace(v.op, std::array<int, 3>{-1, -1, -1});
        it->second[i] = id;
        fromCamera[v.op].insert(camera->coefficient.scale < 0);
      }
  }
  std::vector<AsmUnprojection::Camera> cameras;
  for (const auto& [op, ids] : byOp) {
    if (std::find(ids.begin(), ids.end(), -1) != ids.end() || fromCamera[op].size() != 1) continue;
    AsmUnprojection::Camera c;
    c.fromCamera = *fromCamera[op].begin();
    c.lineNumber = p.ops[op].line;
    c.afterLine = lineIndex.at(c.lineNumber);
    c.centre = centre;
    for (int i = 0; i < 3; ++i) {
      const Value& v = values[ids[i]];
      c.v[i] = registerText(*v.at);
      for (const Part& part : v.form)
        if (part.term < 0) c.camera[i] = elementText(*part.coefficient.element);
    }
    cameras.push_back(std::move(c));
  }
  return cameras;
}

// View rays: the first value per term and axis (a later scaling is per eye through it), an x with a
// y from the same depth, the depth still in its register at x.
void collectViewRays(const std::vector<Value>& values, const Evaluator& evaluation, const Program::Impl& p,
                     const std::map<size_t, size_t>& lineIndex, AsmUnprojections& result) {
  std::map<std::pair<int, int>, RayCandidate> rays;
  for (int id = 0; id < static_cast<int>(values.size()); ++id)
    if (values[id].op != SIZE_MAX && values[id].at)
      if (auto c = rayCandidate(values, id)) rays.emplace(std::pair{c->term, c->axis}, *c);
  for (const auto& entry : rays) {
    const RayCandidate& c = entry.second;  // a named reference: a lambda below captures it
    if (c.axis != 0) continue;
    const bool hasY = std::any_of(rays.begin(), rays.end(), [&](const auto& other) {
      return other.second.axis == 1 && other.second.depth == c.depth && other.second.input == c.input;
    });
    const Value& x = values[c.value];
    const Value& depth = values[c.depth];
    if (!hasY || !evaluation.stillIn(depth, x.op)) continue;
    if (notKnownNdc(values, c.screen)) {
      result.leftAlone.push_back("line " + std::to_string(p.ops[x.op].line) +
                                 ": a view-space x from a texture coordinate or pixel position as it is, not NDC");
      continue;
    }
    AsmViewRay r;
    r.afterLine = lineIndex.at(p.ops[x.op].line);
    r.lineNumber = p.ops[x.op].line;
    r.x = registerText(*x.at);
    r.depthRegister = registerText(*depth.at);
    r.element = elementText(*c.k.element);
    r.divides = c.k.inverse;
    r.scale = c.k.scale;
    r.depth = "t" + std::to_string(originOf(depth).texture.value_or(0));
    r.ndc = "v" + std::to_string(c.input);
    result.rays.push_back(std::move(r));
  }
}

}  // namespace

AsmUnprojections findAsmUnprojections(const AsmText& text, const Program& program) {
  const Program::Impl& p = program.decoded();
  Evaluator evaluation(p);
  evaluation.run();
  const auto& values = evaluation.values();
  // Candidates grouped by matrix and terms, each group's components by index.
  std::map<std::string, std::map<uint32_t, Member>> groups;
  std::map<std::string, Roles> roles;
  std::map<std::string, std::pair<uint32_t, size_t>> lightSpace;  // matrix -> (input, last line)
  for (int id = 0; id < static_cast<int>(values.size()); ++id) {
    if (values[id].op == SIZE_MAX || !values[id].at) continue;
    auto member = memberOf(values, id);
    if (!member) continue;
    auto role = rolesOf(values, *member);
    if (!role) {
      if (auto input = interpolatedPosition(values, *member)) {
        auto& seen = lightSpace[member->matrix];
        seen = {*input, std::max(seen.second, p.ops[values[id].op].line)};
      }
      continue;
    }
    std::string key = member->matrix;
    for (const auto& [term, c] : member->byTerm) key += "|" + std::to_string(term);
    groups[key][member->index] = *member;  // a later value of the same component replaces it
    roles[key] = *role;
  }
  std::map<size_t, size_t> lineIndex;  // line number -> index in text.lines
  for (size_t k = 0; k < text.lines.size(); ++k) lineIndex[text.lines[k].number] = k;
  AsmUnprojections result;
  std::vector<AsmUnprojection>& found = result.found;
  for (const auto& [key, group] : groups) {
    // Four components; or, in the screen-to-world form, whose correction needs no w, a point the
    // shader computes x, y and z of alone (lanes 0-2 of the columns, or three consecutive rows).
    const Roles& role = roles.at(key);
    const size_t needed = role.scaled && (key.front() != 'c' || !group.count(3)) ? 3 : 4;
    std::array<const Member*, 4> q{};
    if (key.front() == 'c') {
      if (group.size() != needed || group.rbegin()->first != needed - 1) continue;
      for (const auto& [index, member] : group) q[index] = &member;
    } else {
      if (group.size() < needed || group.size() > 4 || group.rbegin()->first != group.begin()->first + group.size() - 1) continue;
      for (const auto& [index, member] : group) q[index - group.begin()->first] = &member;
    }
    size_t first = SIZE_MAX, last = 0;
    for (const Member* m : q) {
      if (!m) continue;
      first = std::min(first, values[m->value].op);
      last = std::max(last, values[m->value].op);
    }
    // Correctable right after `last`: every component still in the register it was written to,
    // all of them computed in one straight stretch of the program.
    bool placeable = true;
    for (const Member* m : q) {
      if (!m) continue;
      const Value& v = values[m->value];
      placeable &= evaluation.region(v.op) == evaluation.region(last) && evaluation.stillIn(v, last);
    }
    // The screen-to-world form reads the depth there too: still in the register it was written to.
    const Value& z = values[role.depth];
    if (role.scaled && !evaluation.stillIn(z, last)) placeable = false;
    if (!placeable) continue;
    if (!role.scaled && notKnownNdc(values, role.x)) {
      result.leftAlone.push_back("line " + std::to_string(p.ops[last].line) +
                                 ": a position rebuilt from a texture coordinate or pixel position as it is, not NDC "
                                 "(no -1 offset): the matrix may map UV space, whose column is not the correction's");
      continue;
    }
    AsmUnprojection u;
    u.afterLine = lineIndex.at(p.ops[last].line);
    u.firstLineNumber = p.ops[first].line;
    u.lastLineNumber = p.ops[last].line;
    std::set<Element> rows;  // the matrix's vectors, lane 0 standing for the whole row
    for (size_t i = 0; i < 4; ++i) {
      if (!q[i]) continue;  // a point's w the shader never computes: u.q[3] stays empty
      const Value& v = values[q[i]->value];
      u.q[i] = registerText(*v.at);
      const Coefficient& column = q[i]->byTerm.at(role.x);
      u.column[i] = elementText(*column.element);
      u.columnScale[i] = column.scale;
      for (const auto& [term, c] : q[i]->byTerm) rows.insert({c.element->slot, c.element->row, 0});
      rows.insert({q[i]->translation.slot, q[i]->translation.row, 0});
    }
    for (const auto& row : rows) u.rows += (u.rows.empty() ? "" : ", ") + elementText(row, false);
    u.storage = key.front() == 'c' ? "columns (mad)" : "rows (dp4)";
    u.depth = "t" + std::to_string(role.texture);
    if (role.scaled) {
      u.scaledByDepth = true;
      u.depthRegister = registerText(*z.at);
    }
    u.ndc = "v" + std::to_string(role.input);
    if (!role.scaled) u.cameras = camerasOf(values, p, lineIndex, q, role);
    found.push_back(std::move(u));
  }
  std::sort(found.begin(), found.end(), [](const AsmUnprojection& a, const AsmUnprojection& b) { return a.afterLine < b.afterLine; });
  collectViewRays(values, evaluation, p, lineIndex, result);
  for (const auto& [matrix, seen] : lightSpace)
    result.leftAlone.push_back("line " + std::to_string(seen.second) + ": a matrix in constant-buffer rows applied to the "
                               "interpolated position v" + std::to_string(seen.first) +
                               ".xyz (light space): a shadow-map or projector lookup stays mono, a screen-space lookup "
                               "of this eye's image would need this eye's projection");
  return result;
}

}  // namespace stereoshift::d3dasm
