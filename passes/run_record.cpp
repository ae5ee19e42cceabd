// See run_record.h.
#include "passes/run_record.h"

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

}  // namespace stereoshift
