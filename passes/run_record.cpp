// See run_record.h.
#include "passes/run_record.h"

#include <algorithm>

namespace stereoshift {

const char* toString(PassResult result) {
  switch (result) {
    case PassResult::Unchanged: return "unchanged";
    case PassResult::Changed: return "changed";
    case PassResult::Failed: return "failed";
  }
  return "?";
}

const char* toString(Classification c) {
  switch (c) {
    case Classification::Perspective: return "perspective";
    case Classification::ConstantW1: return "2d-constant-w";
    case Classification::AlreadyStereo: return "already-stereo";
    case Classification::Intermediate: return "intermediate-stage";
    case Classification::NoPositionStage: return "no-position-stage";
    case Classification::NoPositionOutput: return "no-position-output";
    case Classification::NoVertexEmitted: return "no-vertex-emitted";
  }
  return "?";
}

const PassStatus* RunRecord::status(const std::string& name) const {
  for (const auto& pass : passes)
    if (pass.name == name) return &pass;
  return nullptr;
}

bool RunRecord::changed(const std::string& name) const {
  const PassStatus* pass = status(name);
  return pass && pass->result == PassResult::Changed;
}

std::vector<std::string> RunRecord::passesWithEditsBeyond(EditSet rendered) const {
  std::vector<std::string> beyond;
  for (const auto& pass : passes)
    if (pass.result == PassResult::Changed && (pass.edits & ~rendered) != 0) beyond.push_back(pass.name);
  std::sort(beyond.begin(), beyond.end());
  return beyond;
}

bool RunRecord::madeEdit(EditKind kind) const {
  return std::any_of(passes.begin(), passes.end(), [&](const PassStatus& pass) { return hasEdit(pass.edits, kind); });
}

std::string describeEdits(EditSet set) {
  static constexpr std::pair<EditKind, const char*> kNames[] = {
      {EditKind::EyeParameters, "eye parameters"},
      {EditKind::PositionShift, "position shift"},
      {EditKind::DerivedOutputShift, "derived-output shift"},
      {EditKind::PositionAtDepth, "position at depth"},
      {EditKind::SinglePassEye, "single-pass eye"},
      {EditKind::PerEyeCamera, "per-eye camera"},
      {EditKind::UnprojectionCorrection, "unprojection correction"},
  };
  std::string text;
  for (const auto& [kind, name] : kNames)
    if (hasEdit(set, kind)) text += (text.empty() ? "" : ", ") + std::string(name);
  return text.empty() ? "none" : text;
}

}  // namespace stereoshift
