// The text-only shift for HLSL (see text_only_shift.h): this turns a decompiled HLSL vertex,
// geometry or domain shader that glslang cannot analyse (it refused the text, or crashed on it) into
// its stereo version with the HLSL splice alone: the entry point told from its signature, the
// SV_Position output found in the text, the eye parameters a cbuffer at the first free register or
// 3Dmigoto's StereoParams texture.
#include "transpiler/text_only_shift.h"

#include "core/diagnostics.h"
#include "passes/eye_param_emitter.h"
#include "passes/shift_emitter.h"
#include "transpiler/backend/hlsl_splice.h"
#include "transpiler/frontend/hlsl_effects.h"
#include "transpiler/source/lexer.h"
#include "transpiler/source/stage_rules.h"

#include <cctype>
#include <set>
#include <string_view>

namespace stereoshift {

namespace {

// The first b register the text does not name (`register(b3)`, `register(b3, space0)`), for the
// injected cbuffer.
uint32_t firstFreeCbufferRegister(const std::string& text) {
  source::LexedText lexed(text);
  std::set<uint32_t> used;
  for (size_t k = 0; k + 2 < lexed.size(); ++k) {
    if (!lexed.isIdentifier(k) || lexed.text(k) != "register") continue;
    size_t open = lexed.nextNonComment(k), reg = lexed.nextNonComment(open);
    if (!lexed.isPunct(open, '(') || !lexed.isIdentifier(reg)) continue;
    std::string_view r = lexed.text(reg);
    if (r.size() < 2 || (r[0] != 'b' && r[0] != 'B')) continue;
    uint32_t n = 0;
    bool digits = true;
    for (char c : r.substr(1)) {
      if (!std::isdigit(static_cast<unsigned char>(c)) || n > 100000) digits = false;
      n = n * 10 + static_cast<uint32_t>(c - '0');
    }
    if (digits) used.insert(n);
  }
  uint32_t free = 0;
  while (used.count(free)) ++free;
  return free;
}

// `name`, renamed as the eye-params pass renames its block where the text already uses it (a dump's
// 3Dmigoto declarations name a `StereoParams` texture).
std::string unusedName(const std::string& text, const std::string& name) {
  source::LexedText lexed(text);
  std::set<std::string_view> used;
  for (size_t k = 0; k < lexed.size(); ++k)
    if (lexed.isIdentifier(k)) used.insert(lexed.text(k));
  return numberedName(name, [&](const std::string& n) { return used.count(n) > 0; });
}

}  // namespace

bool isDecompiledHlsl(const SourceFile& input) {
  return stageOfDecompiledDump(input.path).has_value() || input.contents.find("3Dmigoto declarations") != std::string::npos ||
         input.contents.find("Created with 3Dmigoto") != std::string::npos;
}

std::optional<Diagnostic> ownTextError(const SourceFile& input) {
  source::LexedText lexed(input.contents);
  auto at = [&](size_t k, std::string message) {
    return Diagnostic{Severity::Error, input.path, static_cast<int>(lexed[k].line), static_cast<int>(lexed[k].column),
                      std::move(message)};
  };
  std::vector<size_t> open;  // the brackets not closed yet, innermost last
  for (size_t k = 0; k < lexed.size(); ++k) {
    const source::Token& t = lexed[k];
    if (t.unterminated)
      return at(k, t.kind == source::TokenKind::Comment ? "a comment is left open to the end of the file"
                                                        : "a string is left open at the end of its line");
    if (t.kind == source::TokenKind::Directive && t.directive == source::DirectiveKind::Error && t.ifDepth == 0)
      return at(k, "the text's own " + std::string(lexed.text(k)));
    if (!t.isCode() || t.kind != source::TokenKind::Punctuation) continue;
    const char c = lexed.text(k)[0];
    if (c == '(' || c == '[' || c == '{') open.push_back(k);
    if (c != ')' && c != ']' && c != '}') continue;
    const char expected = c == ')' ? '(' : c == ']' ? '[' : '{';
    if (open.empty()) return at(k, std::string("'") + c + "' closes nothing");
    if (lexed.text(open.back())[0] != expected)
      return at(open.back(), std::string("'") + lexed.text(open.back())[0] + "' is not closed before the '" + c +
                                 "' at line " + std::to_string(t.line));
    open.pop_back();
  }
  if (!open.empty()) return at(open.back(), std::string("'") + lexed.text(open.back())[0] + "' is never closed");
  return std::nullopt;
}

Result<TextOnlyShift> shiftHlslFromText(const SourceFile& input, Stage stage, const TranspileOptions& options) {
  TextOnlyShift result;
  HlslSpliceOptions splice;
  static_cast<ShiftSpec&>(splice) = makeShiftSpec(options, true);
  splice.eyeSignName = options.eye.eyeSignName;
  splice.separationName = options.eye.separationName;
  splice.convergenceName = options.eye.convergenceName;
  std::string entry = options.entryPoint.empty()
                          ? chooseHlslEntry(input.contents, mentionedFunctions(input.contents), stage, "")
                          : options.entryPoint;
  splice.entryPoint = entry;
  splice.vertex = stage == Stage::Vertex;
  splice.geometry = stage == Stage::Geometry;
  if (splice.vertex) splice.vertexEntries = {{entry, {}}};
  if (options.eyeFrom3DMigoto) {
    useStereoParamsTexture(splice);
    result.eyeParams = "3Dmigoto StereoParams texture (t125)";
  } else if (options.eye.source == EyeSource::Auto || options.eye.source == EyeSource::UniformBlock) {
    splice.cbufferName = unusedName(input.contents, options.eye.blockName);
    splice.cbufferRegister = options.eye.hlslRegister.value_or(firstFreeCbufferRegister(input.contents));
    result.eyeParams = "cbuffer " + splice.cbufferName + " (b" + std::to_string(splice.cbufferRegister) + ")";
  } else {
    return errorAt(0, 0, "the HLSL text-only shift declares its eye parameters as a cbuffer or 3Dmigoto's StereoParams "
                    "texture (--eye-source uniform-block or 3dmigoto)");
  }
  HlslSpliceResult spliced = spliceHlslStereo(input.contents, splice);
  if (!spliced.ok) {
    return errorAt(spliced.line, 0, spliced.error + (spliced.line ? " (line " + std::to_string(spliced.line) + ")" : ""));
  }
  result.output = std::move(spliced.text);
  result.sites = spliced.sites;
  result.notDone = textOnlyNotDone();
  return result;
}

}  // namespace stereoshift
