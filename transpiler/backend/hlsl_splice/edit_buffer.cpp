// The HLSL splice's edit buffer: see edit_buffer.h.
#include "transpiler/backend/hlsl_splice/edit_buffer.h"

#include <algorithm>

namespace stereoshift::hlsl_splice {

namespace {

std::string dominantNewline(const std::string& src) {
  size_t crlf = 0, lf = 0;
  for (size_t i = 0; i < src.size(); ++i) {
    if (src[i] == '\n') (i > 0 && src[i - 1] == '\r') ? ++crlf : ++lf;
  }
  return crlf > lf ? "\r\n" : "\n";
}

size_t lineStart(const std::string& src, size_t offset) {
  size_t ls = src.rfind('\n', offset == 0 ? 0 : offset - 1);
  return (offset == 0 || ls == npos) ? 0 : ls + 1;
}
bool inBlockComment(const TokenView& view, size_t offset) {
  for (const auto& c : view.blockComments) {
    if (c.begin < offset && offset < c.end) return true;
  }
  return false;
}
bool inDirective(const TokenView& view, size_t offset) {
  for (const auto& d : view.directives) {
    if (d.begin < offset && offset <= d.end) return true;
  }
  return false;
}


}  // namespace

EditBuffer::EditBuffer(const std::string& source) : source_(source), newline_(dominantNewline(source)) {}

void EditBuffer::add(size_t offset, size_t remove, std::string insert) {
  edits_.push_back({offset, remove, std::move(insert), edits_.size()});
}

std::string EditBuffer::apply() const {
  std::vector<Edit> edits = edits_;
  std::stable_sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) {
    return a.offset != b.offset ? a.offset < b.offset : a.order < b.order;
  });
  std::string out;
  out.reserve(source_.size() + 2048);
  size_t pos = 0;
  for (const auto& e : edits) {
    out.append(source_, pos, e.offset - pos);
    out += e.insert;
    pos = e.offset + e.remove;
  }
  out.append(source_, pos, npos);
  return out;
}

std::pair<size_t, bool> insertionBefore(const TokenView& view, size_t offset, size_t notBefore) {
  const std::string& src = view.s;
  // Leave a preprocessor conditional that encloses the declaration when possible, so that the
  // inserted declarations exist whichever branch is compiled.
  std::vector<size_t> conds;
  for (const auto& d : view.directives) {
    if (d.begin >= offset) break;
    if (d.name == "if" || d.name == "ifdef" || d.name == "ifndef") conds.push_back(d.begin);
    else if (d.name == "endif" && !conds.empty()) conds.pop_back();
  }
  for (size_t c : conds) {
    if (lineStart(src, c) >= notBefore) return {lineStart(src, c), true};
  }

  size_t ls = lineStart(src, offset);
  bool blank = true;
  for (size_t i = ls; i < offset; ++i) {
    if (src[i] != ' ' && src[i] != '\t') blank = false;
  }
  if (!blank || ls < notBefore || inBlockComment(view, ls) || inDirective(view, ls)) return {offset, false};
  // Keep a `//` comment block directly above the declaration attached to it.
  while (ls > 0) {
    size_t prev = lineStart(src, ls - 1);
    if (prev < notBefore || inBlockComment(view, prev) || inDirective(view, prev)) break;
    size_t t = prev;
    while (t < ls && (src[t] == ' ' || src[t] == '\t')) ++t;
    if (src.compare(t, 2, "//") != 0) break;
    ls = prev;
  }
  return {ls, true};
}

// Insert `block` (lines ending in newlines) before the declaration at `offset`.
void insertBlockBefore(EditBuffer& edits, const TokenView& view, size_t offset, size_t notBefore,
                       const std::string& block) {
  auto [at, lineStartOk] = insertionBefore(view, offset, notBefore);
  const std::string& nl = edits.newline();
  edits.add(at, 0, lineStartOk ? block + nl : nl + block + nl);
}

// Insert `block` after the token `tok` (a closing brace), starting on a new line.
void insertBlockAfter(EditBuffer& edits, const TokenView& view, size_t tok, const std::string& block) {
  const std::string& src = view.s;
  const std::string& nl = edits.newline();
  size_t after = view.tokens[tok].end;
  size_t eol = src.find('\n', after);
  size_t nextThing = npos;
  if (tok + 1 < view.tokens.size()) nextThing = view.tokens[tok + 1].begin;
  for (const auto& d : view.directives) {
    if (d.begin >= after) {
      nextThing = std::min(nextThing, d.begin);
      break;
    }
  }
  for (const auto& c : view.blockComments) {
    if (c.begin >= after) nextThing = std::min(nextThing, c.begin);
  }
  if (eol == npos) {
    edits.add(src.size(), 0, nl + nl + block);
  } else if (nextThing != npos && nextThing < eol) {
    edits.add(after, 0, nl + nl + block);
  } else {
    edits.add(eol + 1, 0, nl + block);
  }
}

}  // namespace stereoshift::hlsl_splice
