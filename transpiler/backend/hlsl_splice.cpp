// This turns an HLSL vertex, geometry or domain shader into its stereo version by splicing text into it
// (see hlsl_splice.h): checks the options, scans and parses the file, and hands it to the
// rewriter of its stage; the pieces live in hlsl_splice/.
#include "transpiler/backend/hlsl_splice.h"

#include "transpiler/backend/hlsl_splice/edit_buffer.h"
#include "transpiler/backend/hlsl_splice/rewriters.h"
#include "transpiler/backend/hlsl_splice/token_view.h"
#include "transpiler/backend/hlsl_splice/top_level.h"
#include "transpiler/source/stage_rules.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace stereoshift {

namespace {

using namespace hlsl_splice;

std::optional<SpliceError> checkOptions(const HlslSpliceOptions& opt) {
  bool entriesListed = opt.vertex && !opt.vertexEntries.empty();  // each checked where it is looked up
  if (!entriesListed && !isValidIdentifier(opt.entryPoint)) {
    return SpliceError{npos, "invalid entry point name '" + opt.entryPoint + "'"};
  }
  std::vector<std::string> names = {opt.cbufferName, opt.eyeSignName, opt.separationName, opt.convergenceName};
  if (opt.stereoParamsTexture) names = {opt.cbufferName};  // the others are the texel's components
  for (const auto& n : names) {
    if (!isValidIdentifier(n)) return SpliceError{npos, "invalid stereo parameter name '" + n + "'"};
  }
  if (std::set<std::string>(names.begin(), names.end()).size() != names.size()) {
    return SpliceError{npos, "the cbuffer and stereo parameter names must be distinct"};
  }
  if (opt.cutoff == HlslSpliceOptions::Cutoff::Epsilon && !(std::isfinite(opt.epsilon) && opt.epsilon > 0.0f)) {
    return SpliceError{npos, "the w cutoff epsilon must be a positive finite number"};
  }
  return std::nullopt;
}

std::optional<SpliceError> splice(const HlslSpliceOptions& options, const TokenView& view, EditBuffer& edits,
                                  int* sites) {
  TopLevel top;
  if (auto err = parseTopLevel(view, top)) return err;
  HlslSpliceOptions effective = options;
  if (options.stereoParamsTexture) {
    // The dump's own declaration (its "3Dmigoto declarations") is the one 3Dmigoto binds; any other
    // resource at t125 would be shadowed by the one declared here.
    effective.declareStereoParams = !top.names.count("StereoParams");
    for (size_t k = 0; effective.declareStereoParams && k + 2 < view.tokens.size(); ++k)
      if (view.isWord(k, "register") && view.isPunct(k + 1, '(') && lower(view.text(k + 2)) == "t125")
        return SpliceError{view.tokens[k + 2].begin,
                           "register(t125) is taken by another resource: 3Dmigoto's StereoParams texture lives there", true};
  }
  SpliceUnit unit{effective, view, top, edits};
  if (options.vertex) {
    std::vector<HlslSplicedEntry> wanted = options.vertexEntries;
    if (wanted.empty()) wanted.push_back({options.entryPoint, {}});
    std::vector<VertexEntry> vertexEntries;
    for (const auto& w : wanted) {
      if (!isValidIdentifier(w.name)) return SpliceError{npos, "invalid entry point name '" + w.name + "'"};
      VertexEntry entry{w, {}};
      for (const auto& f : top.functions) {
        if (view.text(f.nameTok) == w.name) entry.definitions.push_back(&f);
      }
      if (entry.definitions.empty()) return SpliceError{npos, "entry point '" + w.name + "' not found"};
      vertexEntries.push_back(std::move(entry));
    }
    auto err = rewriteVertex(unit, vertexEntries);
    *sites = unit.sites;
    return err;
  }
  std::vector<const Function*> entries;
  for (const auto& f : top.functions) {
    if (view.text(f.nameTok) == options.entryPoint) entries.push_back(&f);
  }
  if (entries.empty()) return SpliceError{npos, "entry point '" + options.entryPoint + "' not found"};
  auto err = options.geometry ? rewriteGeometry(unit, entries) : rewriteDomain(unit, entries);
  *sites = unit.sites;
  return err;
}

// The stage a function's signature says, or Unknown.
Stage stageOfSignature(const TokenView& view, const TopLevel& top, const Function& f) {
  bool domain = false, controlPoints = false, threads = false;
  for (const auto& a : f.attrs) {
    for (size_t t = a.open + 1; t < a.close; ++t) {
      if (view.isWord(t, "domain")) domain = true;
      if (view.isWord(t, "outputcontrolpoints") || view.isWord(t, "patchconstantfunc")) controlPoints = true;
      if (view.isWord(t, "numthreads")) threads = true;
    }
  }
  if (threads) return Stage::Compute;
  if (domain) return controlPoints ? Stage::TessControl : Stage::TessEvaluation;
  for (const auto& p : f.params) {
    if (!p.streamElement.empty()) return Stage::Geometry;
  }
  std::string returnType;
  for (size_t t = f.typeBegin; t < f.nameTok; ++t) {
    if (view.isPunct(t, '<')) break;
    if (view.isIdent(t) && !modifierWords().count(std::string(view.text(t)))) returnType = std::string(view.text(t));
  }
  std::string semantic = f.semTok != npos ? lower(view.text(f.semTok)) : "";
  if (isPositionSemantic(semantic) || top.positionPath(returnType)) return Stage::Vertex;
  for (const auto& p : f.params) {
    if (p.isOut && (isPositionSemantic(p.semantic) || top.positionPath(p.typeName))) return Stage::Vertex;
  }
  if (semantic.starts_with("sv_target") || semantic.starts_with("sv_depth")) return Stage::Fragment;
  for (const auto& p : f.params) {
    if (p.isOut && lower(p.semantic).starts_with("sv_target")) return Stage::Fragment;
  }
  return Stage::Unknown;
}

}  // namespace

std::vector<HlslEntryPoint> findHlslEntryPoints(const std::string& source) {
  TokenView view(source);
  TopLevel top;
  if (view.scan() || parseTopLevel(view, top)) return {};
  // Techniques first: what they compile, they name with its profile.
  std::map<std::string, Stage> byTechnique;
  for (size_t k = 0; k + 5 < view.tokens.size(); ++k) {
    if (!view.isWord(k, "CompileShader") || !view.isPunct(k + 1, '(') || !view.isIdent(k + 2) ||
        !view.isPunct(k + 3, ',') || !view.isIdent(k + 4) || !view.isPunct(k + 5, '('))
      continue;
    byTechnique.emplace(std::string(view.text(k + 4)), stageFromHlslProfile(view.text(k + 2)));
  }
  // Effects 9: `VertexShader = compile vs_3_0 Name();`
  for (size_t k = 0; k + 3 < view.tokens.size(); ++k) {
    if (lower(view.text(k)) != "compile" || !view.isIdent(k + 1) || !view.isIdent(k + 2) || !view.isPunct(k + 3, '('))
      continue;
    byTechnique.emplace(std::string(view.text(k + 2)), stageFromHlslProfile(view.text(k + 1)));
  }
  // A function another function calls is a helper, not an entry point (`VSOut transform(...)`
  // called by the real entry point has an entry's signature too).
  std::set<std::string> called;
  for (const auto& f : top.functions) {
    for (size_t t = f.bodyOpen + 1; t + 1 < f.bodyClose; ++t) {
      if (view.isIdent(t) && view.isPunct(t + 1, '(')) called.insert(std::string(view.text(t)));
    }
  }
  std::vector<HlslEntryPoint> found;
  for (const auto& f : top.functions) {
    std::string name(view.text(f.nameTok));
    if (std::any_of(found.begin(), found.end(), [&](const HlslEntryPoint& e) { return e.name == name; })) continue;
    if (called.count(name) && !byTechnique.count(name)) continue;
    if (auto it = byTechnique.find(name); it != byTechnique.end() && it->second != Stage::Unknown) {
      found.push_back({name, it->second, "technique"});
    } else if (Stage stage = stageOfSignature(view, top, f); stage != Stage::Unknown) {
      found.push_back({name, stage, "signature"});
    }
  }
  return found;
}

void useStereoParamsTexture(HlslSpliceOptions& options) {
  options.stereoParamsTexture = true;
  options.cbufferName = std::string(kPrefix) + "_stereo";
  options.eyeSignName.clear();  // the separation carries the eye's sign
  options.separationName = options.cbufferName + ".x";
  options.convergenceName = options.cbufferName + ".y";
}

HlslSpliceResult spliceHlslStereo(const std::string& source, const HlslSpliceOptions& options) {
  HlslSpliceResult result;
  TokenView view(source);
  EditBuffer edits(source);
  int sites = 0;
  std::optional<SpliceError> err = checkOptions(options);
  if (!err) err = view.scan();
  if (!err) err = splice(options, view, edits, &sites);
  if (err) {
    result.error = err->message;
    result.clash = err->clash;
    if (err->offset != npos) view.locate(err->offset, result.line, result.column);
    return result;
  }
  result.ok = true;
  result.text = edits.apply();
  result.sites = sites;
  return result;
}

}  // namespace stereoshift
