// Depth reprojection against the ground truth on lavapipe (`stereoshift reproject`, ctest
// execution.reproject): the scene of reproject_scene.h drawn per eye with the stereo-shifted shaders
// is the truth; the same scene drawn once from the source view (one eye, or the centre view) and
// reprojected by the generated shaders must match it.
//
// The bound, derived rather than tuned: with the depth read exactly and the bracket refined below a
// pixel, the pass takes the source texel containing the solved position, whose centre is at most
// half a source pixel from it; on the scene's surfaces (constant depth along a row) that lands within
// half a target pixel of the truth's sample. Its colour then lies between the truth pixel's and a
// horizontal neighbour's, so a pixel can be off by more than 8 levels only where the truth itself
// steps by more than 8 to a horizontal neighbour. Hence, outside the disoccluded area (found from the
// truth's depth, not from the pass): wrong pixels <= such edge pixels; and the image must beat showing
// the source unchanged (no reprojection) by at least 6 dB.
#include "test/harness/reproject_scene.h"

#include <gtest/gtest.h>

#include <iomanip>
#include <iostream>

using namespace stereoshift;
using namespace stereoshift::reproject_scene;

namespace {

class Reproject : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string error;
    context_ = VulkanContext::create(&error);
    setupError_ = error;
    scene_ = makeScene();
  }
  static void TearDownTestSuite() { context_.reset(); }
  static inline std::unique_ptr<VulkanContext> context_;
  static inline std::string setupError_;
  static inline Scene scene_;
};

void expectWithinBound(const Comparison& c, const std::string& what) {
  std::cout << std::fixed << std::setprecision(2) << "[reproject] " << what << ": PSNR " << c.psnr << " dB (mono "
            << c.monoPsnr << " dB), disoccluded " << 100.0 * c.disoccluded / c.pixels << "%, off by > 8 outside: "
            << 100.0 * c.wrong / c.pixels << "% (bound: edge pixels " << 100.0 * c.edgePixels / c.pixels
            << "%), floor " << c.floorWrong << "/" << c.floorPixels << " (bound " << c.floorEdges << ")\n";
  EXPECT_LE(c.wrong, c.edgePixels) << what << ": more wrong pixels than the truth has sub-pixel-sensitive edges";
  EXPECT_GE(c.psnr, c.monoPsnr + 6.0) << what << ": not clearly better than no reprojection";
  EXPECT_GT(c.floorPixels, c.pixels / 10) << what << ": the floor should cover a good part of the image";
  EXPECT_LE(c.floorWrong, c.floorEdges) << what << ": errors on the slanted plane (depth striations?)";
}

TEST_F(Reproject, OneEyeSourceMatchesTruthForBothEyes) {
  ASSERT_TRUE(context_) << setupError_;
  ASSERT_TRUE(scene_.error.empty()) << scene_.error;
  DepthSetup depth;
  RenderResult left = renderEye(*context_, scene_, -1, depth), right = renderEye(*context_, scene_, 1, depth);
  ASSERT_TRUE(left.ok() && right.ok()) << left.error << right.error;
  // Left -> right and right -> left: the search runs the other way, objects in front of the screen included.
  for (ReprojectSource source : {ReprojectSource::LeftEye, ReprojectSource::RightEye}) {
    const bool fromLeft = source == ReprojectSource::LeftEye;
    ReprojectOptions options = passOptions(depth, source);
    options.maskOutput = true;  // the mask output must not disturb colour output 0
    Pass pass = makePass(options);
    ASSERT_TRUE(pass.error.empty()) << pass.error;
    const RenderResult& from = fromLeft ? left : right;
    const RenderResult& truth = fromLeft ? right : left;
    const double target = fromLeft ? 1 : -1;
    RenderResult synthesized = reproject(*context_, pass, from, target);
    ASSERT_TRUE(synthesized.ok()) << synthesized.error;
    Comparison c = compare(truth, from, synthesized, target, -target, false);
    expectWithinBound(c, fromLeft ? "left -> right" : "right -> left");
    // The source eye itself comes through unchanged (k = 0: every pixel is its own hit).
    RenderResult same = reproject(*context_, pass, from, -target);
    ASSERT_TRUE(same.ok());
    EXPECT_EQ(same.pixels, from.pixels);
    if (fromLeft) {
      const size_t n = size_t(kWidth) * kHeight;
      std::vector<uint8_t> anaglyph = harness::anaglyph(left.pixels, synthesized.pixels, n);
      EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/reproject_left.png", kWidth, kHeight, left.pixels.data()));
      EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/reproject_right_truth.png", kWidth, kHeight, right.pixels.data()));
      EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/reproject_right_synthesized.png", kWidth, kHeight, synthesized.pixels.data()));
      EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/reproject_difference.png", kWidth, kHeight, c.difference.data()));
      EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/reproject_disocclusion.png", kWidth, kHeight, c.mask.data()));
      EXPECT_TRUE(writePng(IMAGE_OUT_DIR "/reproject_anaglyph.png", kWidth, kHeight, anaglyph.data()));
    }
  }
}

TEST_F(Reproject, CentreViewToBothEyesHasSmallerHoles) {
  ASSERT_TRUE(context_) << setupError_;
  ASSERT_TRUE(scene_.error.empty()) << scene_.error;
  DepthSetup depth;
  RenderResult centre = renderEye(*context_, scene_, 0, depth), left = renderEye(*context_, scene_, -1, depth),
               right = renderEye(*context_, scene_, 1, depth);
  ASSERT_TRUE(centre.ok() && left.ok() && right.ok());
  Pass centrePass = makePass(passOptions(depth, ReprojectSource::Centre));
  Pass eyePass = makePass(passOptions(depth, ReprojectSource::LeftEye));
  ASSERT_TRUE(centrePass.error.empty() && eyePass.error.empty()) << centrePass.error << eyePass.error;
  RenderResult fromLeft = reproject(*context_, eyePass, left, 1);
  ASSERT_TRUE(fromLeft.ok());
  const size_t oneEyeHoles = compare(right, left, fromLeft, 1, -1, false).disoccluded;
  for (double target : {-1.0, 1.0}) {
    RenderResult synthesized = reproject(*context_, centrePass, centre, target);
    ASSERT_TRUE(synthesized.ok()) << synthesized.error;
    Comparison c = compare(target < 0 ? left : right, centre, synthesized, target, 0, false);
    expectWithinBound(c, target < 0 ? "centre -> left" : "centre -> right");
    // Half the parallax per eye: the holes are narrower than those of the full eye-to-eye step.
    EXPECT_LT(c.disoccluded, oneEyeHoles);
  }
}

// Depth quantisation: the same left -> right reprojection from D24 and from D32F depth, standard and
// reversed-Z; the floor (a plane slanted in depth) must meet the bound with each.
TEST_F(Reproject, DepthEncodingsGiveNoStriations) {
  ASSERT_TRUE(context_) << setupError_;
  ASSERT_TRUE(scene_.error.empty()) << scene_.error;
  for (bool reversed : {false, true})
    for (bool d24 : {true, false}) {
      DepthSetup depth{reversed, d24};
      RenderResult left = renderEye(*context_, scene_, -1, depth), right = renderEye(*context_, scene_, 1, depth);
      ASSERT_TRUE(left.ok() && right.ok());
      Pass pass = makePass(passOptions(depth, ReprojectSource::LeftEye));
      ASSERT_TRUE(pass.error.empty()) << pass.error;
      RenderResult synthesized = reproject(*context_, pass, left, 1);
      ASSERT_TRUE(synthesized.ok());
      Comparison c = compare(right, left, synthesized, 1, -1, reversed);
      expectWithinBound(c, std::string(d24 ? "D24" : "D32F") + (reversed ? " reversed-Z" : " standard"));
    }
}

}  // namespace

namespace {

// The numbers behind the pictures: source images made on the host whose colour names the source
// column (R = x mod 256, G = x / 256) over a depth plane (constant w = 7) and a depth ramp (a plane
// slanted in depth: 1/w affine in x, w from 3 to 20), encoded by each kind the pass reads. For each
// target pixel the column the pass took must be the one containing the exact reprojection q, the
// solution of q + k*(1 - C/w(q)) = P with 1/w(q) continuous: its centre within half a pixel of q (and
// a twentieth more, the ramp's own change of depth across the texel the search reads it from).
struct Encoding {
  const char* name;
  ReprojectDepth kind;
  bool reversed;
};

float encode(const Encoding& e, double w, double n, double f) {
  if (e.kind == ReprojectDepth::Linear) return float(w);
  // Window depth in [0, 1], affine in 1/w: 0 at the near plane (1 with reversed-Z), 1 at the far one.
  double d = (1.0 / n - 1.0 / w) / (1.0 / n - 1.0 / f);
  return float(e.reversed ? 1.0 - d : d);
}

TEST_F(Reproject, SolvedPositionsWithinHalfAPixelForEveryEncoding) {
  ASSERT_TRUE(context_) << setupError_;
  const double n = 0.1, f = 50.0;
  const Encoding encodings[] = {{"linear", ReprojectDepth::Linear, false},
                                {"zero-to-one", ReprojectDepth::ZeroToOne, false},
                                {"zero-to-one reversed", ReprojectDepth::ZeroToOne, true},
                                {"minus-one-to-one", ReprojectDepth::MinusOneToOne, false},
                                {"minus-one-to-one reversed", ReprojectDepth::MinusOneToOne, true}};
  for (const Encoding& e : encodings)
    for (bool ramp : {false, true})
      for (double sourceSign : {-1.0, 1.0}) {
        ReprojectOptions options;
        options.source = sourceSign < 0 ? ReprojectSource::LeftEye : ReprojectSource::RightEye;
        options.depth = e.kind;
        options.reversedZ = e.reversed;
        options.nearPlane = n;
        options.farPlane = f;
        options.target = TargetLanguage::Spirv;
        Pass pass = makePass(options);
        ASSERT_TRUE(pass.error.empty()) << pass.error;
        // 1/w(x) = a + b*x at continuous x (texel centres at column + 0.5).
        const double a = ramp ? 1.0 / 3.0 : 1.0 / 7.0, b = ramp ? (1.0 / 20.0 - 1.0 / 3.0) / kWidth : 0.0;
        RenderResult source;
        source.width = kWidth;
        source.height = kHeight;
        source.pixels.resize(size_t(kWidth) * kHeight * 4);
        source.depth.resize(size_t(kWidth) * kHeight);
        for (uint32_t y = 0; y < kHeight; ++y)
          for (uint32_t x = 0; x < kWidth; ++x) {
            uint8_t* p = &source.pixels[(size_t(y) * kWidth + x) * 4];
            p[0] = uint8_t(x & 255);
            p[1] = uint8_t(x >> 8);
            p[2] = 0;
            p[3] = 255;
            source.depth[size_t(y) * kWidth + x] = encode(e, 1.0 / (a + b * (x + 0.5)), n, f);
          }
        const double target = -sourceSign;
        RenderResult out = reproject(*context_, pass, source, target);
        ASSERT_TRUE(out.ok()) << out.error;
        const double k = (target - sourceSign) * kSeparation * 0.5 * kWidth;
        double worst = 0;
        int checked = 0;
        for (uint32_t x = 0; x < kWidth; ++x) {
          const double P = x + 0.5;
          const double q = (P - k + k * kConvergence * a) / (1.0 - k * kConvergence * b);
          if (q < 1.0 || q > kWidth - 1.0) continue;  // the source does not see it: screen edge
          const uint8_t* got = out.pixel(x, kHeight / 2);
          const double taken = got[0] + 256.0 * got[1] + 0.5;
          worst = std::max(worst, std::abs(taken - q));
          ++checked;
        }
        const std::string what = std::string(e.name) + (ramp ? " ramp" : " plane") + (sourceSign < 0 ? " L->R" : " R->L");
        EXPECT_GT(checked, int(kWidth) / 2) << what;
        EXPECT_LE(worst, 0.55) << what << ": a solved position is off the exact reprojection";
        for (uint32_t y = 0; y < kHeight; ++y)
          ASSERT_EQ(0, std::memcmp(out.pixel(0, y), out.pixel(0, 0), kWidth * 4)) << what << ": rows differ";
      }
}

}  // namespace
