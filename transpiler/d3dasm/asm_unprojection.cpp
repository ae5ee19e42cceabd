// See asm_unprojection.h.
#include "transpiler/d3dasm/asm_unprojection.h"

#include "transpiler/d3dasm/asm_evaluation.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <optional>
#include <set>
#include <tuple>

namespace stereoshift::d3dasm {

using namespace evaluation;

namespace {


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
  bool fragmentDepth = false;  // the depth is SV_Position.z as it is (a forward pass), no texture
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

// Whether `term` is lane z of the SV_Position input `position` read as it is: the fragment's own
// depth, which a forward pass rebuilds the point it shades from (Unreal's materials,
// `mul(float4(SvPosition.xyz, 1), View.SVPositionToTranslatedWorld)`).
bool fragmentDepth(const std::vector<Value>& values, int term, std::optional<uint32_t> position) {
  const Value& v = values[term];
  return position && v.op == SIZE_MAX && v.sources.size() == 1 && v.sources.begin()->kind == Source::Input &&
         v.sources.begin()->reg == *position && v.sources.begin()->lane == 2;
}

// `position`: the pixel shader's SV_Position input register, if it declares one.
std::optional<Roles> rolesOf(const std::vector<Value>& values, const Member& m, std::optional<uint32_t> position) {
  Roles r;
  std::vector<std::pair<int, int>> scaled;  // (term, the texel factor it is scaled by)
  // Lanes every screen term reads (an interpolated w both are divided by: `div r0.xy, v1.xyxx,
  // v2.xxxx`) tell no x from y: left out.
  std::map<int, std::set<std::pair<uint32_t, uint32_t>>> screen;  // each term's but the depth's
  std::optional<std::set<std::pair<uint32_t, uint32_t>>> common;
  for (const auto& [term, c] : m.byTerm)
    if (fragmentDepth(values, term, position)) continue;
    else if (auto lanes = screenLanes(values, term)) {
      if (!common) common = *lanes;
      else std::erase_if(*common, [&](const auto& lane) { return !lanes->count(lane); });
      screen[term] = std::move(*lanes);
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
    if (fragmentDepth(values, term, position)) {
      if (r.depth >= 0) return std::nullopt;
      r.depth = term;
      r.fragmentDepth = true;
      continue;
    }
    if (o.texture && o.lanes.empty()) {
      if (r.depth >= 0) return std::nullopt;
      r.depth = term;
      r.texture = *o.texture;
      continue;
    }
    if (!o.texture) {
      auto axis = screenAxis(withoutCommon(screen.at(term)));
      if (!axis || !assign(axis->first, axis->second, term)) return std::nullopt;
      continue;
    }
    // Screen and texel: a product of screen-only factors (their lanes in `screen`) and one
    // texel-only factor.
    int depth = -1;
    for (int factor : values[term].factors) {
      const Origin f = originOf(values[factor]);
      if (f.texture && f.lanes.empty() && depth < 0) depth = factor;
      else if (f.texture) return std::nullopt;
    }
    auto axis = depth >= 0 ? screenAxis(withoutCommon(screen.at(term))) : std::nullopt;
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

// Whether the pixel's x term is a screen input as it is, or times one constant or element, or over a
// value read from no input and no texel (a pixel position over a texture's size, `resinfo`: a UV; a
// perspective divide by an input's w is NDC).
bool notKnownNdc(const std::vector<Value>& values, int term) {
  const Linear& f = values[term].form;
  if (f.size() != 1 || f[0].term < 0) return false;
  auto plainInput = [&](const Value& v) {
    return v.op == SIZE_MAX && !v.sources.empty() &&
           std::all_of(v.sources.begin(), v.sources.end(), [](const Source& s) { return s.kind == Source::Input; });
  };
  const Value& inner = values[f[0].term];
  if (plainInput(inner)) return true;
  const auto [numerator, denominator] = inner.quotient;
  return numerator >= 0 && denominator >= 0 && plainInput(values[numerator]) && values[denominator].sources.empty();
}

// Whether the depth of `role` is a texel sampled at the pixel's own x and y (the values the x and
// y terms are, or the one term each is a multiple of).
bool sampledAtIs(const std::vector<Value>& values, const Roles& role, std::pair<int, int> sampledAt);
bool depthSampledAt(const std::vector<Value>& values, const Roles& role) {
  return sampledAtIs(values, role, values[role.depth].sampledAt);
}

// Whether `sampledAt` (a sample's coordinate lanes 0 and 1) is the pixel's x and y of `role`.
bool sampledAtIs(const std::vector<Value>& values, const Roles& role, std::pair<int, int> sampledAt) {
  const auto [atX, atY] = sampledAt;
  auto is = [&](int term, int at) {
    if (at < 0) return false;
    if (term == at) return true;
    const Linear& f = values[term].form;
    return f.size() == 1 && f[0].term == at && !f[0].coefficient.element && f[0].coefficient.scale == 1.0f;
  };
  return is(role.x, atX) && is(role.y, atY);
}

// The screen-to-world form's coordinates (x * z and y * z, each the coordinate times the depth):
// each term's one factor besides the depth, or -1.
std::pair<int, int> screenFactorsOf(const std::vector<Value>& values, const Roles& role) {
  auto of = [&](int term) {
    std::vector<int> screen;
    for (int factor : values[term].factors)
      if (factor != role.depth) screen.push_back(factor);
    return screen.size() == 1 ? screen[0] : -1;
  };
  return {of(role.x), of(role.y)};
}

// Whether the screen-to-world form's coordinates are read as they are (notKnownNdc) and are the UV
// the one texel its linear depth is made from is sampled at (found through what the depth was
// computed from): the depth buffer's UV, whose NDC is 2u - 1.
bool scaledTermsSampledAt(const std::vector<Value>& values, const Roles& role) {
  const auto [x, y] = screenFactorsOf(values, role);
  if (x < 0 || y < 0 || !notKnownNdc(values, x) || !notKnownNdc(values, y)) return false;
  std::set<std::pair<int, int>> samples;
  walkComputedFrom(values, role.depth, [&](int at) {
    if (values[at].sampledAt.first >= 0) samples.insert(values[at].sampledAt);
    return Walk::Into;
  });
  if (samples.size() != 1) return false;
  Roles screen = role;
  screen.x = x;
  screen.y = y;
  return sampledAtIs(values, screen, *samples.begin());
}

// The operands of InvM's column of the depth and of its constant column (with their signs), for the
// run-time half-width of a screen coordinate (AsmUnprojection::scaleFromTheMatrix); nothing when a
// component is not computed or an element the computation reads (those and the column of x) is
// scaled by other than 1 or -1.
std::optional<std::array<std::array<std::string, 4>, 2>> columnsForTheScale(const std::array<const Member*, 4>& q,
                                                                           const Roles& role) {
  std::array<std::array<std::string, 4>, 2> columns;
  for (size_t i = 0; i < 4; ++i) {
    if (!q[i] && role.scaled && i == 3) continue;  // an affine map's point: its scale reads x, y and z
    if (!q[i]) return std::nullopt;
    const Coefficient& x = q[i]->byTerm.at(role.x);
    const Coefficient& z = q[i]->byTerm.at(role.depth);
    if (std::abs(x.scale) != 1.0f || std::abs(z.scale) != 1.0f || x.inverse || z.inverse) return std::nullopt;
    columns[0][i] = (z.scale < 0 ? "-" : "") + elementText(*z.element);
    columns[1][i] = elementText(q[i]->translation);  // a translation's scale is 1 (memberOf)
  }
  return columns;
}

// Whether the pixel's coordinate of `role` is not known to be NDC (notKnownNdc). The screen-to-world
// form's x term is the coordinate times the depth: the same rule on the coordinate, where a texture
// coordinate read as it is may carry NDC (a full-screen pass that hands its corners on) and is taken
// as such; the pixel position (SV_Position) never is. (Such a coordinate's scale is the map's to show:
// AsmUnprojection::scaleFromTheMatrix.)
// `position`: the SV_Position input register, if the shader declares one.
bool coordinateNotNdc(const std::vector<Value>& values, const Roles& role, std::optional<uint32_t> position) {
  if (!role.scaled) return notKnownNdc(values, role.x);
  const int screenX = screenFactorsOf(values, role).first;
  return screenX >= 0 && notKnownNdc(values, screenX) && position == role.input;
}

// The camera c of a view vector `sign` * (c - p) whose linear form is `f`, p being the point q's
// component `point` itself (the screen-to-world form without w): q's parts all in f times -sign, c
// the one element left over, times sign.
std::optional<Element> cameraBesidesPoint(const Linear& f, const Linear& point, float sign) {
  if (f.size() != point.size() + 1) return std::nullopt;
  std::vector<bool> used(f.size(), false);
  for (const Part& part : point) {
    bool matched = false;
    for (size_t k = 0; k < f.size() && !matched; ++k) {
      const Coefficient& c = f[k].coefficient;
      if (used[k] || f[k].term != part.term || c.element != part.coefficient.element ||
          c.inverse != part.coefficient.inverse || c.scale != -sign * part.coefficient.scale)
        continue;
      used[k] = matched = true;
    }
    if (!matched) return std::nullopt;
  }
  for (size_t k = 0; k < f.size(); ++k)
    if (!used[k]) {
      const Coefficient& c = f[k].coefficient;
      return f[k].term < 0 && c.element && !c.inverse && c.scale == sign ? c.element : std::nullopt;
    }
  return std::nullopt;
}

// The view vectors c - q.xyz / q.w of a rebuild (AsmUnprojection::Camera): x, y and z written by
// one instruction, each a constant-buffer element minus the quotient of q's component by q.w (or,
// the screen-to-world form without w, minus q's component itself); or the same vectors the other
// way round (p - c). The camera the matrix shows: InvM's column of z over its w, or where the
// screen-to-world map sends depth 0, its translation column.
std::vector<AsmUnprojection::Camera> camerasOf(const std::vector<Value>& values, const Program::Impl& p,
                                               const std::map<size_t, size_t>& lineIndex,
                                               const std::array<const Member*, 4>& q, const Roles& role) {
  // InvM's columns of x and z must be plain elements (no constant folded into them).
  std::array<std::string, 4> centre;
  for (size_t i = 0; i < 4; ++i) {
    if (!q[i]) {
      centre[i] = "l(1.000000)";  // an affine map's w
      continue;
    }
    const Coefficient& x = q[i]->byTerm.at(role.x);
    const Coefficient& z = q[i]->byTerm.at(role.depth);
    if (x.scale != 1.0f || x.inverse || (!role.scaled && (z.scale != 1.0f || z.inverse))) return {};
    centre[i] = role.scaled ? elementText(q[i]->translation) : elementText(*z.element);
  }
  // op -> the value of v.x, v.y, v.z it wrote, the camera element of each, and whether each is
  // p - c (the direction from the camera) rather than c - p.
  std::map<size_t, std::array<int, 3>> byOp;
  std::map<size_t, std::array<Element, 3>> cameraOf;
  std::map<size_t, std::set<bool>> fromCamera;
  auto found = [&](size_t op, int i, int id, Element camera, bool fromTheCamera) {
    auto [it, inserted] = byOp.try_emplace(op, std::array<int, 3>{-1, -1, -1});
    it->second[i] = id;
    cameraOf[op][i] = camera;
    fromCamera[op].insert(fromTheCamera);
  };
  for (int id = 0; id < static_cast<int>(values.size()); ++id) {
    const Value& v = values[id];
    if (v.op == SIZE_MAX || !v.at) continue;
    if (!q[3]) {
      for (int i = 0; i < 3; ++i)
        for (float sign : {1.0f, -1.0f})
          if (auto camera = cameraBesidesPoint(v.form, values[q[i]->value].form, sign))
            found(v.op, i, id, *camera, sign < 0);
      continue;
    }
    if (v.form.size() != 2) continue;
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
      if (numerator == q[i]->value) found(v.op, i, id, *camera->coefficient.element, camera->coefficient.scale < 0);
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
      c.v[i] = registerText(*values[ids[i]].at);
      c.camera[i] = elementText(cameraOf[op][i]);
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
  std::optional<uint32_t> position;  // SV_Position's register
  for (const InputDeclaration& input : p.inputs)
    if (input.systemValue == "position") position = input.index;
  // Candidates grouped by matrix and terms, each group's components by index.
  std::map<std::string, std::map<uint32_t, Member>> groups;
  std::map<std::string, Roles> roles;
  std::map<std::string, std::pair<uint32_t, size_t>> lightSpace;  // matrix -> (input, last line)
  for (int id = 0; id < static_cast<int>(values.size()); ++id) {
    if (values[id].op == SIZE_MAX || !values[id].at) continue;
    auto member = memberOf(values, id);
    if (!member) continue;
    auto role = rolesOf(values, *member, position);
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
    // A UV the depth is sampled at is the depth buffer's, over [0, 1] where NDC is over [-1, 1]: the
    // matrix maps UV space and the correction takes half its column of u.
    const bool notNdc = coordinateNotNdc(values, role, position);
    const bool uv = role.scaled ? scaledTermsSampledAt(values, role) : notNdc && depthSampledAt(values, role);
    // A coordinate of unknown scale into a matrix with a w: the matrix shows its scale.
    std::optional<std::array<std::array<std::string, 4>, 2>> scaleColumns;
    if (notNdc && !uv) scaleColumns = columnsForTheScale(q, role);
    if (notNdc && !uv && !scaleColumns) {
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
      u.columnScale[i] = uv ? 0.5f * column.scale : column.scale;
      for (const auto& [term, c] : q[i]->byTerm) rows.insert({c.element->slot, c.element->row, 0});
      rows.insert({q[i]->translation.slot, q[i]->translation.row, 0});
    }
    for (const auto& row : rows) u.rows += (u.rows.empty() ? "" : ", ") + elementText(row, false);
    u.storage = key.front() == 'c' ? "columns (mad)" : "rows (dp4)";
    u.uvOfTheDepthTexture = uv;
    if (scaleColumns) {
      u.scaleFromTheMatrix = true;
      u.columnZ = (*scaleColumns)[0];
      u.translation = (*scaleColumns)[1];
    }
    u.depth = role.fragmentDepth ? "the fragment's own depth (v" + std::to_string(role.input) + ".z)"
                                 : "t" + std::to_string(role.texture);
    if (role.scaled) {
      u.scaledByDepth = true;
      u.depthRegister = registerText(*z.at);
    }
    u.ndc = "v" + std::to_string(role.input);
    u.cameras = camerasOf(values, p, lineIndex, q, role);
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
