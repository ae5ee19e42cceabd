// The shift's cutoff maths, once: see shift_spec.h.
#include "core/shift_spec.h"

#include <cmath>

namespace stereoshift {

CutoffMode normalisedCutoff(CutoffMode asked, float epsilon) {
  return asked == CutoffMode::Epsilon && epsilon <= 0.0f ? CutoffMode::Exact : asked;
}

bool cutoffKeepsMono(CutoffMode cutoff, float epsilon, float w) {
  switch (normalisedCutoff(cutoff, epsilon)) {
    case CutoffMode::None: return false;
    case CutoffMode::Exact: return w == 1.0f || !std::isfinite(w);
    case CutoffMode::Epsilon: return !(std::fabs(w - 1.0f) > epsilon) || !std::isfinite(w);
  }
  return false;
}

}  // namespace stereoshift
