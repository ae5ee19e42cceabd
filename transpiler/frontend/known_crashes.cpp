// See known_crashes.h.
#include "transpiler/frontend/known_crashes.h"

#include "transpiler/source/lexer.h"

#include <set>
#include <vector>

namespace stereoshift {

// glslang's HLSL front end, version 11 to 14: a global variable named like a struct declared before
// it (`struct P { ... }; float4 P;`) reaches a null type in its symbol table. Found by reading the
// tokens at file scope: `struct NAME` declares a type name; a later `TYPE NAME` followed by `;`,
// `=`, `:`, `[` or `,` at brace depth 0 declares a variable of that name.
std::optional<KnownCrashTrigger> knownGlslangCrashTrigger(const std::string& text, SourceLanguage language) {
  if (language != SourceLanguage::Hlsl) return std::nullopt;
  source::LexedText lexed(text);
  std::vector<size_t> code;  // tokens that are neither comments nor on a directive's line
  for (size_t k = 0; k < lexed.size(); ++k)
    if (lexed[k].isCode()) code.push_back(k);
  std::set<std::string_view> structNames;
  int depth = 0;
  for (size_t i = 0; i < code.size(); ++i) {
    size_t k = code[i];
    if (lexed.isPunct(k, '{')) ++depth;
    if (lexed.isPunct(k, '}') && depth > 0) --depth;
    if (!lexed.isIdentifier(k)) continue;
    if (lexed.text(k) == "struct" && i + 1 < code.size() && lexed.isIdentifier(code[i + 1])) {
      structNames.insert(lexed.text(code[i + 1]));
      ++i;
      continue;
    }
    if (depth != 0 || i == 0 || i + 1 >= code.size() || !lexed.isIdentifier(code[i - 1])) continue;
    if (lexed.text(code[i - 1]) == "struct" || !structNames.count(lexed.text(k))) continue;
    size_t after = code[i + 1];
    if (lexed.isPunct(after, ';') || lexed.isPunct(after, '=') || lexed.isPunct(after, ':') ||
        lexed.isPunct(after, '[') || lexed.isPunct(after, ','))
      return KnownCrashTrigger{static_cast<int>(lexed[k].line), static_cast<int>(lexed[k].column),
                               "a global variable named like the struct '" + std::string(lexed.text(k)) +
                                   "' (glslang's HLSL front end crashes on it; rename one of them)"};
  }
  return std::nullopt;
}

}  // namespace stereoshift
