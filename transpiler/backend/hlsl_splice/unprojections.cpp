// The HLSL splice's unprojection wraps (hlsl_splice.h, spliceHlslUnprojections): this turns an HLSL
// shader whose position rebuild `mul(InvM, float4(ndc, depth, 1))` the deferred pass fixed into the
// same text with the product wrapped in a per-eye helper, the helper and the eye parameters'
// cbuffer in a marked block on the lines before the first function that calls it. Read with the
// lexer: the wraps are only where the text is plain (every `mul(<matrix>, ...)` in a function body,
// as many as the analysis fixed, none in a macro).
#include "transpiler/backend/hlsl_splice.h"

#include "transpiler/backend/hlsl_splice/edit_buffer.h"

#include "transpiler/source/lexer.h"

#include <algorithm>
#include <map>
#include <string_view>

namespace stereoshift {

namespace {

// The token that closes the bracket opened at `open`, or lexed.size().
size_t closingParen(const source::LexedText& lexed, size_t open) {
  int depth = 0;
  for (size_t k = open; k < lexed.size(); ++k) {
    if (!lexed[k].isCode()) continue;
    if (lexed.isPunct(k, '(')) ++depth;
    if (lexed.isPunct(k, ')') && --depth == 0) return k;
  }
  return lexed.size();
}

// Whether the tokens from `k` spell `access` (`Frame.InvViewProj`), and where they end.
size_t accessEnd(const source::LexedText& lexed, size_t k, const std::string& access) {
  size_t from = 0;
  for (;;) {
    size_t dot = access.find('.', from);
    std::string part = access.substr(from, dot - from);
    if (!lexed.isIdentifier(k) || lexed.text(k) != part) return lexed.size();
    if (dot == std::string::npos) return k;
    k = lexed.nextNonComment(k);
    if (!lexed.isPunct(k, '.')) return lexed.size();
    k = lexed.nextNonComment(k);
    from = dot + 1;
  }
}

std::string helperText(const HlslUnprojectionOptions& o, const std::string& nl) {
  std::string t = "// ---- stereoshift: stereo parameters and per-eye helpers (injected) ----" + nl;
  t += "cbuffer " + o.cbufferName + " : register(b" + std::to_string(o.cbufferRegister) + ")" + nl + "{" + nl;
  for (const std::string* name : {&o.eyeSignName, &o.separationName, &o.convergenceName})
    t += "    float " + *name + ";" + nl;
  t += "};" + nl;
  for (const auto& w : o.wraps) {
    // mul(M, v) multiplies by M: the NDC x column is M's column 0, element i at M[i][0].
    const std::string& m = w.matrix;
    std::string column = "float4(" + m + "[0][0], " + m + "[1][0], " + m + "[2][0], " + m + "[3][0])";
    std::string d = "(" + o.eyeSignName + " * " + o.separationName + ") * (1.0f - " + o.convergenceName +
                    " * stereoshift_q.w)";
    t += "float4 " + w.function + "(float4 stereoshift_q)" + nl + "{" + nl + "    return " + o.eyeSignName +
         " != 0.0f ? stereoshift_q - " + column + " * (" + d + ") : stereoshift_q;" + nl + "}" + nl;
  }
  t += "// ---- end stereoshift ----" + nl;
  return t;
}

}  // namespace

HlslSpliceResult spliceHlslUnprojections(const std::string& source, const HlslUnprojectionOptions& o) {
  HlslSpliceResult result;
  const std::string nl = source.find("\r\n") != std::string::npos ? "\r\n" : "\n";
  source::LexedText lexed(source);
  std::map<size_t, std::string> inserts;
  size_t firstItem = source.size();
  // Function bodies: a `{` at file scope of an item that has a parameter list and is no struct,
  // cbuffer or technique (`float4 main(...) : SV_Target {`).
  std::vector<bool> inBody(lexed.size(), false);
  std::vector<size_t> itemStart(lexed.size(), 0);
  {
    int depth = 0;
    bool body = false, parameters = false;
    size_t item = 0;
    for (size_t k = 0; k < lexed.size(); ++k) {
      inBody[k] = body;
      itemStart[k] = item;
      if (!lexed[k].isCode()) continue;
      if (depth == 0 && lexed.isPunct(k, '(')) parameters = true;
      if (lexed.isPunct(k, '{')) {
        size_t head = item;
        while (head < k && !lexed[head].isCode()) ++head;
        std::string_view first = lexed.isIdentifier(head) ? lexed.text(head) : std::string_view();
        bool declaration = first == "struct" || first == "cbuffer" || first == "tbuffer" || first == "class" ||
                           first == "interface" || first == "namespace" || first.starts_with("technique") || first == "pass";
        if (depth == 0 && parameters && !declaration) body = true;
        ++depth;
      } else if (lexed.isPunct(k, '}') && depth > 0 && --depth == 0) {
        body = parameters = false;
        item = k + 1;
      } else if (lexed.isPunct(k, ';') && depth == 0) {
        item = k + 1;
        parameters = false;
      }
    }
  }
  for (const auto& w : o.wraps) {
    int found = 0;
    for (size_t k = 0; k < lexed.size(); ++k) {
      if (!lexed.isIdentifier(k) || lexed.text(k) != "mul") continue;
      size_t open = lexed.nextNonComment(k);
      if (!lexed.isPunct(open, '(')) continue;
      size_t first = lexed.nextNonComment(open);
      size_t last = accessEnd(lexed, first, w.matrix);
      if (last >= lexed.size() || !lexed.isPunct(lexed.nextNonComment(last), ',')) continue;
      if (!lexed[k].isCode() || !inBody[k]) {
        result.error = "the product through '" + w.matrix + "' is written in a macro or outside a function";
        return result;
      }
      size_t close = closingParen(lexed, open);
      if (close >= lexed.size()) {
        result.error = "the product through '" + w.matrix + "' is not closed";
        return result;
      }
      inserts[lexed[k].begin] += w.function + "(";
      inserts[lexed[close].end] = ")" + inserts[lexed[close].end];
      size_t item = itemStart[k] < lexed.size() ? lexed[itemStart[k]].begin : 0;
      firstItem = std::min(firstItem, item);
      ++found;
    }
    if (found != w.products) {
      result.error = "the text has " + std::to_string(found) + " product(s) `mul(" + w.matrix + ", ...)`, the analysis fixed " +
                     std::to_string(w.products);
      return result;
    }
  }
  // The block on lines of its own, before the line of the first function that calls a helper.
  size_t lineStart = source.rfind('\n', firstItem == 0 ? 0 : firstItem - 1);
  lineStart = lineStart == std::string::npos || firstItem == 0 ? 0 : lineStart + 1;
  if (source.find_first_not_of(" \t", lineStart) < firstItem) {
    result.error = "the function that rebuilds the position does not start its line";
    return result;
  }
  inserts[lineStart] = helperText(o, nl) + inserts[lineStart];
  hlsl_splice::EditBuffer edits(source);
  for (const auto& [at, insert] : inserts) edits.add(at, 0, insert);
  result.ok = true;
  result.text = edits.apply();
  result.sites = static_cast<int>(o.wraps.size());
  return result;
}

}  // namespace stereoshift
