// See text_only_shift.h.
#include "transpiler/text_only_shift.h"

#include "passes/pass.h"
#include "passes/shift_emitter.h"
#include "transpiler/backend/glsl_splice.h"
#include "transpiler/frontend/glsl_lift.h"
#include "transpiler/frontend/glsl_version.h"
#include "transpiler/source/lexer.h"

#include <algorithm>
#include <charconv>
#include <optional>
#include <set>

namespace stereoshift {

namespace {

// What the text says about itself, read with the lexer.
struct TextFacts {
  std::string problem;             // why the text is not clean enough to splice
  bool writesPosition = false;     // gl_Position (or a component of it) assigned
  bool wMayBeOtherThanOne = false; // a write of gl_Position's w the text does not show is the literal 1
  bool vulkan = false;             // descriptor sets, push constants or Vulkan built-ins
  bool hasPushConstants = false;
  std::optional<uint32_t> highestBinding;
  std::vector<std::string> identifiers;  // every identifier, for clashes
};


bool isPunct(const source::LexedText& lexed, size_t k, char c) { return lexed.isPunct(k, c); }
bool has(const TextFacts& facts, const std::string& name);

// Whether `spelled` is a literal one (`1`, `1.0`, `1.`, `1.0f`, `1e0`, `1.0lf`).
bool isLiteralOne(std::string_view spelled) {
  while (!spelled.empty() && (spelled.back() == 'f' || spelled.back() == 'F' || spelled.back() == 'l' ||
                              spelled.back() == 'L' || spelled.back() == 'u' || spelled.back() == 'U'))
    spelled.remove_suffix(1);
  if (spelled.empty() || spelled.starts_with("0x") || spelled.starts_with("0X")) return false;
  double value = 0;
  auto [end, ec] = std::from_chars(spelled.data(), spelled.data() + spelled.size(), value);
  return ec == std::errc() && end == spelled.data() + spelled.size() && value == 1.0;
}

// The text's 2D proof, one occurrence of gl_Position at a time: whether this one leaves the w of the
// position the literal 1 or untouched. `code` holds the indices of the code tokens (comments left
// out), `at` the occurrence's place in it. Taken as such: a read; a write of lanes without w; a
// declaration (`vec4 gl_Position;` in a redeclared block, `invariant gl_Position;`); `gl_Position =
// vec4(..., 1.0);` (the constructor's last argument the literal one, nothing after it) and
// `gl_Position.w = 1.0;`. Anything else that may write w is not: a compound assignment, an increment,
// an index, another right-hand side, the position handed to a function (an out parameter writes it).
bool occurrenceKeepsUnitW(const source::LexedText& lexed, const std::vector<size_t>& code, size_t at) {
  auto punct = [&](size_t i, char c) { return i < code.size() && lexed.isPunct(code[i], c); };
  auto word = [&](size_t i) { return i < code.size() ? lexed.text(code[i]) : std::string_view(); };
  if (at > 0 && (punct(at - 1, '.') || word(at - 1) == "vec4" || word(at - 1) == "invariant" ||
                 word(at - 1) == "precise"))
    return !punct(at - 1, '.') || !(punct(at + 1, '=') && !punct(at + 2, '='));  // gl_out[i].gl_Position = ...
  size_t n = at + 1;
  bool coversW = true;
  std::string_view mask;  // the lanes written, when a swizzle names them
  if (punct(n, '.') && n + 1 < code.size() && lexed.isIdentifier(code[n + 1])) {
    mask = word(n + 1);
    coversW = mask.find_first_of("waq") != std::string_view::npos;
    n += 2;
  } else if (punct(n, '[')) {
    return false;  // gl_Position[i]: a lane by index, not told apart from w
  }
  const bool compound = (punct(n, '+') || punct(n, '-') || punct(n, '*') || punct(n, '/')) && punct(n + 1, '=');
  const bool increment = (punct(n, '+') && punct(n + 1, '+')) || (punct(n, '-') && punct(n + 1, '-')) ||
                         (at >= 2 && ((punct(at - 1, '+') && punct(at - 2, '+')) || (punct(at - 1, '-') && punct(at - 2, '-'))));
  if (compound || increment) return !coversW;
  const bool assigned = punct(n, '=') && !punct(n + 1, '=');
  if (!assigned) {
    // A read; but handed to a function as a whole argument, an out parameter may write it.
    const bool argument = at > 0 && (punct(at - 1, '(') || punct(at - 1, ',')) && (punct(n, ')') || punct(n, ','));
    return !argument;
  }
  if (!coversW) return true;
  auto literalOneAt = [&](size_t i) {
    return i < code.size() && lexed[code[i]].kind == source::TokenKind::Number && isLiteralOne(word(i));
  };
  if (!mask.empty())  // `gl_Position.w = 1.0;`
    return mask.size() == 1 && literalOneAt(n + 1) && punct(n + 2, ';');
  // `gl_Position = vec4( ... , 1.0 );`: the last argument at the constructor's own depth.
  if (word(n + 1) != "vec4" || !punct(n + 2, '(')) return false;
  int depth = 0;
  size_t lastArgument = n + 3, i = n + 2;
  for (; i < code.size(); ++i) {
    if (punct(i, '(') || punct(i, '[')) ++depth;
    if (punct(i, ')') || punct(i, ']')) --depth;
    if (depth == 1 && punct(i, ',')) lastArgument = i + 1;
    if (depth == 0) break;
  }
  return i < code.size() && i == lastArgument + 1 && literalOneAt(lastArgument) && punct(i + 1, ';');
}

// Whether every occurrence of gl_Position in the text keeps its w the literal 1 (or untouched), none
// of them in a macro (its uses cannot be read without expanding it).
bool keepsUnitW(const source::LexedText& lexed) {
  std::vector<size_t> code;
  for (size_t k = 0; k < lexed.size(); ++k) {
    if (lexed[k].inDirective() && lexed.isIdentifier(k) && lexed.text(k) == "gl_Position") return false;
    if (lexed[k].isCode()) code.push_back(k);
  }
  for (size_t i = 0; i < code.size(); ++i)
    if (lexed.isIdentifier(code[i]) && lexed.text(code[i]) == "gl_Position" && !occurrenceKeepsUnitW(lexed, code, i))
      return false;
  return true;
}

TextFacts readText(const std::string& text) {
  TextFacts facts;
  source::LexedText lexed(text);
  std::vector<char> open;
  for (size_t k = 0; k < lexed.size(); ++k) {
    const source::Token& t = lexed[k];
    if (t.unterminated) {
      facts.problem = "an unterminated comment or string at line " + std::to_string(t.line);
      return facts;
    }
    if (t.kind == source::TokenKind::Comment || t.kind == source::TokenKind::Directive) continue;
    std::string_view word = lexed.text(k);
    if (!t.inDirective() && t.kind == source::TokenKind::Punctuation) {
      char c = word[0];
      if (c == '(' || c == '[' || c == '{') open.push_back(c);
      if (c == ')' || c == ']' || c == '}') {
        char want = c == ')' ? '(' : c == ']' ? '[' : '{';
        if (open.empty() || open.back() != want) {
          facts.problem = "an unbalanced '" + std::string(1, c) + "' at line " + std::to_string(t.line);
          return facts;
        }
        open.pop_back();
      }
    }
    if (t.kind != source::TokenKind::Identifier) continue;
    std::string name = source::spelledString(text, t);
    facts.identifiers.push_back(name);
    if (name == "set" || name == "gl_VertexIndex" || name == "gl_InstanceIndex" || name == "subpassInput" ||
        name == "push_constant" || name == "GL_KHR_vulkan_glsl")
      facts.vulkan = true;
    if (name == "push_constant") facts.hasPushConstants = true;
    if (name == "binding" && isPunct(lexed, k + 1, '=') && k + 2 < lexed.size() &&
        lexed[k + 2].kind == source::TokenKind::Number) {
      std::string_view digits = lexed.text(k + 2);
      uint32_t value = 0;
      auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
      if (ec == std::errc() && end == digits.data() + digits.size())
        facts.highestBinding = std::max(facts.highestBinding.value_or(0), value);
    }
    if (name == "gl_Position") {
      size_t n = k + 1;  // past `.xyz` or `[i]`
      if (isPunct(lexed, n, '.') && lexed.isIdentifier(n + 1)) n += 2;
      bool assigned = (isPunct(lexed, n, '=') && !isPunct(lexed, n + 1, '=')) ||
                      ((isPunct(lexed, n, '+') || isPunct(lexed, n, '-') || isPunct(lexed, n, '*') ||
                        isPunct(lexed, n, '/')) &&
                       lexed.isPunctPair(n, std::string(1, lexed.text(n)[0]) + "="));
      facts.writesPosition |= assigned;
    }
  }
  if (!open.empty()) facts.problem = "an unclosed '" + std::string(1, open.back()) + "'";
  if (facts.problem.empty() && has(facts, "gl_Position")) facts.wMayBeOtherThanOne = !keepsUnitW(lexed);
  return facts;
}

bool has(const TextFacts& facts, const std::string& name) {
  return std::find(facts.identifiers.begin(), facts.identifiers.end(), name) != facts.identifiers.end();
}

// The eye parameters as text for the splice; false with `why` when the source cannot have them so.
bool declareEyeParams(const TextFacts& facts, const VersionLine& v, bool legacy, const PassOptions& options,
                      GlslSpliceOptions& spec, std::string& declared, std::string& why) {
  const EyeParamOptions& o = options.eye;
  EyeSource source = o.source;
  if (source == EyeSource::Auto) source = facts.vulkan ? EyeSource::UniformBlock : EyeSource::LooseUniforms;
  bool vulkanOnly = source == EyeSource::PushConstant || source == EyeSource::SpecConstant;
  if (vulkanOnly && !facts.vulkan) {
    why = "push constants and specialization constants need Vulkan GLSL, and the text does not say it is";
    return false;
  }
  if (source == EyeSource::LooseUniforms && facts.vulkan) {
    why = "--eye-source=loose-uniforms needs an OpenGL GLSL shader, and the text is Vulkan GLSL";
    return false;
  }
  std::vector<std::string> names = {o.eyeSignName, o.separationName, o.convergenceName};
  switch (source) {
    case EyeSource::LooseUniforms:
      declared = "loose uniforms";
      return true;
    case EyeSource::SpecConstant:
      for (int i = 0; i < 3; ++i)
        spec.declarations.push_back("layout(constant_id = " + std::to_string(o.specIdBase + i) + ") const float " +
                                    names[i] + " = " + glslFloatLiteral(eyeParamDefaultValue(i)) + ";");
      declared = "specialization constants";
      return true;
    default:
      break;
  }
  if (legacy || (v.es ? v.version < 300 : v.version < 140)) {
    why = "GLSL below 140 and ESSL 100 have no uniform blocks: use --eye-source loose-uniforms";
    return false;
  }
  std::string layout;
  if (source == EyeSource::PushConstant) {
    if (facts.hasPushConstants) {
      why = "the shader has push constants of its own, which the text-only splice does not extend";
      return false;
    }
    layout = "push_constant";
    declared = "push constants";
  } else {
    if (facts.vulkan) {
      uint32_t binding = o.binding.value_or(facts.highestBinding ? *facts.highestBinding + 1 : 0);
      layout = "set = " + std::to_string(o.descriptorSet.value_or(0)) + ", binding = " + std::to_string(binding) + ", ";
    } else if (o.glBinding) {
      layout = "binding = " + std::to_string(*o.glBinding) + ", ";
    }
    layout += "std140";
    declared = "uniform block";
  }
  spec.declarations.push_back("layout(" + layout + ") uniform " + o.blockName);
  spec.declarations.push_back("{");
  for (const auto& name : names) spec.declarations.push_back("    float " + name + ";");
  spec.declarations.push_back("} " + o.instanceName + ";");
  spec.eyeSignName = o.instanceName + "." + names[0];
  spec.separationName = o.instanceName + "." + names[1];
  spec.convergenceName = o.instanceName + "." + names[2];
  for (const std::string* taken : {&o.blockName, &o.instanceName})
    if (has(facts, *taken)) {
      why = "the shader already uses the name '" + *taken + "'";
      return false;
    }
  return true;
}

}  // namespace

std::string glslangGapIn(const std::string& text) {
  if (text.find("\\\n") != std::string::npos || text.find("\\\r\n") != std::string::npos) return "a line continuation";
  // The #version line comes before the #extension lines: its profile is said first.
  source::LexedText lexed(text);
  for (size_t k = 0; k < lexed.size(); ++k)
    if (lexed[k].kind == source::TokenKind::Directive && lexed[k].directive == source::DirectiveKind::Version &&
        source::spelledString(text, lexed[k]).find("compatibility") != std::string::npos)
      return "the compatibility profile";
  // #include's extensions are glslang's own; every other one it may know only in part.
  if (enablesAnExtension(text)) return "an #extension";
  return {};
}

const std::vector<std::string>& textOnlyNotDone() {
  static const std::vector<std::string> notDone = {
      "2D proof (the runtime cutoff keeps w = 1 draws mono)", "halo copies of the clip position", "per-eye view vectors",
      "deferred unprojection", "HUD placement", "re-compile of the output"};
  return notDone;
}

bool mayShiftFromText(Stage stage, SourceLanguage language, const PassOptions& passes, const BackEndOptions& backEnd) {
  bool preRaster = stage == Stage::Vertex || stage == Stage::TessEvaluation || stage == Stage::Geometry;
  bool sameLanguage = backEnd.target == TargetLanguage::Auto ||
                      (language == SourceLanguage::Glsl
                           ? backEnd.target == TargetLanguage::Glsl || backEnd.target == TargetLanguage::Essl
                           : language == SourceLanguage::Hlsl && backEnd.target == TargetLanguage::Hlsl);
  return preRaster && sameLanguage && !backEnd.targetVersion && !backEnd.forceReemit && !backEnd.requireAnalysis &&
         passes.shiftThisStage && passes.eye.select == EyeSelect::Parameter;
}

bool isVulkanGlslText(const std::string& text) { return readText(text).vulkan; }

bool textWritesPosition(const std::string& text) { return readText(text).writesPosition; }

bool textDefinesEveryPrototype(const std::string& text) {
  source::LexedText lexed(text);
  std::vector<size_t> code;
  for (size_t k = 0; k < lexed.size(); ++k)
    if (lexed[k].isCode()) code.push_back(k);
  std::set<std::string> declared, defined;
  int depth = 0;
  for (size_t i = 0; i < code.size(); ++i) {
    if (lexed.isPunct(code[i], '{')) ++depth;
    if (lexed.isPunct(code[i], '}')) --depth;
    if (depth != 0 || !lexed.isIdentifier(code[i]) || i + 1 >= code.size() || !lexed.isPunct(code[i + 1], '(')) continue;
    size_t j = i + 1;  // past the matching ')'
    for (int parens = 0; j < code.size(); ++j) {
      if (lexed.isPunct(code[j], '(')) ++parens;
      if (lexed.isPunct(code[j], ')') && --parens == 0) break;
    }
    if (j + 1 >= code.size()) break;
    const std::string name(lexed.text(code[i]));
    if (lexed.isPunct(code[j + 1], ';')) declared.insert(name);
    if (lexed.isPunct(code[j + 1], '{')) defined.insert(name);
  }
  return std::includes(defined.begin(), defined.end(), declared.begin(), declared.end());
}

bool textNamesPosition(const std::string& text) {
  source::LexedText lexed(text);
  for (size_t k = 0; k < lexed.size(); ++k)
    if (lexed.isIdentifier(k) && lexed.text(k) == "gl_Position") return true;
  return false;
}

bool textCallsEmit(const std::string& text) {
  source::LexedText lexed(text);
  for (size_t k = 0; k < lexed.size(); ++k)
    if (lexed[k].isCode() && lexed.isIdentifier(k) &&
        (lexed.text(k) == "EmitVertex" || lexed.text(k) == "EmitStreamVertex") &&
        lexed.isPunct(lexed.nextNonComment(k), '('))
      return true;
  return false;
}

bool textKeepsUnitW(const std::string& text) {
  TextFacts facts = readText(text);
  return facts.problem.empty() && !facts.wMayBeOtherThanOne;
}

Result<TextOnlyShift> shiftFromText(const SourceFile& input, Stage stage, const PassOptions& options,
                                    const StageUnits& units) {
  TextOnlyShift result;
  VersionLine v = findVersion(input.contents);
  if (!v.problem.empty()) {
    return errorAt(0, 0, v.problem);
  }
  TextFacts facts = readText(input.contents);
  if (!facts.problem.empty()) {
    return errorAt(0, 0, "the text has " + facts.problem);
  }
  if (!facts.writesPosition && !units.otherWritesPosition) {
    if (units.noUnitNamesPosition) {  // every unit of the stage known, none with a position
      result.output = input.contents;
      result.copiedAs = Classification::NoPositionOutput;
      return result;
    }
    return errorAt(0, 0, "the text writes no gl_Position of its own");
  }
  for (const std::string* name : {&options.eye.eyeSignName, &options.eye.separationName, &options.eye.convergenceName})
    if (has(facts, *name)) {
      return errorAt(0, 0, "the shader already uses the name '" + *name + "' (is it converted already?)");
    }
  if (stage == Stage::Geometry && !units.stageEmits) {
    // No vertex ever reaches the rasterizer: nothing to shift (as the analysis copies such a stage).
    result.output = input.contents;
    result.copiedAs = Classification::NoVertexEmitted;
    return result;
  }
  if (!facts.wMayBeOtherThanOne && units.othersKeepUnitW) {
    // 2D by its text: the runtime cutoff would keep every draw mono, so nothing is spliced (as the
    // analysis copies a stage whose every position has the constant w = 1); the eye parameters are
    // not declared, where a compiler would fold them away unused.
    result.output = input.contents;
    result.copiedAs = Classification::ConstantW1;
    return result;
  }
  bool legacy = !facts.vulkan && (v.es ? v.version < 300 : v.version < 330);
  GlslSpliceOptions spec;
  static_cast<ShiftSpec&>(spec) = makeShiftSpec(options, facts.vulkan || glslHasPreciseAndFma(v.version, v.es));
  spec.eyeSignName = options.eye.eyeSignName;
  spec.separationName = options.eye.separationName;
  spec.convergenceName = options.eye.convergenceName;
  spec.version = v.version;
  spec.es = v.es;
  spec.stage = stage;
  if (spec.compensated || (spec.fused && !glslHasPreciseAndFma(v.version, v.es))) {
    return errorAt(0, 0, "--compensated-shift, and --fused-shift below GLSL 400 / ESSL 320, need the analysis");
  }
  std::string whyNot;
  if (!declareEyeParams(facts, v, legacy, options, spec, result.eyeParams, whyNot)) return errorAt(0, 0, whyNot);
  GlslSpliceResult spliced = spliceGlslStereo(input.contents, spec);
  if (!spliced.ok) {
    return errorAt(0, 0, spliced.error);
  }
  result.output = std::move(spliced.text);
  result.sites = spliced.sites;
  result.notDone = textOnlyNotDone();
  return result;
}

}  // namespace stereoshift
