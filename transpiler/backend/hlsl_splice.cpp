// This turns an HLSL geometry or domain shader into its stereo version by splicing text into it
// (see hlsl_splice.h): checks the options, scans and parses the file, and hands it to the
// rewriter of its stage; the pieces live in hlsl_splice/.
#include "transpiler/backend/hlsl_splice.h"

#include "transpiler/backend/hlsl_splice/edit_buffer.h"
#include "transpiler/backend/hlsl_splice/rewriters.h"
#include "transpiler/backend/hlsl_splice/scanner.h"
#include "transpiler/backend/hlsl_splice/top_level.h"

#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace stereoshift {

namespace {

using namespace hlsl_splice;

std::optional<SpliceError> checkOptions(const HlslSpliceOptions& opt) {
  if (!isValidIdentifier(opt.entryPoint)) {
    return SpliceError{npos, "invalid entry point name '" + opt.entryPoint + "'"};
  }
  std::vector<std::string> names = {opt.cbufferName, opt.eyeSignName, opt.separationName, opt.convergenceName};
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
  std::vector<const Function*> entries;
  for (const auto& f : top.functions) {
    if (view.text(f.nameTok) == options.entryPoint) entries.push_back(&f);
  }
  if (entries.empty()) return SpliceError{npos, "entry point '" + options.entryPoint + "' not found"};
  SpliceUnit unit{options, view, top, edits};
  auto err = options.geometry ? rewriteGeometry(unit, entries) : rewriteDomain(unit, entries);
  *sites = unit.sites;
  return err;
}

}  // namespace

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
    if (err->offset != npos) view.locate(err->offset, result.line, result.column);
    return result;
  }
  result.ok = true;
  result.text = edits.apply();
  result.sites = sites;
  return result;
}

}  // namespace stereoshift
