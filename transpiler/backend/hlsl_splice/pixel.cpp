// The HLSL splice's per-eye corrections of a pixel shader: turns the deferred pass's text fixes
// (RowProductTextFix: an unprojection through a matrix in cbuffer rows, each component of q located
// by the line of the statement that computes it) into a marked block of statements right after the
// line that completes q,
//     float4 stereoshift_stereo = StereoParams.Load(int3(0, 0, 0));
//     float stereoshift_d = stereoshift_stereo.x * (1 - stereoshift_stereo.y * <q.w>);
//     <q.x> -= <InvM[0][0]> * stereoshift_d;  ...  <q.w> -= <InvM[3][0]> * stereoshift_d;
// (the screen-to-world form q = M * (ndc * z, z, 1) has d = s.x * (|z| - s.y) * sign(z) instead,
// the pixel's NDC x being off by s.x * (1 - s.y / |z|) and scaled by z),
// (deferred_unprojection_pass.cpp has the maths: 3Dmigoto's x is the separation with the eye's
// sign, y the convergence), and 3Dmigoto's `Texture2D<float4> StereoParams : register(t125)` before
// the entry point unless the file declares it.
//
// Where each component of q lives is read from the text: the statement on its line assigns
// `reg.mask = ...;` and the component is mask[lane]. The block is written only where that is
// certain: one statement on each of those lines, and no line between a component's statement and
// the block writes that register component again, reads it, or is anything but a plain assignment
// or control flow that writes nothing (an early `discard` or `return`, the braces of an `if`; not a
// loop, not a call of a helper that might write). Everything else of the file stays as written.
#include "transpiler/backend/hlsl_splice.h"

#include "transpiler/backend/hlsl_splice/edit_buffer.h"
#include "transpiler/backend/hlsl_splice/shift_text.h"
#include "transpiler/backend/hlsl_splice/top_level.h"

#include <algorithm>
#include <array>
#include <optional>
#include <regex>
#include <set>

namespace stereoshift {

using namespace hlsl_splice;

namespace {

struct Lines {
  std::vector<size_t> begin;  // offset of each line's first byte (line k+1 at begin[k])
  const std::string& text;
  explicit Lines(const std::string& source) : text(source) {
    begin.push_back(0);
    for (size_t i = 0; i < source.size(); ++i)
      if (source[i] == '\n') begin.push_back(i + 1);
  }
  size_t count() const { return begin.size(); }
  // Line `n` (1-based) without its line break.
  std::string line(uint32_t n) const {
    if (n == 0 || n > begin.size()) return "";
    size_t from = begin[n - 1], to = n < begin.size() ? begin[n] : text.size();
    std::string l = text.substr(from, to - from);
    while (!l.empty() && (l.back() == '\n' || l.back() == '\r')) l.pop_back();
    return l;
  }
  size_t endOf(uint32_t n) const { return n < begin.size() ? begin[n] : text.size(); }
};

// `reg.mask = rhs;` alone on its line (a trailing // comment allowed).
struct Assignment {
  std::string reg, mask, rhs;
};

std::optional<Assignment> assignmentOn(const std::string& line) {
  static const std::regex form(R"(^\s*([A-Za-z_]\w*)\.([xyzw]{1,4})\s*=\s*([^;]*);\s*(//.*)?$)");
  std::smatch m;
  if (!std::regex_match(line, m, form)) return std::nullopt;
  return Assignment{m[1], m[2], m[3]};
}

// Whether `rhs` reads component `c` of `reg` (`reg.xyzw`, `reg.x`, or `reg` whole).
bool reads(const std::string& rhs, const std::string& reg, char c) {
  std::regex use("\\b" + reg + R"(\b(\.([xyzw]+))?)");
  for (auto it = std::sregex_iterator(rhs.begin(), rhs.end(), use); it != std::sregex_iterator(); ++it)
    if (!(*it)[2].matched || (*it)[2].str().find(c) != std::string::npos) return true;
  return false;
}

struct Located {
  std::array<std::string, 4> component;  // "r1.x"
  std::string depth;                      // the screen-to-world form: where the depth z is
  std::string error;
  uint32_t errorLine = 0;
};

// `out` with the reason it cannot be placed, at `line`.
Located failedAt(Located out, uint32_t line, std::string why) {
  out.error = std::move(why);
  out.errorLine = line;
  return out;
}

// Whether a line is control flow that writes no register: a branch that leaves the shader (`if (c)
// discard;`, `if (c) return;`), the header or the end of an `if` / `else` block, `discard;` or
// `return;` (a sky's or a stencil's early out before the lighting, as the decompiler writes them).
// A block's statements are lines of their own, checked as any other; loops and calls are not this.
bool controlOnly(const std::string& line) {
  static const std::regex form(
      R"(^\s*(if\s*\(.*\)\s*(discard;|return;|\{)|\}\s*else\s*\{|else\s*\{|\{|\}|discard;|return;)\s*(//.*)?$)");
  return std::regex_match(line, form);
}

// Whether a line is one call statement (`t1.GetDimensions(0, fDest.x, fDest.y, fDest.z);`,
// `sincos(r0.x, r1.x, r2.x);`): in a pixel shader's HLSL a call writes registers only through its
// arguments, so a register its line does not name keeps its value.
bool callStatement(const std::string& line) {
  static const std::regex form(R"(^\s*(([A-Za-z_]\w*)\.)?([A-Za-z_]\w*)\s*\(.*\)\s*;\s*(//.*)?$)");
  std::smatch m;
  if (!std::regex_match(line, m, form)) return false;
  static const std::set<std::string> keywords = {"if", "for", "while", "switch", "return", "do"};
  return !m[2].matched ? !keywords.count(m[3]) : true;
}

// Whether a line holds no code (blank, or a comment only).
bool blankCode(const std::string& text) {
  return text.substr(0, text.find("//")).find_first_not_of(" \t") == std::string::npos;
}

// Where the depth a fix reads lives: the statement on `depthLine` assigns `reg.mask = ...;`, and no
// line after it up to `until` is anything but a plain assignment or rewrites that component. `what`
// names the fix's value ("the rebuilt position"), `done` the moment it must last to ("the rebuilt
// position is complete"). The component ("r1.x"), or the failure in `out`.
std::optional<std::string> locateDepth(const Lines& lines, uint32_t depthLine, uint32_t depthLane, uint32_t until,
                                       const std::string& what, const std::string& done, Located& out) {
  auto depth = assignmentOn(lines.line(depthLine));
  if (!depth || depthLane >= depth->mask.size() || depthLine > until) {
    out = failedAt(out, depthLine, "the statement computing the depth is not one `reg.mask = ...;` on its line");
    return std::nullopt;
  }
  const char c = depth->mask[depthLane];
  const std::string component = depth->reg + "." + c;
  for (uint32_t l = depthLine + 1; l <= until; ++l) {
    std::string text = lines.line(l);
    if (blankCode(text)) continue;
    auto later = assignmentOn(text);
    if (!later && controlOnly(text)) continue;  // writes nothing
    if (!later && callStatement(text)) {
      if (reads(text, depth->reg, c)) {
        out = failedAt(out, l, "register " + component + " (the depth) may be written by the call on this line before " + done);
        return std::nullopt;
      }
      continue;
    }
    if (!later) {
      out = failedAt(out, l, "a line between the depth and " + what + " is not a plain assignment");
      return std::nullopt;
    }
    if (later->reg == depth->reg && later->mask.find(c) != std::string::npos) {
      out = failedAt(out, l, "register " + component + " (the depth) is written again before " + done);
      return std::nullopt;
    }
  }
  return component;
}

Located locate(const Lines& lines, const RowProductTextFix& fix) {
  Located out;
  auto fail = [&](uint32_t line, std::string why) { return failedAt(out, line, std::move(why)); };
  if (!fix.present[3] && !fix.scaledByDepth) return fail(fix.afterLine, "the rebuilt position has no w");
  for (size_t i = 0; i < 4; ++i) {
    if (!fix.present[i]) continue;
    auto a = assignmentOn(lines.line(fix.lines[i]));
    if (!a || fix.lanes[i] >= a->mask.size())
      return fail(fix.lines[i], "the statement computing component " + std::to_string(i) +
                                    " of the rebuilt position is not one `reg.mask = ...;` on its line");
    char c = a->mask[fix.lanes[i]];
    out.component[i] = a->reg + "." + c;
    for (uint32_t l = fix.lines[i] + 1; l <= fix.afterLine; ++l) {
      std::string text = lines.line(l);
      if (blankCode(text)) continue;
      auto later = assignmentOn(text);
      if (!later && (controlOnly(text) || callStatement(text))) {
        if (reads(text, a->reg, c)) return fail(l, out.component[i] + " is read before the rebuilt position is complete");
        continue;
      }
      if (!later) return fail(l, "a line between the rebuilt position's statements is not a plain assignment");
      bool partOfQ = false;
      for (size_t j = 0; j < 4; ++j) partOfQ |= fix.present[j] && fix.lines[j] == l;
      if (later->reg == a->reg && later->mask.find(c) != std::string::npos)
        return fail(l, "register " + out.component[i] + " is written again before the rebuilt position is complete");
      if (!partOfQ && reads(later->rhs, a->reg, c))
        return fail(l, out.component[i] + " is read before the rebuilt position is complete");
    }
  }
  if (fix.scaledByDepth) {
    // The depth the screen coordinates were scaled by, still in its register after q.
    auto z = locateDepth(lines, fix.depthLine, fix.depthLane, fix.afterLine, "the rebuilt position",
                         "the rebuilt position is complete", out);
    if (!z) return out;
    out.depth = *z;
  }
  return out;
}

std::string indentOf(const std::string& line) { return line.substr(0, line.find_first_not_of(" \t")); }

// `float3(c[0], c[1], c[2])` of a column's elements.
template <class Column>
std::string float3Of(const Column& c) {
  return "float3(" + c[0] + ", " + c[1] + ", " + c[2] + ")";
}

// The declaration of `h`, the screen coordinate's half-width, from M (RowProductTextFix::
// scaleFromTheMatrix): with x, z and t M's columns of the coordinate, the depth and the constant
// (x.w = 0), the camera is z.xyz / z.w and the coordinate c0 on the optical axis solves
// dot(q(c0).xyz / q.w - camera, x.xyz) = 0:
//     c0 = -dot(t.xyz * z.w - z.xyz * t.w, x.xyz) / (dot(x.xyz, x.xyz) * z.w)
// (the axis is orthogonal to the image's right and up, M's columns of x and y); `affine`, the
// screen-to-world form (c z, c' z, z, 1), whose camera is its constant column: c0 = -dot(z.xyz,
// x.xyz) / dot(x.xyz, x.xyz). A UV or a pixel position starts at 0, so c0 is its half-width; NDC is
// centred (c0 = 0, up to a jitter): h = 1.
std::string halfWidthLines(const std::array<std::string, 3>& columnX, const std::array<std::string, 4>& columnZ,
                           const std::array<std::string, 4>& translation, bool affine, const std::string& h,
                           const std::string& in, const std::string& nl) {
  const std::string x = std::string(kPrefix) + "_column";
  std::string t = in + "float3 " + x + " = " + float3Of(columnX) + ";" + nl;
  if (affine)  // M (c z, c' z, z, 1): the point minus the camera (M's constant column) is z (x c + y c' + z)
    t += in + "float " + h + " = -dot(" + float3Of(columnZ) + ", " + x + ") / dot(" + x + ", " + x + ");" + nl;
  else
    t += in + "float " + h + " = -dot(" + float3Of(translation) + " * " + columnZ[3] + " - " + float3Of(columnZ) + " * " +
         translation[3] + ", " + x + ") / (dot(" + x + ", " + x + ") * " + columnZ[3] + ");" + nl;
  t += in + h + " = " + h + " > 0.25 ? " + h + " : 1;" + nl;
  return t;
}

// `d` scaled by the half-width (halfWidthLines).
std::string screenScaleLines(const RowProductTextFix& fix, const std::string& d, const std::string& in,
                             const std::string& nl) {
  const std::string h = std::string(kPrefix) + "_half_width";
  std::string t = halfWidthLines({fix.column[0], fix.column[1], fix.column[2]}, fix.columnZ, fix.translation,
                                 fix.scaledByDepth, h, in, nl);
  return t + in + d + " *= " + h + ";" + nl;
}

// The basis form's depth must be the view depth: the ray's part along the view axis (orthogonal to
// the bases of x and y) is 1. A ray to the far plane (a depth over the far distance) has the far
// distance there, and the correction's convergence would be in the wrong units: none then (d = 0).
std::string viewDepthCheck(const RowProductTextFix& fix, const std::string& d, const std::string& in,
                           const std::string& nl) {
  const std::string n = std::string(kPrefix) + "_view_axis";
  std::string t = in + "float3 " + n + " = cross(" + float3Of(fix.column) + ", " + float3Of(fix.columnY) + ");" + nl;
  t += in + "if (abs(abs(dot(" + float3Of(fix.columnZ) + ", " + n + ")) / length(" + n + ") - 1) > 0.001) " + d + " = 0;" + nl;
  return t;
}

std::string correctionBlock(const RowProductTextFix& fix, const Located& at, const std::string& indent,
                            const std::string& nl) {
  const std::string s = std::string(kPrefix) + "_stereo", d = std::string(kPrefix) + "_d", in = indent + "  ";
  uint32_t first = fix.afterLine;
  for (size_t i = 0; i < 4; ++i)
    if (fix.present[i]) first = std::min(first, fix.lines[i]);
  std::string lines = first == fix.afterLine ? "line " + std::to_string(first)
                                              : "lines " + std::to_string(first) + "-" + std::to_string(fix.afterLine);
  std::string t = indent + "// ---- stereoshift: this eye's position rebuild (" + lines +
                  (fix.basisRay ? ": p = (bx * x + by * y + bz) * depth over cbuffer basis vectors) ----"
                   : fix.scaledByDepth && fix.scaleFromTheMatrix
                       ? ": q = M * (screen * depth, depth, 1) over cbuffer rows, the screen's scale from M) ----"
                   : fix.scaledByDepth       ? ": q = M * (ndc * depth, depth, 1) over cbuffer rows) ----"
                   : fix.uvOfTheDepthTexture ? ": q = InvM * (uv, depth, 1) over cbuffer rows) ----"
                   : fix.scaleFromTheMatrix  ? ": q = M * (screen, depth, 1) over cbuffer rows, the screen's scale from M) ----"
                                             : ": q = InvM * (ndc, depth, 1) over cbuffer rows) ----") +
                  nl;
  t += indent + "{" + nl;
  t += in + "float4 " + s + " = StereoParams.Load(int3(0, 0, 0));" + nl;
  if (fix.scaledByDepth)
    t += in + "float " + d + " = " + s + ".x * (abs(" + at.depth + ") - " + s + ".y) * sign(" + at.depth + ");" + nl;
  else
    t += in + "float " + d + " = " + s + ".x * (1 - " + s + ".y * " + at.component[3] + ");" + nl;
  if (fix.scaleFromTheMatrix) t += screenScaleLines(fix, d, in, nl);
  if (fix.basisRay) t += viewDepthCheck(fix, d, in, nl);
  for (size_t i = 0; i < 4; ++i)
    if (fix.present[i]) t += in + at.component[i] + " -= " + fix.column[i] + " * " + d + ";" + nl;
  t += indent + "}" + nl + indent + "// ---- end stereoshift ----" + nl;
  return t;
}

// Where a view-ray fix's x and depth live: the statements on their lines, and no line from the
// depth's statement to x's rewriting the depth's register component or being anything but an
// assignment.
Located locateRay(const Lines& lines, const ViewRayTextFix& fix) {
  Located out;
  auto fail = [&](uint32_t line, std::string why) { return failedAt(out, line, std::move(why)); };
  auto x = assignmentOn(lines.line(fix.line));
  if (!x || fix.lane >= x->mask.size())
    return fail(fix.line, "the statement computing the view-space x is not one `reg.mask = ...;` on its line");
  out.component[0] = x->reg + "." + x->mask[fix.lane];
  auto depth = locateDepth(lines, fix.depthLine, fix.depthLane, fix.line, "the view-space x",
                           "the view-space x is corrected", out);
  if (!depth) return out;
  out.component[1] = *depth;
  return out;
}

std::string rayBlock(const ViewRayTextFix& fix, const Located& at, const std::string& indent, const std::string& nl) {
  const std::string s = std::string(kPrefix) + "_stereo";
  std::string t = indent + "// ---- stereoshift: this eye's view-space x (line " + std::to_string(fix.line) +
                  ": x = ndc.x * depth * " + fix.scale + ") ----" + nl;
  t += indent + "{" + nl;
  t += indent + "  float4 " + s + " = StereoParams.Load(int3(0, 0, 0));" + nl;
  t += indent + "  " + at.component[0] + " -= " + s + ".x * (abs(" + at.component[1] + ") - " + s + ".y) * abs(" +
       fix.scale + ");" + nl;
  t += indent + "}" + nl + indent + "// ---- end stereoshift ----" + nl;
  return t;
}

// Where a camera fix's view vector lives: the statement on its line, x, y and z in its mask.
Located locateCamera(const Lines& lines, const CameraTextFix& fix) {
  Located out;
  auto v = assignmentOn(lines.line(fix.line));
  if (!v) return failedAt(out, fix.line, "the statement computing the view vector is not one `reg.mask = ...;` on its line");
  for (size_t i = 0; i < 3; ++i) {
    if (fix.lanes[i] >= v->mask.size())
      return failedAt(out, fix.line, "the statement computing the view vector does not write all of x, y and z");
    out.component[i] = v->reg + "." + v->mask[fix.lanes[i]];
  }
  return out;
}

// v += s.x * s.y * InvM[column of x].xyz, where the constant is the camera InvM shows.
std::string cameraBlock(const CameraTextFix& fix, const Located& at, const std::string& indent, const std::string& nl) {
  const std::string s = std::string(kPrefix) + "_stereo", c = std::string(kPrefix) + "_camera", in = indent + "  ";
  std::string t = indent + "// ---- stereoshift: this eye's camera (line " + std::to_string(fix.line) +
                  (fix.fromCamera ? ": v = position - camera" : ": v = camera - position") +
                  ", the camera the position's matrix shows) ----" + nl;
  t += indent + "{" + nl;
  t += in + "float4 " + s + " = StereoParams.Load(int3(0, 0, 0));" + nl;
  t += in + "float3 " + c + " = float3(" + fix.centre[0] + ", " + fix.centre[1] + ", " + fix.centre[2] + ")" +
       (fix.centre[3] == "1" ? "" : " / " + fix.centre[3]) + ";" + nl;
  t += in + "if (all(abs(float3(" + fix.camera[0] + ", " + fix.camera[1] + ", " + fix.camera[2] + ") - " + c +
       ") <= 0.0001 * (abs(" + c + ") + 1))) {" + nl;
  // c moves by +s.x*s.y*InvM[column of x]: c - p by as much, p - c by minus as much. (InvM's column
  // is the matrix's times the screen coordinate's half-width where that is not NDC.)
  const std::string op = fix.fromCamera ? " -= " : " += ", h = std::string(kPrefix) + "_half_width";
  std::string scale;
  if (fix.scaleFromTheMatrix) {
    t += halfWidthLines(fix.columnX, fix.columnZ, fix.translation, fix.affine, h, in + "  ", nl);
    scale = h + " * ";
  }
  for (size_t i = 0; i < 3; ++i)
    t += in + "  " + at.component[i] + op + s + ".x * " + s + ".y * " + scale + fix.columnX[i] + ";" + nl;
  t += in + "}" + nl;
  t += indent + "}" + nl + indent + "// ---- end stereoshift ----" + nl;
  return t;
}

// Where the two values a fix reads and writes live, found as a rebuild's components 0 and 3
// (locate()): each on the line of its statement, neither written or read again up to `afterLine`.
Located locatePair(const Lines& lines, uint32_t afterLine, const std::array<uint32_t, 2>& at,
                   const std::array<uint32_t, 2>& lanes) {
  RowProductTextFix asProduct;
  asProduct.afterLine = afterLine;
  asProduct.present = {true, false, false, true};
  asProduct.lines = {at[0], 0, 0, at[1]};
  asProduct.lanes = {lanes[0], 0, 0, lanes[1]};
  return locate(lines, asProduct);
}

// Where a re-projection's clip x and w live: as a rebuild's components 0 and 3 (locate()), the
// lines between them and the block neither rewriting nor reading x.
Located locateReprojection(const Lines& lines, const ReprojectionTextFix& fix) {
  Located at = locatePair(lines, fix.afterLine, fix.lines, fix.lanes);
  if (at.error.find("rebuilt position") != std::string::npos) {
    // Say it of what it is.
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"the rebuilt position's statements", "clip x and w"},
                                   {"the rebuilt position is complete", "clip x is corrected"},
                                   {"component 0 of the rebuilt position", "clip x"},
                                   {"component 3 of the rebuilt position", "clip w"}})
      if (size_t k = at.error.find(from); k != std::string::npos) at.error.replace(k, from.size(), to);
  }
  return at;
}

// clip.x += a * s.x * (clip.w - s.y), a = VP's row of x times InvM's column of NDC x.
std::string reprojectionBlock(const ReprojectionTextFix& fix, const Located& at, const std::string& indent,
                              const std::string& nl) {
  const std::string s = std::string(kPrefix) + "_stereo", in = indent + "  ";
  std::string t = indent + "// ---- stereoshift: this eye's re-projection (line " + std::to_string(fix.afterLine) +
                  ": clip = VP * (p, 1) of the corrected position, the depth read at it again) ----" + nl;
  t += indent + "{" + nl;
  t += in + "float4 " + s + " = StereoParams.Load(int3(0, 0, 0));" + nl;
  t += in + at.component[0] + " += dot(" + float3Of(fix.rowX) + ", " + float3Of(fix.column) + ") * " + s + ".x * (" +
       at.component[3] + " - " + s + ".y);" + nl;
  t += indent + "}" + nl + indent + "// ---- end stereoshift ----" + nl;
  return t;
}

// Where an interpolated ray's p.x and p.z live (as a rebuild's components 0 and 3, locate()), and the
// name of the pixel-position input (`float4 v0 : SV_Position0`) whose x the block reads.
Located locateInterpolatedRay(const Lines& lines, const InterpolatedRayTextFix& fix) {
  Located at = locatePair(lines, fix.afterLine, fix.lines, fix.lanes);
  if (!at.error.empty()) return at;
  static const std::regex position(R"(\b([A-Za-z_]\w*)\s*:\s*SV_Position\d*\b)", std::regex::icase);
  std::smatch m;
  if (!std::regex_search(lines.text, m, position))
    return failedAt(at, fix.afterLine, "the shader has no SV_Position input, whose x tells the ray's 1/P00");
  at.depth = m[1].str() + ".x";
  return at;
}

// p.x -= s.x * (|p.z| - s.y) * sign(p.z) * k with k = x * ddx(ratio) - ratio (InterpolatedRayTextFix),
// where the ray's z is the far plane's (a full-screen pass's ray, kept mono); nothing for another.
std::string interpolatedRayBlock(const InterpolatedRayTextFix& fix, const Located& at, const std::string& indent,
                                 const std::string& nl) {
  const std::string s = std::string(kPrefix) + "_stereo", ratio = std::string(kPrefix) + "_ratio",
                    k = std::string(kPrefix) + "_k", d = std::string(kPrefix) + "_d", in = indent + "  ";
  const std::string& px = at.component[0], pz = at.component[3];
  std::string t = indent + "// ---- stereoshift: this eye's position rebuild (line " + std::to_string(fix.afterLine) +
                  ": p = ray * (" + fix.farPlane + " / " + fix.rayZ + ") * depth, the ray a full-screen pass's) ----" + nl;
  t += indent + "{" + nl;
  t += in + "float4 " + s + " = StereoParams.Load(int3(0, 0, 0));" + nl;
  t += in + "float " + ratio + " = " + fix.rayX + " / " + fix.rayZ + ";" + nl;
  t += in + "float " + k + " = " + at.depth + " * ddx(" + ratio + ") - " + ratio + ";" + nl;
  t += in + "float " + d + " = " + s + ".x * (abs(" + pz + ") - " + s + ".y) * sign(" + pz + ") * " + k + ";" + nl;
  // A full-screen pass's rays share one z, the far plane's (up to the fp32 rounding of a far point
  // an inverse projection makes, ulp * far / near); a light volume's z is its surface's depth.
  t += in + "if (abs(" + fix.farPlane + " / " + fix.rayZ + " - 1) > 0.01 || ddx(" + fix.rayZ + ") != 0 || ddy(" +
       fix.rayZ + ") != 0) " + d + " = 0;" + nl;
  t += in + px + " -= " + d + ";" + nl;
  t += indent + "}" + nl + indent + "// ---- end stereoshift ----" + nl;
  return t;
}

// Inserts `block` after line `line`, with a line break first when the file's last line has none.
void insertAfterLine(EditBuffer& edits, const Lines& lines, const std::string& source, uint32_t line, std::string block) {
  size_t end = lines.endOf(line);
  if (end == source.size() && (source.empty() || source.back() != '\n')) block = edits.newline() + block;
  edits.add(end, 0, std::move(block));
}

}  // namespace

HlslSpliceResult splicePixelCorrections(const std::string& source, const DeferredFacts& facts,
                                        const std::string& entryPoint) {
  HlslSpliceResult result;
  TokenView view(source);
  TopLevel top;
  std::optional<SpliceError> err = view.scan();
  if (!err) err = parseTopLevel(view, top);
  const Function* entry = nullptr;
  for (const auto& f : top.functions)
    if (!err && view.text(f.nameTok) == entryPoint) entry = &f;
  if (!err && !entry) err = SpliceError{npos, "entry point '" + entryPoint + "' not found"};
  if (err) {
    result.error = err->message;
    if (err->offset != npos) view.locate(err->offset, result.line, result.column);
    return result;
  }
  EditBuffer edits(source);
  Lines lines(source);
  auto failAt = [&](const Located& at, const std::string& what) {
    result.error = "cannot place this eye's " + what + ": " + at.error;
    result.line = static_cast<int>(at.errorLine);
    std::string text = lines.line(at.errorLine);
    result.column = static_cast<int>(std::min(text.find_first_not_of(" \t"), text.size())) + 1;
  };
  // Each fix of one kind: where its values live in the text (or why it cannot be placed), its block
  // after the line `after` names. False when one cannot be placed (result says where and why).
  auto place = [&](const auto& fixes, auto locateFix, auto block, const std::string& what, auto after) {
    for (const auto& fix : fixes) {
      Located at = locateFix(lines, fix);
      if (!at.error.empty()) {
        failAt(at, what);
        return false;
      }
      const uint32_t line = after(fix);
      insertAfterLine(edits, lines, source, line, block(fix, at, indentOf(lines.line(line)), edits.newline()));
      ++result.sites;
    }
    return true;
  };
  auto afterLine = [](const auto& fix) { return fix.afterLine; };
  auto line = [](const auto& fix) { return fix.line; };
  if (!place(facts.textFixes, locate, correctionBlock, "position rebuild", afterLine) ||
      !place(facts.cameraTextFixes, locateCamera, cameraBlock, "camera", line) ||
      !place(facts.reprojectionTextFixes, locateReprojection, reprojectionBlock, "re-projection", afterLine) ||
      !place(facts.interpolatedRayTextFixes, locateInterpolatedRay, interpolatedRayBlock, "position rebuild", afterLine) ||
      !place(facts.rayTextFixes, locateRay, rayBlock, "view-space position", line))
    return result;
  // The dump's own declaration (its "3Dmigoto declarations") is the one 3Dmigoto binds.
  if (!top.names.count("StereoParams")) {
    for (size_t k = 0; k + 2 < view.tokens.size(); ++k)
      if (view.isWord(k, "register") && view.isPunct(k + 1, '(') && lower(view.text(k + 2)) == "t125") {
        result.error = "register(t125) is taken by another resource: 3Dmigoto's StereoParams texture lives there";
        view.locate(view.tokens[k + 2].begin, result.line, result.column);
        result.clash = true;
        return result;
      }
    const std::string& nl = edits.newline();
    insertBlockBefore(edits, view, view.tokens[entry->declBegin].begin, 0,
                      "// ---- stereoshift: 3Dmigoto's stereo parameters (injected) ----" + nl +
                          "Texture2D<float4> StereoParams : register(t125);" + nl + "// ---- end stereoshift ----" + nl);
  }
  result.text = edits.apply();
  result.ok = true;
  return result;
}

}  // namespace stereoshift
