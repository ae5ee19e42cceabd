// The maths the position-rebuild checks share (deferred_render_test.cpp on lavapipe,
// asm_unprojection_test.cpp on the assembly interpreter): 4x4 matrices in double, and the
// first-order rounding bound of a world position an fp32 shader rebuilds from depth, with and
// without the stereo correction q -= InvM[column 0] * eS * (1 - C q.w).
#pragma once

#include <array>
#include <optional>
#include <cmath>
#include <utility>

namespace stereoshift::harness {

inline constexpr double kUnitRoundoff = 1.0 / (1 << 24);  // fp32, round to nearest

using Mat4 = std::array<double, 16>;  // column-major: m[col * 4 + row]

inline Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k) r[c * 4 + row] += a[k * 4 + row] * b[c * 4 + k];
  return r;
}

// Gauss-Jordan with partial pivoting, in double.
inline Mat4 inverse(const Mat4& m) {
  double a[4][8];
  for (int row = 0; row < 4; ++row)
    for (int c = 0; c < 4; ++c) {
      a[row][c] = m[c * 4 + row];
      a[row][c + 4] = row == c ? 1.0 : 0.0;
    }
  for (int c = 0; c < 4; ++c) {
    int pivot = c;
    for (int row = c + 1; row < 4; ++row)
      if (std::abs(a[row][c]) > std::abs(a[pivot][c])) pivot = row;
    std::swap(a[c], a[pivot]);
    double scale = a[c][c];
    for (double& v : a[c]) v /= scale;
    for (int row = 0; row < 4; ++row) {
      if (row == c) continue;
      double factor = a[row][c];
      for (int k = 0; k < 8; ++k) a[row][k] -= factor * a[c][k];
    }
  }
  Mat4 r;
  for (int row = 0; row < 4; ++row)
    for (int c = 0; c < 4; ++c) r[c * 4 + row] = a[row][c + 4];
  return r;
}

inline std::array<float, 16> toFloat(const Mat4& m) {
  std::array<float, 16> r;
  for (int i = 0; i < 16; ++i) r[i] = static_cast<float>(m[i]);
  return r;
}

inline Mat4 toDouble(const std::array<float, 16>& m) {
  Mat4 r;
  for (int i = 0; i < 16; ++i) r[i] = m[i];
  return r;
}

// The bound on p = fl(q.xyz / q.w) from the bounds dq on q: |dp_i| <= (|dq_i| + |p_i| |dq_w|) / |q_w| + u |p_i|.
inline std::array<double, 3> quotientBound(const std::array<double, 4>& q, const std::array<double, 4>& dq) {
  std::array<double, 3> bound;
  for (int i = 0; i < 3; ++i) {
    const double p = q[i] / q[3];
    bound[i] = (dq[i] + std::abs(p) * dq[3]) / std::abs(q[3]) + kUnitRoundoff * std::abs(p);
  }
  return bound;
}

// First-order bound (unit roundoff u) on |p - p_exact| for the world position a lighting shader
// rebuilds on the GPU, per component, from fp32 inputs:
//   q = fl(A v): each component a 4-term dot product from entries A rounded once from the exact
//     inverse: |dq_i| <= (gamma_4 + u) * sum_j |A_ij v_j|, gamma_4 = 4u/(1 - 4u) (any summation
//     order, with or without fused multiply-adds);
//   the fix adds k = fl(fl(e S) * fl(1 - fl(C q.w))), c = fl(col0 * k), q' = fl(q - c):
//     |dk| <= |eS| (C |dq_w| + u C |q_w| + u |1 - C q_w|) + 2u |k|,
//     |dq'_i| <= |dq_i| + |col0_i| |dk| + 2u |col0_i k| + u |q'_i|;
//   p = fl(q.xyz / q.w): |dp_i| <= (|dq_i| + |p_i| |dq_w|) / |q_w| + u |p_i|.
// v (pixel-centre NDC and the sampled depth) is exact in fp32. Second-order terms are below
// 1e-6 of the bound and ignored.
// `columnScale`: the fix subtracts that much of column 0 (a matrix from UV space: half its column
// of u, InvM's column of NDC x; a power of two, so no rounding of its own).
// `scaleError`: the shader computes the column's scale itself (a half-width it derives from the
// matrix, matrixHalfWidth), off from `columnScale` by at most this much; then k is multiplied by the
// scale in one more rounding, |d(k h)| <= |dk| |h| + |k| scaleError + u |k h|.
inline std::array<double, 3> positionBound(const Mat4& a, const std::array<double, 4>& v, bool fixed, double eyeSeparation,
                                          double convergence, double columnScale = 1.0,
                                          std::optional<double> scaleError = std::nullopt) {
  const double u = kUnitRoundoff, gamma4 = 4 * u / (1 - 4 * u);
  std::array<double, 4> q{}, dq{};
  for (int i = 0; i < 4; ++i) {
    double magnitude = 0;
    for (int j = 0; j < 4; ++j) {
      q[i] += a[j * 4 + i] * v[j];
      magnitude += std::abs(a[j * 4 + i] * v[j]);
    }
    dq[i] = (gamma4 + u) * magnitude;
  }
  if (fixed) {
    const double es = eyeSeparation, c = convergence;
    double k = es * (1 - c * q[3]);
    double dk = std::abs(es) * (c * dq[3] + u * c * std::abs(q[3]) + u * std::abs(1 - c * q[3])) + 2 * u * std::abs(k);
    double dw = dq[3];
    if (scaleError) {
      dk = dk * columnScale + std::abs(k) * *scaleError + u * std::abs(k * columnScale);
      k *= columnScale;
      columnScale = 1.0;
    }
    for (int i = 0; i < 4; ++i) {
      double column0 = a[i] * columnScale;
      q[i] -= column0 * k;
      dq[i] += std::abs(column0) * dk + 2 * u * std::abs(column0 * k) + u * std::abs(q[i]);
    }
    dq[3] = std::max(dq[3], dw);
  }
  return quotientBound(q, dq);
}

// The half-width h of the screen coordinate a matrix `a` (column-major: a[4j + i], column j) takes,
// as the text fix computes it in fp32 (pixel.cpp, screenScaleLines): with x, z, t the columns of the
// coordinate, the depth and the constant, A = t.xyz z.w - z.xyz t.w and
//     h = -dot(A, x.xyz) / (dot(x.xyz, x.xyz) z.w).
// `value` in exact arithmetic on a's elements; `bound`, first order on fp32 evaluation: each A_i
// off by 2u (|t_i z.w| + |z_i t.w|), the dot product adding gamma_4 sum |A_i x_i|, the denominator
// gamma_4 relative, the quotient u.
struct MatrixHalfWidth {
  double value = 0, bound = 0;
};
inline MatrixHalfWidth matrixHalfWidth(const Mat4& a) {
  const double u = kUnitRoundoff, gamma4 = 4 * u / (1 - 4 * u);
  double numerator = 0, numeratorError = 0, magnitude = 0, columnLength = 0;
  for (int i = 0; i < 3; ++i) {
    const double difference = a[12 + i] * a[11] - a[8 + i] * a[15];
    const double differenceError = 2 * u * (std::abs(a[12 + i] * a[11]) + std::abs(a[8 + i] * a[15]));
    numerator += difference * a[i];
    numeratorError += differenceError * std::abs(a[i]);
    magnitude += std::abs(difference * a[i]);
    columnLength += a[i] * a[i];
  }
  numeratorError += gamma4 * magnitude;
  MatrixHalfWidth h;
  h.value = -numerator / (columnLength * a[11]);
  h.bound = std::abs(h.value) * (numeratorError / std::abs(numerator) + 2 * gamma4 + u);
  return h;
}

// The half-width of the screen coordinate an affine screen-to-world map `a` takes ((c z, c' z, z, 1)
// to the world), as the text fix computes it in fp32: h = -dot(z.xyz, x.xyz) / dot(x.xyz, x.xyz),
// x and z its columns of the coordinate and the depth. `bound`, first order: each dot product
// gamma_3 relative to its sum of magnitudes, the quotient u.
inline MatrixHalfWidth affineMapHalfWidth(const Mat4& a) {
  const double u = kUnitRoundoff, gamma3 = 3 * u / (1 - 3 * u);
  double numerator = 0, magnitude = 0, columnLength = 0;
  for (int i = 0; i < 3; ++i) {
    numerator += a[8 + i] * a[i];
    magnitude += std::abs(a[8 + i] * a[i]);
    columnLength += a[i] * a[i];
  }
  MatrixHalfWidth h;
  h.value = -numerator / columnLength;
  h.bound = std::abs(h.value) * (gamma3 * magnitude / std::abs(numerator) + gamma3 + u);
  return h;
}

// The same bound for the screen-to-world form, q = fl(M v') with v' = (fl(x z), fl(y z), z, 1) for
// the pixel's NDC x, y (exact in fp32) and the view depth z (as the shader reads it): the two
// products add u |M_i0 x z| + u |M_i1 y z| to the dot product's (gamma_4 + u) sum_j |M_ij v'_j|.
// The fix subtracts c = fl(col0 * k) with k = fl(fl(eS) * fl(|z| - C)) * sign(z):
//     |dk| <= |eS| u ||z| - C| + 2u |k|,  |dq'_i| <= |dq_i| + |col0_i| |dk| + 2u |col0_i k| + u |q'_i|;
// p = fl(q.xyz / q.w) as above.
// `columnScale` as for positionBound (a map from UV space: half its column of u).
// `scaleError` as for positionBound (a half-width the shader computes: affineMapHalfWidth).
inline std::array<double, 3> screenToWorldBound(const Mat4& a, double x, double y, double z, bool fixed,
                                                double eyeSeparation, double convergence, double columnScale = 1.0,
                                                std::optional<double> scaleError = std::nullopt) {
  const double u = kUnitRoundoff, gamma4 = 4 * u / (1 - 4 * u);
  const std::array<double, 4> v = {x * z, y * z, z, 1.0};
  std::array<double, 4> q{}, dq{};
  for (int i = 0; i < 4; ++i) {
    double magnitude = 0;
    for (int j = 0; j < 4; ++j) {
      q[i] += a[j * 4 + i] * v[j];
      magnitude += std::abs(a[j * 4 + i] * v[j]);
    }
    dq[i] = (gamma4 + u) * magnitude + u * (std::abs(a[i] * v[0]) + std::abs(a[4 + i] * v[1]));
  }
  if (fixed) {
    double k = eyeSeparation * (std::abs(z) - convergence) * (z < 0 ? -1.0 : 1.0);
    double dk = std::abs(eyeSeparation) * u * std::abs(std::abs(z) - convergence) + 2 * u * std::abs(k);
    if (scaleError) {
      dk = dk * columnScale + std::abs(k) * *scaleError + u * std::abs(k * columnScale);
      k *= columnScale;
      columnScale = 1.0;
    }
    for (int i = 0; i < 4; ++i) {
      const double column0 = a[i] * columnScale;
      q[i] -= column0 * k;
      dq[i] += std::abs(column0) * dk + 2 * u * std::abs(column0 * k) + u * std::abs(q[i]);
    }
  }
  return quotientBound(q, dq);
}

// The view vector from `eyeCamera` to the exact rebuilt point `exact` (homogeneous), normalized,
// and the first-order bound on a shader's normalized vector to it: the rebuilt position's bound
// `positionError` and the camera's `cameraError`, over the distance, twice (a normalized vector moves
// by at most twice the relative change of the vector), plus 8u for the normalization.
struct ViewVector {
  std::array<double, 3> direction;
  double bound = 0;
};
inline ViewVector viewVectorTo(const std::array<double, 3>& eyeCamera, const std::array<double, 4>& exact,
                               const std::array<double, 3>& positionError, double cameraError) {
  std::array<double, 3> toCamera;
  for (int c = 0; c < 3; ++c) toCamera[c] = eyeCamera[c] - exact[c] / exact[3];
  const double length = std::hypot(toCamera[0], toCamera[1], toCamera[2]);
  ViewVector v;
  for (int c = 0; c < 3; ++c) v.direction[c] = toCamera[c] / length;
  v.bound = 2 * (std::hypot(positionError[0], positionError[1], positionError[2]) + cameraError) / length + 8 * kUnitRoundoff;
  return v;
}

}  // namespace stereoshift::harness
