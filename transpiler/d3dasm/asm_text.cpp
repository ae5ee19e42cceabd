#include "transpiler/d3dasm/asm_text.h"

#include "transpiler/source/identifiers.h"

#include <cctype>

namespace stereoshift::d3dasm {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t'; }

// Where the code of `line` ends: at a `//` comment outside brackets, else its end.
size_t codeEnd(std::string_view line) {
  int depth = 0;
  for (size_t k = 0; k + 1 < line.size(); ++k) {
    char c = line[k];
    if (c == '(' || c == '[' || c == '{') ++depth;
    else if (c == ')' || c == ']' || c == '}') --depth;
    else if (c == '/' && line[k + 1] == '/' && depth <= 0) return k;
  }
  return line.size();
}

// The opcode starts at `begin`; it runs to the first blank outside parentheses, so that
// `ld_structured_indexable(structured_buffer, stride=16)(mixed,mixed,mixed,mixed)` is one word.
size_t opcodeEnd(std::string_view line, size_t begin, size_t end) {
  int depth = 0;
  size_t k = begin;
  for (; k < end; ++k) {
    char c = line[k];
    if (c == '(') ++depth;
    else if (c == ')') --depth;
    else if (isBlank(c) && depth <= 0) break;
  }
  return k;
}

int braceBalance(std::string_view code) {
  int balance = 0;
  for (char c : code) balance += c == '{' ? 1 : c == '}' ? -1 : 0;
  return balance;
}

// Operands of an instruction: split at commas outside (), [] and {}; false when a bracket does
// not close on the line. A declaration's operands are also split at blanks outside brackets, since
// its words are (`dcl_resource_texture2d (float,float,float,float) t0`, `dcl_input_ps linear v1.xy`);
// an instruction's are not (`cb0[r0.x + 4].xyzw` holds blanks only inside brackets, but keep it safe).
bool splitOperands(std::string_view line, size_t begin, size_t end, bool atBlanksToo, std::vector<Operand>* out,
                   size_t* badColumn) {
  int depth = 0;
  size_t start = begin;
  auto add = [&](size_t from, size_t to) {
    while (from < to && isBlank(line[from])) ++from;
    while (to > from && isBlank(line[to - 1])) --to;
    if (to > from) out->push_back({std::string(line.substr(from, to - from)), from + 1});
  };
  for (size_t k = begin; k < end; ++k) {
    char c = line[k];
    if (c == '(' || c == '[' || c == '{') ++depth;
    else if (c == ')' || c == ']' || c == '}') {
      if (--depth < 0) {
        *badColumn = k + 1;
        return false;
      }
    } else if ((c == ',' || (atBlanksToo && isBlank(c))) && depth == 0) {
      add(start, k);
      start = k + 1;
    }
  }
  if (depth != 0) {
    *badColumn = end;
    return false;
  }
  add(start, end);
  return true;
}

}  // namespace

std::string AsmLine::baseOpcode() const {
  std::string base = opcode.substr(0, opcode.find('('));
  if (base.ends_with("_sat")) base.resize(base.size() - 4);
  return base;
}

bool AsmLine::saturates() const {
  std::string base = opcode.substr(0, opcode.find('('));
  return base.ends_with("_sat");
}

std::optional<ShaderModel> readShaderModel(std::string_view word) {
  // [vpghdc]s_<major>_<minor>, optionally _level_9_N (feature-level 9 targets).
  if (word.size() < 6 || word[1] != 's' || word[2] != '_' || !std::isdigit(static_cast<unsigned char>(word[3])) ||
      word[4] != '_' || !std::isdigit(static_cast<unsigned char>(word[5])))
    return std::nullopt;
  if (std::string_view("vpghdc").find(word[0]) == std::string_view::npos) return std::nullopt;
  std::string_view rest = word.substr(6);
  if (!rest.empty() && !rest.starts_with("_level_")) return std::nullopt;
  ShaderModel m;
  m.kind = word[0];
  m.major = word[3] - '0';
  m.minor = word[5] - '0';
  m.text = std::string(word);
  return m;
}

std::optional<Stage> stageOfShaderModel(const ShaderModel& model) {
  switch (model.kind) {
    case 'v': return Stage::Vertex;
    case 'p': return Stage::Fragment;
    case 'g': return Stage::Geometry;
    case 'h': return Stage::TessControl;
    case 'd': return Stage::TessEvaluation;
    case 'c': return Stage::Compute;
    default: return std::nullopt;
  }
}

bool isD3DAssembly(const std::string& text) {
  size_t at = 0;
  while (at < text.size()) {
    size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    std::string_view line = std::string_view(text).substr(at, end - at);
    size_t first = 0;
    while (first < line.size() && (isBlank(line[first]) || line[first] == '\r')) ++first;
    line = line.substr(first);
    if (!line.empty() && !line.starts_with("//")) {
      size_t wordEnd = 0;
      while (wordEnd < line.size() && isIdentifierChar(line[wordEnd])) ++wordEnd;
      std::string_view after = line.substr(wordEnd);
      while (!after.empty() && (isBlank(after.front()) || after.front() == '\r')) after.remove_prefix(1);
      return readShaderModel(line.substr(0, wordEnd)).has_value() && (after.empty() || after.starts_with("//"));
    }
    at = end + 1;
  }
  return false;
}

Result<AsmText> parseAssembly(const std::string& text) {
  AsmText parsed;
  parsed.newline = text.find("\r\n") != std::string::npos ? "\r\n" : "\n";
  parsed.endsWithNewline = !text.empty() && text.back() == '\n';
  bool haveModel = false;
  int openBraces = 0;      // a declaration with a brace block still open
  size_t openDeclaration = 0;
  size_t at = 0;
  while (at < text.size()) {
    size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    AsmLine line;
    line.number = parsed.lines.size() + 1;
    line.text = text.substr(at, end - at);
    if (!line.text.empty() && line.text.back() == '\r') line.text.pop_back();
    at = end + 1;
    std::string_view view = line.text;
    size_t first = 0;
    while (first < view.size() && isBlank(view[first])) ++first;
    line.indent = line.text.substr(0, first);
    size_t code = codeEnd(view);
    if (openBraces > 0) {
      line.kind = LineKind::Continuation;
      openBraces += braceBalance(view.substr(0, code));
      parsed.lines[openDeclaration].lastLine = parsed.lines.size();
      parsed.lines.push_back(std::move(line));
      continue;
    }
    if (first >= code) {
      line.kind = first == view.size() ? LineKind::Blank : LineKind::Comment;
      parsed.lines.push_back(std::move(line));
      continue;
    }
    size_t opEnd = opcodeEnd(view, first, code);
    line.opcode = line.text.substr(first, opEnd - first);
    if (!haveModel) {
      auto model = readShaderModel(line.opcode);
      if (!model) {
        return errorAt(line.number, first + 1, "'" + line.opcode + "' before the shader model line (vs_5_0, ps_4_0, ...)");
      }
      line.kind = LineKind::ShaderModel;
      parsed.model = *model;
      parsed.modelLine = parsed.lines.size();
      haveModel = true;
      parsed.lines.push_back(std::move(line));
      continue;
    }
    line.kind = line.opcode.starts_with("dcl_") ? LineKind::Declaration : LineKind::Instruction;
    line.lastLine = parsed.lines.size();
    if (line.kind == LineKind::Declaration && braceBalance(view.substr(opEnd, code - opEnd)) > 0) {
      // dcl_immediateConstantBuffer { { ... }, ... }: the operand is the whole brace block.
      openBraces = braceBalance(view.substr(opEnd, code - opEnd));
      openDeclaration = parsed.lines.size();
      line.operands.push_back({line.text.substr(opEnd), opEnd + 1});
      parsed.lines.push_back(std::move(line));
      continue;
    }
    size_t badColumn = 0;
    if (!splitOperands(view, opEnd, code, line.kind == LineKind::Declaration, &line.operands, &badColumn)) {
      return errorAt(line.number, badColumn, "unbalanced brackets in the operands of '" + line.opcode + "'");
    }
    parsed.lines.push_back(std::move(line));
  }
  if (!haveModel) {
    return errorAt(0, 0, "no shader model line (vs_5_0, ps_4_0, ...): not D3D shader assembly");
  }
  if (openBraces > 0) {
    return errorAt(parsed.lines[openDeclaration].number, 1, "'" + parsed.lines[openDeclaration].opcode + "' opens a brace that is never closed");
  }
  return parsed;
}

std::string joinLines(const AsmText& text) {
  std::string joined;
  for (size_t k = 0; k < text.lines.size(); ++k) {
    joined += text.lines[k].text;
    if (k + 1 < text.lines.size() || text.endsWithNewline) joined += text.newline;
  }
  return joined;
}

std::vector<size_t> registerTokenOffsets(const AsmLine& line, std::string_view name) {
  std::vector<size_t> offsets;
  std::string_view view = line.text;
  size_t begin = line.indent.size() + line.opcode.size(), end = codeEnd(view);
  for (size_t k = begin; k < end;) {
    if (!isIdentifierChar(view[k])) {
      ++k;
      continue;
    }
    size_t start = k;
    while (k < end && isIdentifierChar(view[k])) ++k;
    bool swizzle = start > 0 && view[start - 1] == '.';
    if (!swizzle && view.substr(start, k - start) == name) offsets.push_back(start);
  }
  return offsets;
}

}  // namespace stereoshift::d3dasm
