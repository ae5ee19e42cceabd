// stereoshift runtime helper: the per-eye values an application feeds to shaders that stereoshift
// converted. Header-only, C++17, no dependencies beyond the standard library.
//
// The maths is docs/stereo-math.md sections 1 and 3 and NVIDIA's "stereo fundamentals" GDC talk:
//   e = eye sign (-1 left, +1 right, 0 mono), S = separation (interaxial / virtual screen width,
//   user scale applied), C = convergence (eye-space depth of the zero-parallax plane).
//   - the converted vertex shaders shift the clip position: x' = x + e*S*(w - C), the same as
//     rendering with the stereo projection matrix (stereoProjectionGL / stereoProjectionD3D);
//   - view vectors (relief / parallax mapping) need the eye centre C_eye = C_mono + offset with
//     offset = InvVP * (e*S*C, 0, 0, 0) = e*S*C/P00 along the camera's right axis
//     (eyeOffsetFromInverseView / eyeOffsetFromInverseViewProjection).
//
// Matrix storage: `Mat4` is 16 scalars, element (row r, column c) of the column-vector matrix
// (clip = P * v) at index 4*c + r: what glUniformMatrix4fv(..., GL_FALSE, ...) and a std140 / GLSL
// `mat4` expect. A D3D row-vector matrix (clip = v * M, M = P^T) stored row-major is the very same
// 16 scalars, so D3D code can pass its matrices as they are; the *D3D functions take them in that
// reading and exist so call sites say which convention they mean.
#pragma once

#include <array>
#include <cmath>
#include <utility>

namespace stereoshift::runtime {

// The injected eye parameters, member i at byte offset 4*i (std140 / cbuffer packing of 8 floats).
// A shader declares a prefix: the shift needs the first three, HUD-at-depth four, per-eye view
// vectors without a matrix to derive them from all seven. Upload this struct to the `StereoParams`
// block (or set the loose uniforms / specialization constants of the same names).
struct StereoParams {
  float eyeSign = 0.0f;      // -1 left, +1 right, 0 mono (the converted shaders are then the originals)
  float separation = 0.0f;   // interaxial / virtual screen width, user scale applied
  float convergence = 1.0f;  // eye-space depth of the zero-parallax plane
  float hudDepth = 1.0f;     // eye depth at which a 2D element is placed (--hud-at-depth)
  float eyeOffsetX = 0.0f;   // world-space offset of this eye's centre from the mono camera
  float eyeOffsetY = 0.0f;
  float eyeOffsetZ = 0.0f;
  float projScaleX = 1.0f;   // the projection's x scale P[0][0] (view-ray deferred lighting without one)
};
static_assert(sizeof(StereoParams) == 8 * sizeof(float), "StereoParams must be 8 tightly packed floats");

template <class T>
using Mat4 = std::array<T, 16>;
template <class T>
using Vec3 = std::array<T, 3>;
template <class T>
using Vec4 = std::array<T, 4>;

// ---- small matrix helpers (for applications without a maths library, and the tests) ---------------

template <class T>
constexpr T element(const Mat4<T>& m, int row, int column) {
  return m[4 * column + row];
}

template <class T>
Mat4<T> multiply(const Mat4<T>& a, const Mat4<T>& b) {  // a * b, column vectors
  Mat4<T> out{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      T sum = 0;
      for (int k = 0; k < 4; ++k) sum += a[4 * k + r] * b[4 * c + k];
      out[4 * c + r] = sum;
    }
  return out;
}

template <class T>
Vec4<T> transform(const Mat4<T>& m, const Vec4<T>& v) {  // m * v
  Vec4<T> out{};
  for (int r = 0; r < 4; ++r) out[r] = m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2] + m[12 + r] * v[3];
  return out;
}

// General inverse by Gauss-Jordan elimination with partial pivoting. A singular matrix gives
// non-finite elements.
template <class T>
Mat4<T> inverse(const Mat4<T>& m) {
  T a[4][8];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      a[r][c] = m[4 * c + r];
      a[r][c + 4] = r == c ? T(1) : T(0);
    }
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 4; ++r)
      if (std::fabs(a[r][col]) > std::fabs(a[pivot][col])) pivot = r;
    for (int c = 0; c < 8; ++c) std::swap(a[col][c], a[pivot][c]);
    T scale = T(1) / a[col][col];
    for (int c = 0; c < 8; ++c) a[col][c] *= scale;
    for (int r = 0; r < 4; ++r) {
      if (r == col) continue;
      T factor = a[r][col];
      for (int c = 0; c < 8; ++c) a[r][c] -= factor * a[col][c];
    }
  }
  Mat4<T> out{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[4 * c + r] = a[r][c + 4];
  return out;
}

// ---- the stereo projection (docs/stereo-math.md section 1) ---------------------------------------------------

// The projection whose clip x is the shifted one, x' = x + e*S*(w - C), for every point:
//   row 0  +=  e*S * row 3      (w is row 3: -z in GL, +z in a left-handed D3D projection)
//   P[0][3] -= e*S*C
// For the usual GL perspective (row 3 = [0, 0, -1, 0]) row 0 becomes [p00, 0, p02 - e*S, -e*S*C].
template <class T>
Mat4<T> stereoProjectionGL(Mat4<T> projection, T eyeSign, T separation, T convergence) {
  const T shift = eyeSign * separation;
  for (int c = 0; c < 4; ++c) projection[4 * c + 0] += shift * projection[4 * c + 3];
  projection[12] -= shift * convergence;
  return projection;
}

// The same for a D3D row-vector matrix M (clip = v * M) stored row-major, element (r, c) at 4*r + c:
// column 0 += e*S * column 3, M[3][0] -= e*S*C. (The same 16 scalars change as in the GL function:
// M is P transposed.) For a left-handed perspective (column 3 = [0, 0, 1, 0]) M[2][0] becomes
// m20 + e*S.
template <class T>
Mat4<T> stereoProjectionD3D(Mat4<T> rowVectorMatrix, T eyeSign, T separation, T convergence) {
  const T shift = eyeSign * separation;
  for (int r = 0; r < 4; ++r) rowVectorMatrix[4 * r + 0] += shift * rowVectorMatrix[4 * r + 3];
  rowVectorMatrix[4 * 3 + 0] -= shift * convergence;
  return rowVectorMatrix;
}

// ---- the per-eye camera centre (docs/stereo-math.md section 3) -----------------------------------------------

// World-space offset of this eye's centre from the mono camera, from the inverse view matrix and
// P00 (the projection's horizontal scale, element (0, 0)): InvView * (e*S*C / P00, 0, 0, 0), i.e.
// e*S*C/P00 along the camera's right axis. This is what the eyeOffsetX/Y/Z parameters hold.
// D3D: pass the row-major inverse view of the row-vector convention as it is (same scalars).
template <class T>
Vec3<T> eyeOffsetFromInverseView(const Mat4<T>& inverseView, T p00, T eyeSign, T separation, T convergence) {
  const T along = eyeSign * separation * convergence / p00;
  return {inverseView[0] * along, inverseView[1] * along, inverseView[2] * along};
}

// The same from the inverse view-projection: InvVP * (e*S*C, 0, 0, 0) (a direction: w is 0).
template <class T>
Vec3<T> eyeOffsetFromInverseViewProjection(const Mat4<T>& inverseViewProjection, T eyeSign, T separation,
                                           T convergence) {
  const T k = eyeSign * separation * convergence;
  return {inverseViewProjection[0] * k, inverseViewProjection[1] * k, inverseViewProjection[2] * k};
}

// Everything one eye's StereoParams hold, from the mono inverse view and P00.
template <class T>
StereoParams stereoParamsForEye(T eyeSign, T separation, T convergence, const Mat4<T>& inverseView, T p00,
                                T hudDepth = T(1)) {
  Vec3<T> offset = eyeOffsetFromInverseView(inverseView, p00, eyeSign, separation, convergence);
  StereoParams params;
  params.eyeSign = static_cast<float>(eyeSign);
  params.separation = static_cast<float>(separation);
  params.convergence = static_cast<float>(convergence);
  params.hudDepth = static_cast<float>(hudDepth);
  params.eyeOffsetX = static_cast<float>(offset[0]);
  params.eyeOffsetY = static_cast<float>(offset[1]);
  params.eyeOffsetZ = static_cast<float>(offset[2]);
  return params;
}

// ---- culling (NVIDIA GDC talk "3D Objects Culling": compound frustum) ----------------------------

// Culling against the mono frustum drops what one eye sees beyond the screen, and keeps what only
// one eye sees in front of it. The frustum bounded by the right eye's left plane and the left eye's
// right plane does both: it is the union of the eye frustums beyond the screen (w > C) and their
// common part in front of it. Its apex lies on the mono view axis, in front of the mono eye, at
//   Z = C / (1 + 1/S)        (the talk's formula; written C*S/(1+S) so that S = 0 gives 0)
// Its left and right planes open by (1 + S) against the mono ones, P00_cull = P00 / (1 + S); the
// top, bottom and far planes are the mono ones.
template <class T>
T cullingFrustumOriginDepth(T separation, T convergence) {
  return convergence * separation / (T(1) + separation);
}

template <class T>
T cullingFrustumP00(T p00, T separation) {
  return p00 / (T(1) + separation);
}

// World-space apex of the compound frustum: the mono eye moved Z along the view direction.
// `viewLooksDownNegativeZ`: true for GL right-handed views (forward = -z), false for D3D
// left-handed ones (forward = +z).
template <class T>
Vec3<T> cullingFrustumOrigin(const Mat4<T>& inverseView, T separation, T convergence,
                             bool viewLooksDownNegativeZ = true) {
  const T depth = cullingFrustumOriginDepth(separation, convergence);
  const T sign = viewLooksDownNegativeZ ? T(-1) : T(1);
  Vec3<T> forward = {inverseView[8] * sign, inverseView[9] * sign, inverseView[10] * sign};
  T length = std::sqrt(forward[0] * forward[0] + forward[1] * forward[1] + forward[2] * forward[2]);
  return {inverseView[12] + forward[0] / length * depth, inverseView[13] + forward[1] / length * depth,
          inverseView[14] + forward[2] / length * depth};
}

// ==== single-pass stereo (--eye-source multiview | instanced) =====================================
//
// Both eyes in one draw; the converted shaders derive eyeSign themselves (the StereoParams member is
// kept, so the layout is the same in every mode, and ignored): eye 0 is the left eye (-1), eye 1 the
// right (+1), swapped by --swap-eyes. separation and convergence are uploaded as in two passes, once
// per frame. eyeOffsetX/Y/Z (per-eye view vectors without a matrix): the shaders scale them by the
// eye sign, so upload the right eye's offset (eyeSign = +1).
//   multiview: eye = view index. Vulkan: VkRenderPassMultiviewCreateInfo view mask 0b11 (or
//     VkRenderingInfo::viewMask) on a 2-layer target, device feature `multiview`. OpenGL / GL ES:
//     GL_OVR_multiview2, glFramebufferTextureMultiviewOVR(..., baseViewIndex 0, numViews 2) on a
//     2-layer texture array. D3D12: view instancing (SM 6.1, D3D12_VIEW_INSTANCING_DESC with two
//     views whose RenderTargetArrayIndex are 0 and 1).
//   instanced: eye = instance & 1, the shader sees instance >> 1. Draw twice the instances; keep
//     firstInstance even (the shader sees firstInstance / 2 + k); per-instance vertex attributes
//     need an instance step of 2 (VK_EXT_vertex_attribute_divisor divisor 2, glVertexAttribDivisor(i, 2),
//     D3D InstanceDataStepRate 2), and with a base instance they are read at firstInstance + k, so
//     offset the per-instance buffer binding instead of using a base. The eye goes to the layer of a
//     2-layer target (Vulkan: shaderOutputLayer / VK_EXT_shader_viewport_index_layer; GL 4.1:
//     GL_ARB_shader_viewport_layer_array; D3D12: VPAndRTArrayIndexFromAnyShaderFeedingRasterizer) or,
//     with --eye-route viewport, to viewport 0 / 1 (side by side: sideBySideViewports).
//   Metal, multiview (--target msl): Metal has no view index; SPIRV-Cross's output emulates it by
//     instancing. Draw twice the instances (firstInstance unchanged: the shader subtracts the base
//     instance), bind the view mask buffer {first view 0, view count 2} (two uints) at vertex and
//     fragment buffer index 24, render into a 2-layer texture (the view is
//     [[render_target_array_index]]), and step per-instance attributes every 2 instances
//     (MTLVertexBufferLayoutDescriptor stepRate 2). Instanced mode for Metal is set up as InstancedLayer.

enum class SinglePassMode { Multiview, InstancedLayer, InstancedViewport, MetalMultiview };

// What the application sets up for one draw of a single-pass frame.
struct SinglePassSetup {
  unsigned viewMask = 0;        // multiview: the render pass / rendering view mask; 0 otherwise
  unsigned layerCount = 1;      // array layers of the colour and depth targets
  unsigned viewportCount = 1;   // viewports bound (2 for side by side)
  unsigned instanceCount = 0;   // the draw's instance count
  unsigned firstInstance = 0;   // the draw's first instance
  unsigned instanceStep = 1;    // per-instance attribute divisor
  // MetalMultiview: the two uints of SPIRV-Cross's view mask buffer and its buffer index.
  std::array<unsigned, 2> viewMaskBuffer = {0, 0};
  unsigned viewMaskBufferIndex = 0;
};

// The set-up for a draw the mono renderer records as (instanceCount, firstInstance).
inline SinglePassSetup singlePassSetup(SinglePassMode mode, unsigned instanceCount, unsigned firstInstance) {
  SinglePassSetup s;
  s.instanceCount = instanceCount;
  s.firstInstance = firstInstance;
  switch (mode) {
    case SinglePassMode::Multiview:
      s.viewMask = 0x3u;
      s.layerCount = 2;
      break;
    case SinglePassMode::InstancedLayer:
    case SinglePassMode::InstancedViewport:
      s.instanceCount = 2 * instanceCount;
      s.firstInstance = 2 * firstInstance;  // even, so eye 0 stays the left; the shader reads firstInstance + k
      s.instanceStep = 2;
      if (mode == SinglePassMode::InstancedLayer) s.layerCount = 2;
      else s.viewportCount = 2;
      break;
    case SinglePassMode::MetalMultiview:
      s.instanceCount = 2 * instanceCount;  // view = (instance - base) % 2, instance = (instance - base) / 2 + base
      s.instanceStep = 2;
      s.layerCount = 2;
      s.viewMaskBuffer = {0, 2};
      s.viewMaskBufferIndex = 24;  // SPIRV-Cross's default, which stereoshift keeps
      break;
  }
  return s;
}

struct Viewport {
  float x = 0, y = 0, width = 0, height = 0;
};

// --eye-route viewport: the left eye in the left half of a width x height target, the right eye in
// the right half (viewport index 0 / 1).
inline std::array<Viewport, 2> sideBySideViewports(float width, float height) {
  return {Viewport{0, 0, width / 2, height}, Viewport{width / 2, 0, width / 2, height}};
}

// The StereoParams of a single-pass frame: both eyes at once (eyeSign is derived by the shaders and
// left 0), eyeOffset as the right eye's.
inline StereoParams singlePassParams(float separation, float convergence, float hudDepth = 1.0f,
                                     const Vec3<float>& rightEyeOffset = {0, 0, 0}) {
  StereoParams p;
  p.separation = separation;
  p.convergence = convergence;
  p.hudDepth = hudDepth;
  p.eyeOffsetX = rightEyeOffset[0];
  p.eyeOffsetY = rightEyeOffset[1];
  p.eyeOffsetZ = rightEyeOffset[2];
  return p;
}

// ==== end of single-pass stereo =====================================================================

// ---- comfort ---------------------------------------------------------------------------------------

// The eye depths that stay comfortable for a convergence C: [C/2, 100*C]. At C/2 the screen
// parallax e*S*(1 - C/w) is -e*S, as large as the largest (at infinity) behind the screen;
// at 100*C it is already 99% of that. Content nearer than C/2 pops out more than anything recedes.
template <class T>
std::array<T, 2> comfortableDepthRange(T convergence) {
  return {convergence / T(2), T(100) * convergence};
}

// Screen parallax in NDC of a point at eye depth w: e*S*(1 - C/w).
template <class T>
T parallax(T eyeSign, T separation, T convergence, T w) {
  return eyeSign * separation * (T(1) - convergence / w);
}


// =====================================================================================================
// ---- depth reprojection: the widened source view (docs/stereo-math.md section 5) ----------------------
// =====================================================================================================
//
// A view synthesized by `stereoshift reproject` shows, near its left and right edges, points the
// source view did not have on screen: the target pixel at NDC x reads the source between
// x - |de|*S (infinitely far) and x + |de|*S*r (r = --search-near, in front of the screen), where de is
// the eye-sign difference (2 from one eye to the other, 1 from the centre view). The fix the seed
// article gives: render the source with a horizontal field of view widened by that margin, into a
// target widened by the same number of pixels, so the edge pixels fall inside it; the final image is
// the central `width` columns. Pixel density is kept (P00 scaled by width / widenedWidth) and the
// shift must be too, so the source and the pass both use separation * separationScale.
template <class T>
struct WidenedSourceView {
  Mat4<T> projection;      // the mono projection with P00 scaled: render the source with it
  int widenedWidth = 0;    // columns of the source (and the pass's) target
  int columnsEachSide = 0; // the final image is columns [columnsEachSide, columnsEachSide + width)
  T separationScale = 1;   // width / widenedWidth: the separation to use for the widened render
  T extraPixelCost = 0;    // (widenedWidth - width) / width: extra pixels drawn, as a fraction
};

// `projection`: the mono projection (GL column-major, or the D3D row-major scalars: P00 is element 0
// in both readings, and a symmetric frustum is assumed, as P02 = 0 keeps the widening centred);
// `width`: the final image's columns; `eyeSignDifference`: |e_target - e_source|.
template <class T>
WidenedSourceView<T> widenedSourceView(const Mat4<T>& projection, int width, T eyeSignDifference, T separation,
                                       T searchNear = T(0.5)) {
  WidenedSourceView<T> view;
  const T reach = std::fabs(eyeSignDifference) * std::fabs(separation) * (searchNear > T(1) ? searchNear : T(1));
  // reach is in NDC of the final view: width/2 pixels per unit.
  view.columnsEachSide = static_cast<int>(std::ceil(static_cast<double>(reach) * width / 2.0));
  view.widenedWidth = width + 2 * view.columnsEachSide;
  view.separationScale = T(width) / T(view.widenedWidth);
  view.projection = projection;
  view.projection[0] = projection[0] * view.separationScale;
  view.extraPixelCost = T(view.widenedWidth - width) / T(width);
  return view;
}

}  // namespace stereoshift::runtime
