// Turns ReprojectOptions into the reprojection pass's shaders (see reproject_shaders.h): writes them
// as GLSL text with the eye parameters declared the way the eye-params pass declares them, then
// hands each one to transpile(), which compiles, validates and emits it for the target language.
#include "transpiler/reproject/reproject_shaders.h"

#include "passes/pass.h"
#include "transpiler/stereoshift.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <tuple>
#include <utility>

namespace stereoshift {

namespace {

// The name of `value` in `names`; "?" for a value the table lacks.
template <class E, size_t N>
const char* nameIn(const std::pair<E, const char*> (&names)[N], E value) {
  for (const auto& [known, name] : names)
    if (known == value) return name;
  return "?";
}

}  // namespace

const char* reprojectDepthName(ReprojectDepth d) {
  static constexpr std::pair<ReprojectDepth, const char*> kNames[] = {
      {ReprojectDepth::Linear, "linear"}, {ReprojectDepth::ZeroToOne, "zero-to-one"},
      {ReprojectDepth::MinusOneToOne, "minus-one-to-one"}};
  return nameIn(kNames, d);
}
const char* reprojectRefinementName(ReprojectRefinement r) {
  static constexpr std::pair<ReprojectRefinement, const char*> kNames[] = {
      {ReprojectRefinement::None, "none"}, {ReprojectRefinement::Bisection, "bisection"},
      {ReprojectRefinement::Secant, "secant"}};
  return nameIn(kNames, r);
}
const char* reprojectColourName(ReprojectColour c) {
  return c == ReprojectColour::Nearest ? "nearest" : "interpolated";
}
const char* disocclusionFillName(DisocclusionFill f) {
  return f == DisocclusionFill::Background ? "background" : "farther-sample";
}
const char* reprojectSourceName(ReprojectSource s) {
  static constexpr std::pair<ReprojectSource, const char*> kNames[] = {
      {ReprojectSource::LeftEye, "left"}, {ReprojectSource::RightEye, "right"}, {ReprojectSource::Centre, "centre"}};
  return nameIn(kNames, s);
}

namespace {

EyeSource effectiveEyeSource(const ReprojectOptions& o) {
  return o.eye.source == EyeSource::Auto ? EyeSource::UniformBlock : o.eye.source;
}

// The eye block's binding: the option (the HLSL register when the output is HLSL), else the
// transpiler's rule, one past the highest binding the shader uses (the two textures).
uint32_t eyeBinding(const ReprojectOptions& o) {
  if (o.target == TargetLanguage::Hlsl && o.eye.hlslRegister) return *o.eye.hlslRegister;
  if (o.eye.binding) return *o.eye.binding;
  return std::max(o.colourBinding, o.depthBinding) + 1;
}

double sourceEyeSign(ReprojectSource s) {
  return s == ReprojectSource::LeftEye ? -1.0 : s == ReprojectSource::RightEye ? 1.0 : 0.0;
}

// A float literal that reads back as the nearest float to `value` (9 significant digits).
std::string floatLiteral(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(static_cast<float>(value)));
  std::string text = buffer;
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
  return text;
}

bool openGlSource(const ReprojectOptions& o) { return effectiveEyeSource(o) == EyeSource::LooseUniforms; }

std::string versionLine(const ReprojectOptions&) { return "#version 450\n"; }

}  // namespace

DepthDecode depthDecode(const ReprojectOptions& o) {
  DepthDecode decode;
  if (o.depth == ReprojectDepth::Linear) {
    decode.linear = true;
    return decode;
  }
  // z_ndc = -a + b / w for the projection's depth row (z_clip = a*z_eye + b, w_clip = -z_eye = w).
  double a, b;
  const bool openGl = o.depth == ReprojectDepth::MinusOneToOne;
  if (o.depthScale && o.depthOffset) {
    a = *o.depthScale;
    b = *o.depthOffset;
  } else {
    const double n = o.nearPlane;
    // z_ndc runs from lo (at the near plane) to hi (at the far plane); reversed-Z swaps them.
    const double lo = openGl ? -1.0 : 0.0, hi = 1.0;
    const double atNear = o.reversedZ ? hi : lo, atFar = o.reversedZ ? lo : hi;
    // -a + b/n = atNear, -a + b/f = atFar  =>  b = (atNear - atFar) / (1/n - 1/f), a = b/n - atNear
    const double inverseFar = o.farPlane ? 1.0 / *o.farPlane : 0.0;
    b = (atNear - atFar) / (1.0 / n - inverseFar);
    a = b / n - atNear;
  }
  // 1/w = (z_ndc + a) / b with z_ndc = stored ([0, 1]) or 2*stored - 1 ([-1, 1]).
  if (openGl) {
    decode.scale = 2.0 / b;
    decode.offset = (a - 1.0) / b;
  } else {
    decode.scale = 1.0 / b;
    decode.offset = a / b;
  }
  return decode;
}

std::vector<std::string> checkReprojectOptions(const ReprojectOptions& o) {
  std::vector<std::string> problems;
  if (o.samples < 2 || o.samples > 256)
    problems.push_back("--samples must be between 2 and 256 (got " + std::to_string(o.samples) + ")");
  if (o.refinementSteps < 0 || o.refinementSteps > 16)
    problems.push_back("--refine-steps must be between 0 and 16 (got " + std::to_string(o.refinementSteps) + ")");
  if (!(o.searchNear >= 0.0 && o.searchNear <= 16.0))
    problems.push_back("--search-near must be between 0 and 16 (times the maximum parallax)");
  if (o.depthScale.has_value() != o.depthOffset.has_value())
    problems.push_back("--depth-coefficients needs both coefficients");
  if (o.depth == ReprojectDepth::Linear && (o.depthScale || o.reversedZ))
    problems.push_back("--depth linear stores the eye depth itself: --depth-coefficients and --reversed-z do not apply");
  if (o.depthScale && o.depthOffset) {
    if (!std::isfinite(*o.depthScale) || !std::isfinite(*o.depthOffset) || *o.depthOffset == 0.0)
      problems.push_back("--depth-coefficients: the second coefficient (P[2][3]) must be finite and non-zero");
  } else if (o.depth != ReprojectDepth::Linear) {
    if (!(o.nearPlane > 0.0) || !std::isfinite(o.nearPlane))
      problems.push_back("--near must be a positive eye depth");
    if (o.farPlane && !(*o.farPlane > o.nearPlane && std::isfinite(*o.farPlane)))
      problems.push_back("--far must be farther than --near (or 'inf' for an infinite far plane)");
  }
  // The decode's two coefficients are written as float literals: past FLT_MAX they read as `inf`
  // (a near plane of 1e-40 gives a scale of about 1e40), and the shader decodes nothing.
  if (problems.empty()) {
    DepthDecode decode = depthDecode(o);
    auto fits = [](double v) { return std::isfinite(v) && std::abs(v) <= static_cast<double>(FLT_MAX); };
    if (!decode.linear && (!fits(decode.scale) || !fits(decode.offset)))
    {
      char values[96];
      std::snprintf(values, sizeof values, "scale %g, offset %g", decode.scale, decode.offset);
      problems.push_back(std::string("the depth decoding these --near/--far (or --depth-coefficients) give does not fit "
                                     "a float (") + values + "): choose a near plane of at least 1e-30 eye units");
    }
  }
  // Bindings are written as layout numbers; glslang's layout fields hold bindings below 65535 and sets
  // below 63 (found by fuzz_reproject_options: `--set 148`).
  for (const auto& [option, value, max] :
       {std::tuple{"--colour-binding", std::optional<uint32_t>(o.colourBinding), kMaxBinding},
        std::tuple{"--depth-binding", std::optional<uint32_t>(o.depthBinding), kMaxBinding},
        std::tuple{"--set", o.eye.descriptorSet, kMaxDescriptorSet}, std::tuple{"--binding", o.eye.binding, kMaxBinding},
        std::tuple{"--hlsl-register", o.eye.hlslRegister, kMaxBinding}})
    if (value)
      if (auto problem = layoutNumberOutOfRange(option, *value, max)) problems.push_back(*problem);
  // In OpenGL ES a sampler's binding is a texture unit: below gl_MaxCombinedTextureImageUnits, which
  // glslang (and the re-compile check) takes as 80 (found by fuzz_reproject_options: an ESSL pass
  // with --depth-binding 2148 did not compile). The same for OpenGL GLSL (loose uniforms).
  constexpr uint32_t kEsTextureUnits = 80;
  if (o.target == TargetLanguage::Essl || (o.target == TargetLanguage::Glsl && openGlSource(o)))
    for (const auto& [option, value] : {std::pair{"--colour-binding", o.colourBinding}, std::pair{"--depth-binding", o.depthBinding}})
      if (value >= kEsTextureUnits && value <= 65534)
        problems.push_back(std::string(option) + " " + std::to_string(value) + " is out of range for an OpenGL (ES) target (valid: 0 to " +
                           std::to_string(kEsTextureUnits - 1) + ", a texture unit)");
  if (o.colourBinding == o.depthBinding) problems.push_back("the colour and depth textures need different bindings");
  EyeSource source = effectiveEyeSource(o);
  if (source == EyeSource::UniformBlock) {
    uint32_t b = eyeBinding(o);
    if (b == o.colourBinding || b == o.depthBinding)
      problems.push_back("--binding " + std::to_string(b) + " is a source texture's binding");
  }
  if (source == EyeSource::LooseUniforms &&
      (o.target == TargetLanguage::Spirv || o.target == TargetLanguage::SpirvAsm))
    problems.push_back("--eye-source=loose-uniforms needs an OpenGL GLSL or ESSL target; SPIR-V for Vulkan has no "
                       "default-block uniforms (use uniform-block, push-constant or spec-constant)");
  if (source == EyeSource::LooseUniforms && o.target == TargetLanguage::Msl)
    problems.push_back("--eye-source=loose-uniforms needs an OpenGL GLSL or ESSL target");
  return problems;
}

std::string reprojectVertexSource(const ReprojectOptions& o) {
  std::string index = openGlSource(o) ? "gl_VertexID" : "gl_VertexIndex";
  return versionLine(o) +
         "// stereoshift reproject: one triangle that covers the viewport (vertices 0, 1, 2 at NDC\n"
         "// (-1,-1), (3,-1), (-1,3)); draw it with 3 vertices and no vertex buffer. w = 1: never shifted.\n"
         "void main() {\n"
         "  vec2 corner = vec2(float((" + index + " << 1) & 2), float(" + index + " & 2));\n"
         "  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);\n"
         "}\n";
}

namespace {

// The fragment shader's opening comment and its two source textures.
void appendSourceTextures(std::ostringstream& s, const ReprojectOptions& o) {
  const EyeParamOptions& e = o.eye;
  const bool gl = openGlSource(o);
  const uint32_t set = e.descriptorSet.value_or(0);
  s << "// stereoshift reproject: synthesizes the eye " << e.eyeSignName << " (-1 left, +1 right) from the "
    << (o.source == ReprojectSource::Centre ? "centre (mono) view" : std::string(reprojectSourceName(o.source)) + " eye")
    << "'s colour and depth.\n"
       "// For each pixel it searches this row of the source for the surface point that lands on it\n"
       "// (docs/stereo-math.md section 5).\n";
  auto binding = [&](uint32_t b) {
    return gl ? "layout(binding = " + std::to_string(b) + ") "
              : "layout(set = " + std::to_string(set) + ", binding = " + std::to_string(b) + ") ";
  };
  s << binding(o.colourBinding) << "uniform sampler2D sourceColour;\n";
  s << binding(o.depthBinding) << "uniform sampler2D sourceDepth;\n";
}

// The eye parameters, declared the way the eye-params pass declares them; returns how the code
// reads each (eyeSign, separation, convergence).
std::array<std::string, 3> appendEyeParameters(std::ostringstream& s, const ReprojectOptions& o) {
  const EyeParamOptions& e = o.eye;
  const EyeSource source = effectiveEyeSource(o);
  const uint32_t set = e.descriptorSet.value_or(0);
  // The eye parameters: the first three of the eye-params pass's (member i at byte offset 4*i).
  const std::string* names[3] = {&e.eyeSignName, &e.separationName, &e.convergenceName};
  std::array<std::string, 3> access;
  switch (source) {
    case EyeSource::SpecConstant:
      for (int i = kEyeSign; i <= kConvergence; ++i) {
        s << "layout(constant_id = " << e.specIdBase + i << ") const float " << *names[i] << " = "
          << floatLiteral(eyeParamDefaultValue(i)) << ";\n";
        access[i] = *names[i];
      }
      break;
    case EyeSource::LooseUniforms:
      for (int i = kEyeSign; i <= kConvergence; ++i) {
        s << "uniform float " << *names[i] << ";\n";
        access[i] = *names[i];
      }
      break;
    default: {
      if (source == EyeSource::PushConstant)
        s << "layout(push_constant) uniform ";
      else
        s << "layout(set = " << set << ", binding = " << eyeBinding(o) << ", std140) uniform ";
      s << e.blockName << " {\n";
      for (int i = kEyeSign; i <= kConvergence; ++i) {
        s << "  float " << *names[i] << ";\n";
        access[i] = e.instanceName + "." + *names[i];
      }
      s << "} " << e.instanceName << ";\n";
      break;
    }
  }
  return access;
}

// The outputs, the search's constants and the depth decode's.
void appendConstants(std::ostringstream& s, const ReprojectOptions& o, const DepthDecode& decode) {
  s << "layout(location = 0) out vec4 reprojectedColour;\n";
  if (o.maskOutput) s << "layout(location = 1) out float disocclusionMask;  // 1: not seen by the source\n";
  s << "\n"
    << "const float kSourceEyeSign = " << floatLiteral(sourceEyeSign(o.source)) << ";\n"
    << "const int kSamples = " << o.samples << ";\n"
    << "// Parallax factors t = 1 - C/w searched: from -kSearchNear (in front of the screen) to 1 (infinity).\n"
    << "const float kSearchNear = " << floatLiteral(o.searchNear) << ";\n";
  if (!decode.linear)
    s << "// 1/w = stored depth * kDepthScale + kDepthOffset (" << reprojectDepthName(o.depth)
      << (o.reversedZ ? ", reversed-Z" : "") << ")\n"
      << "const float kDepthScale = " << floatLiteral(decode.scale) << ";\n"
      << "const float kDepthOffset = " << floatLiteral(decode.offset) << ";\n";
}

// The helpers: 1/w of a texel, the column clamp, the residual of a hypothesis, a colour fetch.
void appendHelpers(std::ostringstream& s, const DepthDecode& decode) {
  s << "\n"
       "// 1/w of texel `column` of `row`: exact from the stored depth, no division for device depth.\n"
       "float inverseEyeDepth(int column, int row) {\n"
       "  float stored = texelFetch(sourceDepth, ivec2(column, row), 0).r;\n";
  if (decode.linear)
    s << "  return 1.0 / stored;\n";
  else
    s << "  return stored * kDepthScale + kDepthOffset;\n";
  s << "}\n"
       "\n"
       "int columnAt(float x, int width) { return clamp(int(floor(x)), 0, width - 1); }\n"
       "\n"
       "// A point with parallax factor t that lands on `target` comes from source x = target - k*t.\n"
       "// The residual is the factor the source shows there minus t: zero where the hypothesis holds.\n"
       "float residual(float t, float target, float k, int row, int width, float screenDepth) {\n"
       "  float x = target - k * t;\n"
       "  return (1.0 - screenDepth * inverseEyeDepth(columnAt(x, width), row)) - t;\n"
       "}\n"
       "\n"
       "vec4 colourAt(float x, int row, int width) {\n"
       "  return texelFetch(sourceColour, ivec2(columnAt(x, width), row), 0);\n"
       "}\n"
       "\n";
}

// main() up to the linear search's bracket of the visible surface.
void appendSearch(std::ostringstream& s, const std::array<std::string, 3>& access) {
  s << "void main() {\n"
       "  int width = textureSize(sourceDepth, 0).x;\n"
       "  int row = int(gl_FragCoord.y);\n"
       "  float target = gl_FragCoord.x;\n"
       "  float screenDepth = " << access[kConvergence] << ";\n"
       "  // Pixels the target moves per unit of t against the source: (e_target - e_source) * S * width/2.\n"
       "  float k = (" << access[kEyeSign] << " - kSourceEyeSign) * " << access[kSeparation] << " * 0.5 * float(width);\n"
       "  // Linear search from the nearest hypothesis to the farthest: the first one whose residual is\n"
       "  // not positive brackets the visible surface (nearer points that land here occlude farther ones).\n"
       "  float tLo = -kSearchNear;\n"
       "  float rLo = residual(tLo, target, k, row, width, screenDepth);\n"
       "  float tHi = tLo;\n"
       "  float rHi = rLo;\n"
       "  bool crossed = rLo <= 0.0;\n"
       "  for (int i = 1; i < kSamples && !crossed; ++i) {\n"
       "    float t = mix(-kSearchNear, 1.0, float(i) / float(kSamples - 1));\n"
       "    float r = residual(t, target, k, row, width, screenDepth);\n"
       "    if (r <= 0.0) {\n"
       "      tHi = t;\n"
       "      rHi = r;\n"
       "      crossed = true;\n"
       "    } else {\n"
       "      tLo = t;\n"
       "      rLo = r;\n"
       "    }\n"
       "  }\n"
       "  if (!crossed) {  // only when the stored depth lies beyond infinity by rounding: the farthest sample\n"
       "    tHi = tLo;\n"
       "    rHi = rLo;\n"
       "  }\n"
       "  bool bracketed = tHi > tLo;\n";
}

// One step inside the bracket, shared by the refinement and the background fill: the residual at
// t, and t replaces the bracket's end on its side. `indent` is the loop body's.
std::string bracketStep(const std::string& indent) {
  return indent + "float r = residual(t, target, k, row, width, screenDepth);\n" + indent + "if (r <= 0.0) {\n" +
         indent + "  tHi = t;\n" + indent + "  rHi = r;\n" + indent + "} else {\n" + indent + "  tLo = t;\n" +
         indent + "  rLo = r;\n" + indent + "}\n";
}

// The bracket's refinement (bisection or secant steps), when asked for.
void appendRefinement(std::ostringstream& s, const ReprojectOptions& o) {
  if (o.refinement != ReprojectRefinement::None && o.refinementSteps > 0) {
    s << "  // Refinement: " << reprojectRefinementName(o.refinement) << " steps inside the bracket.\n"
      << "  for (int j = 0; j < " << o.refinementSteps << " && bracketed; ++j) {\n";
    if (o.refinement == ReprojectRefinement::Bisection)
      s << "    float t = 0.5 * (tLo + tHi);\n";
    else
      s << "    float t = tLo + (tHi - tLo) * (rLo / (rLo - rHi));  // rLo > 0 >= rHi\n";
    s << bracketStep("    ") << "  }\n";
  }
}

// The end of main(): disocclusion, the colour of a hit, the outputs.
void appendResolve(std::ostringstream& s, const ReprojectOptions& o) {
  s << "  // The bracket's two source points land |k|*(rLo - rHi) pixels apart; a continuous surface lands\n"
       "  // them about as far apart as they are (|k|*(tHi - tLo)). Much farther: the bracket spans a depth\n"
       "  // edge whose far side moved away from its near side, and this pixel is disoccluded.\n"
       "  float spread = abs(k);\n"
       "  bool disoccluded = bracketed && spread * (rLo - rHi) > 2.0 * spread * (tHi - tLo) + 1.0;\n"
       "  vec4 colour;\n"
       "  if (disoccluded) {\n";
  if (o.fill == DisocclusionFill::Background)
    s << "    // Background repeat: narrow the bracket onto the edge, then take the far side's texel there.\n"
         "    for (int j = 0; j < 16 && spread * (tHi - tLo) > 1.0; ++j) {\n"
         "      float t = 0.5 * (tLo + tHi);\n"
      << bracketStep("      ") << "    }\n";
  else
    s << "    // Nearest farther sample: the bracket's far end as the search found it.\n";
  s << "    colour = colourAt(target - k * tLo, row, width);\n"
       "  } else {\n"
       "    // Where the residual crosses zero between the bracket's ends (a secant step).\n"
       "    float alpha = bracketed ? rLo / (rLo - rHi) : 1.0;\n";
  if (o.colour == ReprojectColour::Nearest)
    s << "    colour = colourAt(target - k * mix(tLo, tHi, alpha), row, width);\n";
  else
    s << "    colour = mix(colourAt(target - k * tLo, row, width), colourAt(target - k * tHi, row, width), alpha);\n";
  s << "  }\n"
       "  reprojectedColour = colour;\n";
  if (o.maskOutput) s << "  disocclusionMask = disoccluded ? 1.0 : 0.0;\n";
  s << "}\n";
}

}  // namespace

std::string reprojectFragmentSource(const ReprojectOptions& o) {
  std::ostringstream s;
  s << versionLine(o);
  appendSourceTextures(s, o);
  const std::array<std::string, 3> access = appendEyeParameters(s, o);
  const DepthDecode decode = depthDecode(o);
  appendConstants(s, o, decode);
  appendHelpers(s, decode);
  appendSearch(s, access);
  appendRefinement(s, o);
  appendResolve(s, o);
  return s.str();
}

nlohmann::json describeReprojectOptions(const ReprojectOptions& o) {
  nlohmann::json j;
  static const char* kEyeSources[] = {"auto", "uniform-block", "push-constant", "spec-constant", "loose-uniforms"};
  j["source_view"] = reprojectSourceName(o.source);
  j["eye"]["source"] = kEyeSources[static_cast<int>(effectiveEyeSource(o))];
  j["eye"]["names"] = {o.eye.eyeSignName, o.eye.separationName, o.eye.convergenceName};
  switch (effectiveEyeSource(o)) {
    case EyeSource::UniformBlock:
      j["eye"]["block"] = o.eye.blockName;
      j["eye"]["instance"] = o.eye.instanceName;
      j["eye"]["set"] = o.eye.descriptorSet.value_or(0);
      j["eye"]["binding"] = eyeBinding(o);
      break;
    case EyeSource::PushConstant:
      j["eye"]["block"] = o.eye.blockName;
      j["eye"]["instance"] = o.eye.instanceName;
      j["eye"]["offset"] = 0;
      break;
    case EyeSource::SpecConstant:
      j["eye"]["specIds"] = {o.eye.specIdBase + kEyeSign, o.eye.specIdBase + kSeparation, o.eye.specIdBase + kConvergence};
      break;
    default: break;
  }
  j["textures"] = {{"colour", {{"set", o.eye.descriptorSet.value_or(0)}, {"binding", o.colourBinding}}},
                   {"depth", {{"set", o.eye.descriptorSet.value_or(0)}, {"binding", o.depthBinding}}}};
  j["depth"]["kind"] = reprojectDepthName(o.depth);
  if (o.depth != ReprojectDepth::Linear) {
    j["depth"]["reversed_z"] = o.reversedZ;
    if (o.depthScale && o.depthOffset) {
      j["depth"]["coefficients"] = {*o.depthScale, *o.depthOffset};
    } else {
      j["depth"]["near"] = o.nearPlane;
      if (o.farPlane) j["depth"]["far"] = *o.farPlane;
      else j["depth"]["far"] = "inf";
    }
    DepthDecode d = depthDecode(o);
    j["depth"]["inverse_depth"] = {{"scale", d.scale}, {"offset", d.offset}};
  }
  j["search"] = {{"samples", o.samples},
                 {"near", o.searchNear},
                 {"refinement", reprojectRefinementName(o.refinement)},
                 {"refinement_steps", o.refinement == ReprojectRefinement::None ? 0 : o.refinementSteps},
                 {"colour", reprojectColourName(o.colour)}};
  j["disocclusion"] = {{"fill", disocclusionFillName(o.fill)}, {"mask_output", o.maskOutput}};
  return j;
}

namespace {

std::string outputName(Stage stage, TargetLanguage target) {
  std::string base = stage == Stage::Vertex ? "reproject.vert" : "reproject.frag";
  switch (target) {
    case TargetLanguage::Essl: return stage == Stage::Vertex ? "reproject.es.vert" : "reproject.es.frag";
    case TargetLanguage::Hlsl: return base + ".hlsl";
    case TargetLanguage::Msl: return base + ".metal";
    case TargetLanguage::Spirv: return base + ".spv";
    case TargetLanguage::SpirvAsm: return base + ".spvasm";
    default: return base;
  }
}

}  // namespace

ReprojectResult generateReprojectShaders(const ReprojectOptions& options) {
  ReprojectResult result;
  for (const auto& problem : checkReprojectOptions(options)) result.diagnostics.error("stereoshift reproject", problem);
  if (result.diagnostics.errorCount()) return result;
  result.report = describeReprojectOptions(options);

  TranspileOptions t;
  t.target = options.target;
  t.targetVersion = options.targetVersion;
  t.forceReemit = true;
  // The generated shaders need no stereo pass: the vertex shader is 2D (w = 1) and the fragment
  // shader declares its eye parameters itself. Classification only, for the report.
  t.onlyPasses = {"clip-position-detection"};
  t.perEyeView = false;
  t.deferredUnprojection = false;
  if (openGlSource(options)) t.targetEnv = TargetEnv::OpenGL45;
  t.eye = options.eye;

  struct Job {
    Stage stage;
    std::string text;
  };
  const Job jobs[] = {{Stage::Vertex, reprojectVertexSource(options)},
                      {Stage::Fragment, reprojectFragmentSource(options)}};
  bool ok = true;
  for (const Job& job : jobs) {
    TranspileOptions stageOptions = t;
    stageOptions.stage = job.stage;
    // The generated source's own name, so a problem points at the text the report shows.
    SourceFile file{job.stage == Stage::Vertex ? "reproject.vert" : "reproject.frag", job.text};
    TranspileResult converted = transpile(file, stageOptions);
    result.diagnostics.append(converted.diagnostics);
    nlohmann::json entry;
    entry["file"] = outputName(job.stage, options.target);
    entry["stage"] = stageName(job.stage);
    if (converted.record.target) entry["target"] = targetName(*converted.record.target);
    entry["verified"] = converted.record.verified;
    result.report["outputs"].push_back(entry);
    if (!converted.ok) {
      ok = false;
      continue;
    }
    ReprojectShader shader;
    shader.stage = job.stage;
    shader.fileName = outputName(job.stage, options.target);
    shader.output = std::move(converted.output);
    shader.binary = converted.binaryOutput;
    result.shaders.push_back(std::move(shader));
  }
  result.ok = ok;
  if (!ok) result.shaders.clear();
  return result;
}

}  // namespace stereoshift
