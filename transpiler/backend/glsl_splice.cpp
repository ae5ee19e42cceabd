// This turns the passes' decisions for a legacy GLSL vertex shader into stereo GLSL of the same
// dialect by a source splice: see glsl_splice.h.
#include "transpiler/backend/glsl_splice.h"

#include "transpiler/source/lexer.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <string_view>

namespace stereoshift {

namespace {

constexpr const char* kMonoMain = "main_stereoshift_mono";

struct Word {
  size_t begin, end;
  std::string text;     // as spelled (line splices removed)
  std::string splices;  // the line splices inside it, kept by a rename
};

// The identifiers and punctuation of `text` outside comments and outside directives other than
// #define (whose body is code: the macro's name and body are words, `define` is not), in order;
// numbers and string literals are skipped.
std::vector<Word> words(const std::string& text) {
  std::vector<Word> out;
  source::LexedText lexed(text);
  size_t defineName = std::string::npos;  // the `define` of the directive being read
  for (size_t k = 0; k < lexed.size(); ++k) {
    const source::Token& t = lexed[k];
    if (t.kind == source::TokenKind::Directive) {
      defineName = t.directive == source::DirectiveKind::Define ? lexed.nextNonComment(k) : std::string::npos;
      continue;
    }
    if (t.inDirective() && (t.directive != source::DirectiveKind::Define || k == defineName)) continue;
    if (t.kind == source::TokenKind::Identifier || t.kind == source::TokenKind::Punctuation)
      out.push_back({t.begin, t.end, source::spelledString(text, t), source::splicesOf(text, t)});
  }
  return out;
}

std::string floatLiteral(float value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(value));
  std::string lit = buf;
  if (lit.find_first_of(".eEn") == std::string::npos) lit += ".0";
  return lit;
}

// When `p` (the position) is shifted: the condition of emitCutoffCondition, in its order.
std::string conditionText(const GlslSpliceOptions& spec, const std::string& p) {
  std::string stereo = spec.eyeSignName + " != 0.0";
  // isinf exists from GLSL 130 / ESSL 300; below, `abs(w) <= FLT_MAX` is false for inf and NaN alike
  // (a NaN w fails the other term anyway), so the condition is the same.
  bool hasIsinf = spec.es ? spec.version >= 300 : spec.version >= 130;
  std::string finite = hasIsinf ? "!isinf(" + p + ".w)" : "abs(" + p + ".w) <= 3.40282347e+38";
  switch (spec.cutoff) {
    case CutoffMode::Epsilon:
      return stereo + " && abs(" + p + ".w - 1.0) > " + floatLiteral(spec.epsilon) + " && " + finite;
    case CutoffMode::Exact:
      return stereo + " && " + p + ".w != 1.0 && " + finite;
    case CutoffMode::None:
      break;
  }
  return stereo;
}

std::string shiftedX(const GlslSpliceOptions& spec, const std::string& p) {
  return p + ".x + (" + spec.eyeSignName + " * " + spec.separationName + ") * (" + p + ".w - " +
         spec.convergenceName + ")";
}

}  // namespace

std::vector<std::string> exactPositionCopies(const std::string& source) {
  std::vector<Word> w = words(source);
  std::map<std::string, bool> exact;  // name -> every assignment seen is `name = gl_Position;`
  for (size_t k = 0; k + 1 < w.size(); ++k) {
    if (!isIdentifierStart(w[k].text[0]) || w[k].text == "gl_Position") continue;
    bool assigned = w[k + 1].text == "=" && !(k + 2 < w.size() && w[k + 2].text == "=") &&
                    !(k > 0 && (w[k - 1].text == "." || w[k - 1].text == "]"));
    if (!assigned) continue;
    bool copy = k + 3 < w.size() && w[k + 2].text == "gl_Position" && w[k + 3].text == ";";
    auto [it, fresh] = exact.emplace(w[k].text, copy);
    if (!fresh) it->second = it->second && copy;
  }
  std::vector<std::string> out;
  for (const auto& [name, isCopy] : exact)
    if (isCopy) out.push_back(name);
  return out;
}

GlslSpliceResult spliceGlslStereo(const std::string& source, const GlslSpliceOptions& options) {
  GlslSpliceResult result;
  std::string nl = source.find("\r\n") != std::string::npos ? "\r\n" : "\n";
  std::vector<Word> w = words(source);
  std::string text;
  size_t pos = 0;
  int mains = 0;
  for (const auto& word : w) {
    if (word.text != "main") continue;
    text.append(source, pos, word.begin - pos);
    text += kMonoMain + word.splices;  // a `main` written across a line splice keeps its lines
    pos = word.end;
    ++mains;
  }
  text.append(source, pos, std::string::npos);
  if (mains == 0) {
    result.error = "the shader defines no `main`";
    return result;
  }
  for (const auto& word : w)
    if (word.text == kMonoMain) {
      result.error = std::string("the shader already uses the name `") + kMonoMain + "`";
      return result;
    }

  const std::string p = "gl_Position", ind = "    ";
  std::string t;
  if (!text.empty() && text.back() != '\n') t += nl;
  t += "// ---- stereoshift: stereo parameters and clip-space shift (injected) ----" + nl;
  for (const std::string* name : {&options.eyeSignName, &options.separationName, &options.convergenceName})
    t += "uniform float " + *name + ";" + nl;
  t += "void main()" + nl + "{" + nl + ind + kMonoMain + "();" + nl;
  if (options.form == ShiftForm::Select) {
    t += ind + p + ".x = (" + conditionText(options, p) + ") ? " + shiftedX(options, p) + " : " + p + ".x;" + nl;
  } else {
    t += ind + "if (" + conditionText(options, p) + ")" + nl + ind + "{" + nl;
    t += ind + ind + p + ".x = " + shiftedX(options, p) + ";" + nl + ind + "}" + nl;
  }
  for (const auto& copy : options.haloCopies) t += ind + copy + " = " + p + ";" + nl;
  t += "}" + nl + "// ---- end stereoshift ----" + nl;
  result.text = text + t;
  result.ok = true;
  return result;
}

}  // namespace stereoshift
