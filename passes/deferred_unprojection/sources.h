// What a value of a fragment shader is computed from, for deferred-unprojection: the leaves of the
// shared backward value flow (analysis/value_flow.h) as this pass sees them, gl_FragCoord / SV_Position,
// other inputs, texels, uniforms, constants and stereoshift's own eye parameters, with the names the
// source gives them (for the report).
#pragma once

#include "passes/analysis/value_flow.h"
#include "passes/ir/module.h"

#include <cstdint>
#include <optional>
#include <set>
#include <string>

namespace stereoshift::deferred {

using analysis::AccessPath;
using analysis::ValueFlow;

// What a value is computed from.
struct Sources {
  bool fragCoord = false;  // gl_FragCoord / SV_Position
  bool varying = false;    // another fragment input (full-screen UV, interpolated clip position)
  bool texel = false;      // an image sample, fetch or read
  bool uniform = false;    // uniform, push-constant or specialization-constant data
  bool constant = false;
  bool other = false;      // anything the analysis does not see through
  bool arithmetic = false;            // computed, not only moved
  bool constantOtherThanOne = false;  // some constant leaf is not the float 1.0
  bool eyeParameter = false;          // stereoshift's own eye parameters: injected code
  // gl_FragCoord.z / SV_Position.z, the fragment's own depth: the same per eye, so `other` as far as
  // a pixel position goes; a forward pass's rebuild reads it as its depth (row_products.cpp).
  bool fragmentDepth = false;
  // Which lanes of gl_FragCoord / of a vector input the value is computed from (bit k: lane k; a
  // whole vector read sets every lane it has): tells a pixel's x from its y.
  uint32_t inputLanes = 0;
  std::set<std::string> inputs, textures, uniforms;
  std::set<uint32_t> products;  // matrix x vector products the value went through

  Sources& operator|=(const Sources& o) {
    fragCoord |= o.fragCoord;
    varying |= o.varying;
    texel |= o.texel;
    uniform |= o.uniform;
    constant |= o.constant;
    other |= o.other;
    arithmetic |= o.arithmetic;
    constantOtherThanOne |= o.constantOtherThanOne;
    eyeParameter |= o.eyeParameter;
    fragmentDepth |= o.fragmentDepth;
    inputLanes |= o.inputLanes;
    inputs.insert(o.inputs.begin(), o.inputs.end());
    textures.insert(o.textures.begin(), o.textures.end());
    uniforms.insert(o.uniforms.begin(), o.uniforms.end());
    products.insert(o.products.begin(), o.products.end());
    return *this;
  }
};

std::string lower(std::string text);
// "a, b, c" ("?" for none).
std::string joined(const std::set<std::string>& names);
// Whether `root` with `path` is gl_FragCoord (a built-in variable, or the member of an input block).
bool isFragCoord(const spirv::Module& m, uint32_t root, const AccessPath& path);
// A variable (and the member a path starts with) as the source names it.
std::string describe(const spirv::Module& m, uint32_t root, const AccessPath& path);

// The leaves of "what is this computed from" for this pass (the rules of the backward engine).
class SourceRules {
 public:
  // `eyeParameters`: the injected eye-parameter variables / constants. `opaqueProducts`: products
  // whose result counts as computed from nothing (the fixed unprojections, when asking what else
  // a value depends on).
  SourceRules(const ValueFlow& flow, bool hlsl, std::set<uint32_t> eyeParameters, std::set<uint32_t> opaqueProducts)
      : flow_(flow), hlsl_(hlsl), eyeParameters_(std::move(eyeParameters)), opaqueProducts_(std::move(opaqueProducts)) {}

  Sources unknown() const;
  std::optional<Sources> leaf(const spirv::Instruction& def, const AccessPath&) const;
  Sources moduleVariable(const spirv::Instruction& variable, const AccessPath& path) const;
  void computed(const spirv::Instruction& def, Sources& s) const;

 private:
  const ValueFlow& flow_;
  bool hlsl_;
  std::set<uint32_t> eyeParameters_, opaqueProducts_;

  std::string imageName(uint32_t image) const;
};

// What a value (or one element of it, by access path) of the real module is computed from: the
// backward engine of the shared value flow with this pass's leaves. Loads look at every store that
// may reach them, whatever the control flow (an over-approximation: a value counts as computed
// from every source it may come from).
class SourceAnalysis {
 public:
  SourceAnalysis(const ValueFlow& flow, bool hlsl, std::set<uint32_t> eyeParameters,
                 std::set<uint32_t> opaqueProducts = {})
      : rules_(flow, hlsl, std::move(eyeParameters), std::move(opaqueProducts)), engine_(flow, rules_) {}
  Sources value(uint32_t id, AccessPath path = {}) { return engine_.value(id, std::move(path)); }

 private:
  SourceRules rules_;
  analysis::BackwardFlow<Sources, SourceRules> engine_;
};

}  // namespace stereoshift::deferred
