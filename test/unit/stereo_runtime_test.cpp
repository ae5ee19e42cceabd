// include/stereoshift/stereo_runtime.h checked numerically in double precision: every formula
// against an independent statement of what it must do (the clip-space shift, the projection
// centre of the stereo view-projection, the planes of the eye frustums).
#include <stereoshift/stereo_runtime.h>

#include <gtest/gtest.h>

#include <cstddef>

using namespace stereoshift::runtime;

namespace {

using M = Mat4<double>;
using V4 = Vec4<double>;

// GL perspective (right-handed view, w = -z), column-major; off-centre so p02 != 0 is covered.
M glPerspective(double fovY, double aspect, double n, double f, double skewX) {
  double t = 1.0 / std::tan(fovY / 2);
  M p{};
  p[0] = t / aspect;
  p[5] = t;
  p[8] = skewX;
  p[10] = (f + n) / (n - f);
  p[11] = -1;
  p[14] = 2 * f * n / (n - f);
  return p;
}

// D3D left-handed perspective in the row-vector convention (clip = v * M, w = +z), row-major.
M d3dPerspectiveRowVector(double fovY, double aspect, double n, double f) {
  double t = 1.0 / std::tan(fovY / 2);
  M m{};
  m[0] = t / aspect;               // M[0][0]
  m[5] = t;                        // M[1][1]
  m[10] = f / (f - n);             // M[2][2]
  m[11] = 1;                       // M[2][3]: w = z
  m[14] = -n * f / (f - n);        // M[3][2]
  return m;
}

V4 rowVectorTimes(const V4& v, const M& rowMajor) {  // v * M, M row-major
  V4 out{};
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < 4; ++k) out[c] += v[k] * rowMajor[4 * k + c];
  return out;
}

// A rigid camera: rotated about y and x, placed at `eye`; returns the view matrix (world -> view).
M lookFrom(const Vec3<double>& eye, double yaw, double pitch) {
  double cy = std::cos(yaw), sy = std::sin(yaw), cp = std::cos(pitch), sp = std::sin(pitch);
  // Camera-to-world rotation R = Ry(yaw) * Rx(pitch); columns are the right, up, back axes.
  double r[3][3] = {{cy, sy * sp, sy * cp}, {0, cp, -sp}, {-sy, cy * sp, cy * cp}};
  M invView{};
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row) invView[4 * c + row] = r[row][c];
  invView[12] = eye[0];
  invView[13] = eye[1];
  invView[14] = eye[2];
  invView[15] = 1;
  return inverse(invView);
}

constexpr double kS = 0.065, kC = 3.5;

TEST(StereoRuntime, StereoParamsMatchesTheInjectedBlockLayout) {
  EXPECT_EQ(sizeof(StereoParams), 32u);
  EXPECT_EQ(offsetof(StereoParams, eyeSign), 0u);
  EXPECT_EQ(offsetof(StereoParams, separation), 4u);
  EXPECT_EQ(offsetof(StereoParams, convergence), 8u);
  EXPECT_EQ(offsetof(StereoParams, hudDepth), 12u);
  EXPECT_EQ(offsetof(StereoParams, eyeOffsetX), 16u);
  EXPECT_EQ(offsetof(StereoParams, eyeOffsetY), 20u);
  EXPECT_EQ(offsetof(StereoParams, eyeOffsetZ), 24u);
  EXPECT_EQ(offsetof(StereoParams, projScaleX), 28u);
  StereoParams mono;
  EXPECT_EQ(mono.eyeSign, 0.0f);  // mono until the application says otherwise
}

TEST(StereoRuntime, GlStereoProjectionIsTheMonoProjectionFollowedByTheShift) {
  M p = glPerspective(0.9, 16.0 / 9.0, 0.1, 500.0, 0.03);
  for (double e : {-1.0, 1.0, 0.0}) {
    M stereo = stereoProjectionGL(p, e, kS, kC);
    // docs/stereo-math.md section 1, in GL notation: row 0 = [p00, 0, p02 - e S, -e S C].
    EXPECT_DOUBLE_EQ(element(stereo, 0, 0), element(p, 0, 0));
    EXPECT_DOUBLE_EQ(element(stereo, 0, 2), element(p, 0, 2) - e * kS);
    EXPECT_DOUBLE_EQ(element(stereo, 0, 3), -e * kS * kC);
    for (double depth : {0.2, kC / 2, kC, 2 * kC, 40.0, 450.0})
      for (double x : {-3.0, 0.0, 1.7}) {
        V4 v = {x * depth / 4, 0.3 * depth, -depth, 1};
        V4 mono = transform(p, v), clip = transform(stereo, v);
        EXPECT_NEAR(clip[0], mono[0] + e * kS * (mono[3] - kC), 1e-12 * (1 + std::fabs(mono[0])));
        for (int k = 1; k < 4; ++k) EXPECT_EQ(clip[k], mono[k]);
      }
  }
}

TEST(StereoRuntime, D3dStereoProjectionIsTheMonoProjectionFollowedByTheShift) {
  M m = d3dPerspectiveRowVector(1.0, 1.5, 0.5, 1000.0);
  for (double e : {-1.0, 1.0}) {
    M stereo = stereoProjectionD3D(m, e, kS, kC);
    EXPECT_DOUBLE_EQ(stereo[4 * 2 + 0], e * kS);  // M[2][0] = m20 + e S for w = +z
    for (double depth : {0.7, kC, 9.0, 800.0}) {
      V4 v = {0.4 * depth, -0.2 * depth, depth, 1};
      V4 mono = rowVectorTimes(v, m), clip = rowVectorTimes(v, stereo);
      EXPECT_NEAR(clip[0], mono[0] + e * kS * (mono[3] - kC), 1e-12 * (1 + std::fabs(mono[0])));
      for (int k = 1; k < 4; ++k) EXPECT_EQ(clip[k], mono[k]);
    }
  }
}

// The eye offset puts the camera at the projection centre of the stereo view-projection: every
// point on a ray from C_eye lands on one pixel of that eye's image (and not from the mono camera).
TEST(StereoRuntime, EyeOffsetIsTheCentreOfTheStereoViewProjection) {
  Vec3<double> camera = {2.0, 1.5, -4.0};
  M view = lookFrom(camera, 0.6, -0.25);
  M invView = inverse(view);
  M p = glPerspective(1.1, 1.25, 0.05, 800.0, 0.0);
  for (double e : {-1.0, 1.0}) {
    M stereoVP = multiply(stereoProjectionGL(p, e, kS, kC), view);
    Vec3<double> offset = eyeOffsetFromInverseView(invView, element(p, 0, 0), e, kS, kC);
    Vec3<double> fromVP = eyeOffsetFromInverseViewProjection(inverse(multiply(p, view)), e, kS, kC);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(offset[k], fromVP[k], 1e-12);
    // |offset| = S C / P00 (the camera moves along its right axis).
    double length = std::sqrt(offset[0] * offset[0] + offset[1] * offset[1] + offset[2] * offset[2]);
    EXPECT_NEAR(length, kS * kC / element(p, 0, 0), 1e-12);

    V4 centre = {camera[0] + offset[0], camera[1] + offset[1], camera[2] + offset[2], 1};
    V4 atCentre = transform(stereoVP, centre);
    EXPECT_NEAR(atCentre[0], 0, 1e-12);  // x = y = w = 0: the centre of projection
    EXPECT_NEAR(atCentre[1], 0, 1e-12);
    EXPECT_NEAR(atCentre[3], 0, 1e-12);

    const Vec3<double> directions[] = {{0.3, -0.1, 1.0}, {-0.5, 0.2, 0.8}, {0.05, 0.4, 0.9}};
    for (const auto& d : directions) {
      // The direction in world space: the camera looks down its -z.
      V4 dir = transform(invView, {d[0], d[1], -d[2], 0});
      double ndcX = 0, ndcY = 0, monoSpread = 0, firstMonoX = 0;
      bool first = true;
      for (double t : {kC / 2, kC, 2 * kC, 10 * kC, 100 * kC}) {
        V4 point = {centre[0] + t * dir[0], centre[1] + t * dir[1], centre[2] + t * dir[2], 1};
        V4 clip = transform(stereoVP, point);
        // The same ray cast from the mono camera: x/w drifts with depth (the parallax).
        V4 monoPoint = {camera[0] + t * dir[0], camera[1] + t * dir[1], camera[2] + t * dir[2], 1};
        V4 monoClip = transform(stereoVP, monoPoint);
        if (first) {
          ndcX = clip[0] / clip[3];
          ndcY = clip[1] / clip[3];
          firstMonoX = monoClip[0] / monoClip[3];
          first = false;
        }
        EXPECT_NEAR(clip[0] / clip[3], ndcX, 1e-12);
        EXPECT_NEAR(clip[1] / clip[3], ndcY, 1e-12);
        monoSpread = std::max(monoSpread, std::fabs(monoClip[0] / monoClip[3] - firstMonoX));
      }
      EXPECT_GT(monoSpread, 0.01) << "the mono camera would not show the error this offset fixes";
    }
  }
  // Mono: no offset.
  Vec3<double> none = eyeOffsetFromInverseView(invView, element(p, 0, 0), 0.0, kS, kC);
  EXPECT_EQ(none[0] * none[0] + none[1] * none[1] + none[2] * none[2], 0.0);
}

TEST(StereoRuntime, StereoParamsForEyeHoldTheOffset) {
  M view = lookFrom({0, 2, 5}, -0.3, 0.1);
  M p = glPerspective(0.8, 1.0, 0.1, 100.0, 0.0);
  StereoParams right = stereoParamsForEye(1.0, kS, kC, inverse(view), element(p, 0, 0));
  Vec3<double> offset = eyeOffsetFromInverseView(inverse(view), element(p, 0, 0), 1.0, kS, kC);
  EXPECT_EQ(right.eyeSign, 1.0f);
  EXPECT_EQ(right.separation, float(kS));
  EXPECT_EQ(right.convergence, float(kC));
  EXPECT_EQ(right.eyeOffsetX, float(offset[0]));
  EXPECT_EQ(right.eyeOffsetY, float(offset[1]));
  EXPECT_EQ(right.eyeOffsetZ, float(offset[2]));
}

// The compound frustum from the eye frustums themselves: in view space (y = 0) the right eye's
// left plane is where its NDC x is -1, the left eye's right plane where its NDC x is +1.
TEST(StereoRuntime, CullingFrustumOriginIsWhereTheOuterEyePlanesMeet) {
  M p = glPerspective(1.0, 1.6, 0.1, 1000.0, 0.0);
  double p00 = element(p, 0, 0);
  for (double s : {0.01, kS, 0.3}) {
    for (double c : {0.5, kC, 40.0}) {
      M right = stereoProjectionGL(p, 1.0, s, c), left = stereoProjectionGL(p, -1.0, s, c);
      // x of the plane NDC x = edge at eye depth d: solve row0 . (x, 0, -d, 1) = edge * d.
      auto planeX = [](const M& m, double edge, double d) {
        return (edge * d - element(m, 0, 2) * -d - element(m, 0, 3)) / element(m, 0, 0);
      };
      // Both planes cross the view axis at the same depth: the apex.
      double z = cullingFrustumOriginDepth(s, c);
      EXPECT_NEAR(planeX(right, -1, z), 0, 1e-12 * c);
      EXPECT_NEAR(planeX(left, +1, z), 0, 1e-12 * c);
      EXPECT_NEAR(z, c / (1 + 1 / s), 1e-12 * c);  // the talk's form
      // Their slope: the mono one opened by (1 + S).
      double slope = (planeX(left, +1, z + 10) - planeX(left, +1, z)) / 10;
      EXPECT_NEAR(slope, 1 / cullingFrustumP00(p00, s), 1e-12);
      // Beyond the screen they are the outermost planes of the two eyes (the union), in front of
      // it the innermost (what both eyes see).
      for (double d : {1.5 * c, 10 * c})
        EXPECT_GT(planeX(left, +1, d), planeX(right, +1, d));
      for (double d : {0.5 * (z + c), 0.9 * c})
        EXPECT_LT(planeX(left, +1, d), planeX(right, +1, d));
    }
  }
  EXPECT_EQ(cullingFrustumOriginDepth(0.0, kC), 0.0);  // mono: the mono frustum

  // World space: the mono eye moved along the view direction.
  Vec3<double> camera = {1, 2, 3};
  M view = lookFrom(camera, 0.4, 0.2);
  Vec3<double> origin = cullingFrustumOrigin(inverse(view), kS, kC);
  V4 inView = transform(view, {origin[0], origin[1], origin[2], 1});
  EXPECT_NEAR(inView[0], 0, 1e-12);
  EXPECT_NEAR(inView[1], 0, 1e-12);
  EXPECT_NEAR(-inView[2], cullingFrustumOriginDepth(kS, kC), 1e-12);
}

TEST(StereoRuntime, ComfortableDepthRange) {
  auto range = comfortableDepthRange(kC);
  EXPECT_DOUBLE_EQ(range[0], kC / 2);
  EXPECT_DOUBLE_EQ(range[1], 100 * kC);
  // At C/2 the parallax is as large (out of the screen) as the largest behind it (at infinity).
  EXPECT_DOUBLE_EQ(parallax(1.0, kS, kC, range[0]), -kS);
  EXPECT_NEAR(parallax(1.0, kS, kC, range[1]), 0.99 * kS, 1e-15);
  EXPECT_EQ(parallax(1.0, kS, kC, kC), 0.0);
}

TEST(StereoRuntime, SinglePassSetupPerMode) {
  SinglePassSetup s = singlePassSetup(SinglePassMode::Multiview, 5, 3);
  EXPECT_EQ(s.viewMask, 0x3u);
  EXPECT_EQ(s.layerCount, 2u);
  EXPECT_EQ(s.instanceCount, 5u);  // multiview draws every instance once; the views are the eyes
  EXPECT_EQ(s.firstInstance, 3u);
  s = singlePassSetup(SinglePassMode::InstancedLayer, 5, 3);
  EXPECT_EQ(s.viewMask, 0u);
  EXPECT_EQ(s.layerCount, 2u);
  EXPECT_EQ(s.instanceCount, 10u);  // each instance twice, the low bit the eye
  EXPECT_EQ(s.firstInstance, 6u);   // the shader reads (6 + i) >> 1 = 3 + i / 2
  EXPECT_EQ(s.instanceStep, 2u);
  s = singlePassSetup(SinglePassMode::InstancedViewport, 1, 0);
  EXPECT_EQ(s.layerCount, 1u);
  EXPECT_EQ(s.viewportCount, 2u);
  s = singlePassSetup(SinglePassMode::MetalMultiview, 5, 3);
  EXPECT_EQ(s.viewMask, 0u);        // no render-pass view mask in Metal: instancing does it
  EXPECT_EQ(s.instanceCount, 10u);  // the emulated view is (instance - base) % 2
  EXPECT_EQ(s.firstInstance, 3u);   // kept: the shader subtracts the base instance itself
  EXPECT_EQ(s.instanceStep, 2u);
  EXPECT_EQ(s.layerCount, 2u);
  EXPECT_EQ(s.viewMaskBuffer[0], 0u);
  EXPECT_EQ(s.viewMaskBuffer[1], 2u);
  EXPECT_EQ(s.viewMaskBufferIndex, 24u);
  auto halves = sideBySideViewports(1280, 720);
  EXPECT_EQ(halves[0].width, 640);
  EXPECT_EQ(halves[1].x, 640);
  StereoParams p = singlePassParams(0.065f, 3.0f, 1.0f, {0.1f, 0, 0});
  EXPECT_EQ(p.eyeSign, 0.0f);  // the shaders derive it
  EXPECT_EQ(p.separation, 0.065f);
  EXPECT_EQ(p.eyeOffsetX, 0.1f);
}

}  // namespace

// The widened source view for depth reprojection: a point at the final view's edge, shifted by the
// largest parallax the search reads, lands inside the widened image at the same pixel density; the
// central columns are the original view.
TEST(StereoRuntime, WidenedSourceViewCoversTheLargestParallaxAtTheEdges) {
  const M p = glPerspective(1.0, 16.0 / 9.0, 0.1, 100.0, 0.0);
  const int width = 1280;
  const double separation = 0.06, convergence = 3.0;
  for (double difference : {2.0, 1.0}) {
    WidenedSourceView<double> v = widenedSourceView(p, width, difference, separation, 0.5);
    // Margin: |de|*S NDC of the final view, width/2 pixels per NDC unit, rounded up.
    EXPECT_EQ(v.columnsEachSide, int(std::ceil(difference * separation * width / 2)));
    EXPECT_EQ(v.widenedWidth, width + 2 * v.columnsEachSide);
    EXPECT_DOUBLE_EQ(v.extraPixelCost, 2.0 * v.columnsEachSide / width);
    // Same pixel density: a view-space point maps to the same pixel offset from the centre.
    const V4 point = {0.7, 0.2, -5.0, 1.0};
    const V4 mono = transform(p, point), wide = transform(v.projection, point);
    EXPECT_NEAR(mono[0] / mono[3] * width / 2, wide[0] / wide[3] * v.widenedWidth / 2, 1e-9);
    // The shift in pixels is the same with the scaled separation in the widened render.
    const double w = 40.0;
    EXPECT_NEAR(difference * separation * (1 - convergence / w) * width / 2,
                difference * separation * v.separationScale * (1 - convergence / w) * v.widenedWidth / 2, 1e-9);
    // The final view's right edge (NDC 1), read from the farthest source point (x - |de|*S), and its
    // left edge read at x + |de|*S: both inside the widened source.
    const double rightEdgeSource = width / 2.0 + difference * separation * width / 2.0;  // pixels from the centre
    EXPECT_LE(rightEdgeSource, v.widenedWidth / 2.0);
  }
  // A search reaching farther in front than behind widens by that reach.
  WidenedSourceView<double> nearer = widenedSourceView(p, width, 2.0, separation, 1.5);
  EXPECT_EQ(nearer.columnsEachSide, int(std::ceil(2.0 * separation * 1.5 * width / 2)));
}
