// The shift's cutoff maths, written once (core/shift_spec.h): what every printer's guard computes
// in fp32 and what the execution checks compare them with.
#include "core/shift_spec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace stereoshift {
namespace {

TEST(ShiftSpec, AZeroOrNegativeEpsilonIsTheExactRule) {
  EXPECT_EQ(normalisedCutoff(CutoffMode::Epsilon, 0.0f), CutoffMode::Exact);
  EXPECT_EQ(normalisedCutoff(CutoffMode::Epsilon, -1.0f), CutoffMode::Exact);
  EXPECT_EQ(normalisedCutoff(CutoffMode::Epsilon, 1e-5f), CutoffMode::Epsilon);
  EXPECT_EQ(normalisedCutoff(CutoffMode::None, 0.0f), CutoffMode::None);
  EXPECT_EQ(normalisedCutoff(CutoffMode::Exact, 1e-5f), CutoffMode::Exact);
}

TEST(ShiftSpec, TheCutoffKeepsWhatEveryGuardKeeps) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const float below = std::nextafter(1.0f, 0.0f), above = std::nextafter(1.0f, 2.0f);
  struct Case {
    float w;
    bool epsilon, exact, none;  // kept mono under |w - 1| > 1e-5, w != 1, no cutoff
  } cases[] = {
      {1.0f, true, true, false},   {below, true, false, false},  {above, true, false, false},
      {1.00002f, false, false, false}, {0.99998f, false, false, false}, {3.0f, false, false, false},
      {-1.0f, false, false, false}, {0.0f, false, false, false}, {inf, true, true, false},
      {-inf, true, true, false},   {nan, true, true, false},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(cutoffKeepsMono(CutoffMode::Epsilon, 1e-5f, c.w), c.epsilon) << c.w;
    EXPECT_EQ(cutoffKeepsMono(CutoffMode::Exact, 1e-5f, c.w), c.exact) << c.w;
    EXPECT_EQ(cutoffKeepsMono(CutoffMode::Epsilon, 0.0f, c.w), c.exact) << c.w;
    EXPECT_EQ(cutoffKeepsMono(CutoffMode::None, 1e-5f, c.w), c.none) << c.w;
  }
  // |w - 1| is taken in fp32, as the shaders take it: exactly epsilon away is kept (not greater).
  EXPECT_TRUE(cutoffKeepsMono(CutoffMode::Epsilon, 0.5f, 1.5f));
  EXPECT_FALSE(cutoffKeepsMono(CutoffMode::Epsilon, 0.5f, std::nextafter(1.5f, 2.0f)));
}

}  // namespace
}  // namespace stereoshift
