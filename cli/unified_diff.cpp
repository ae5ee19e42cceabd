// See unified_diff.h. The edit script is Myers' O(ND) greedy algorithm ("An O(ND) Difference
// Algorithm and Its Variations", 1986) over lines, after the common prefix and suffix are set
// aside: a conversion's edits are few and local, so D is small and the diff is near linear.
#include "cli/unified_diff.h"

#include <algorithm>
#include <string_view>
#include <vector>

namespace stereoshift {

namespace {

std::vector<std::string_view> splitLines(const std::string& text) {
  std::vector<std::string_view> lines;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    end = end == std::string::npos ? text.size() : end + 1;
    lines.emplace_back(text.data() + start, end - start);
    start = end;
  }
  return lines;
}

enum class Op { Keep, Remove, Add };
struct Edit {
  Op op;
  size_t line;  // in `a` for Keep and Remove, in `b` for Add
};

// The shortest edit script from a to b (Myers): the furthest-reaching path per diagonal, one
// vector of them per edit distance kept for the walk back.
std::vector<Edit> editScript(const std::vector<std::string_view>& a, const std::vector<std::string_view>& b) {
  const long n = static_cast<long>(a.size()), m = static_cast<long>(b.size()), max = n + m;
  std::vector<long> v(2 * max + 2, 0);
  std::vector<std::vector<long>> trace;
  long found = -1;
  for (long d = 0; d <= max && found < 0; ++d) {
    trace.push_back(v);
    for (long k = -d; k <= d; k += 2) {
      long x = (k == -d || (k != d && v[max + k - 1] < v[max + k + 1])) ? v[max + k + 1] : v[max + k - 1] + 1;
      long y = x - k;
      while (x < n && y < m && a[x] == b[y]) ++x, ++y;
      v[max + k] = x;
      if (x >= n && y >= m) {
        found = d;
        break;
      }
    }
  }
  std::vector<Edit> edits;
  long x = n, y = m;
  for (long d = found; d > 0; --d) {
    const std::vector<long>& pv = trace[d];
    long k = x - y;
    bool down = k == -d || (k != d && pv[max + k - 1] < pv[max + k + 1]);
    long prevK = down ? k + 1 : k - 1;
    long prevX = pv[max + prevK], prevY = prevX - prevK;
    while (x > prevX && y > prevY) {
      edits.push_back({Op::Keep, static_cast<size_t>(--x)});
      --y;
    }
    if (down) edits.push_back({Op::Add, static_cast<size_t>(--y)});
    else edits.push_back({Op::Remove, static_cast<size_t>(--x)});
  }
  while (x > 0) edits.push_back({Op::Keep, static_cast<size_t>(--x)});
  std::reverse(edits.begin(), edits.end());
  return edits;
}

void appendLine(std::string& out, char mark, std::string_view line) {
  out += mark;
  out += line;
  if (line.empty() || line.back() != '\n') out += "\n\\ No newline at end of file\n";
}

std::string range(size_t start, size_t count) {
  // diff -u: "start,count", the start 1-based, or the line before an empty range.
  std::string r = std::to_string(count == 0 ? start : start + 1);
  if (count != 1) r += "," + std::to_string(count);
  return r;
}

}  // namespace

std::string unifiedDiff(const std::string& before, const std::string& after, const std::string& beforeName,
                        const std::string& afterName) {
  if (before == after) return {};
  std::vector<std::string_view> a = splitLines(before), b = splitLines(after);
  // The common prefix and suffix stay out of the O(ND) search; they come back as kept lines.
  size_t prefix = 0;
  while (prefix < a.size() && prefix < b.size() && a[prefix] == b[prefix]) ++prefix;
  size_t suffix = 0;
  while (suffix < a.size() - prefix && suffix < b.size() - prefix && a[a.size() - 1 - suffix] == b[b.size() - 1 - suffix])
    ++suffix;
  std::vector<std::string_view> midA(a.begin() + prefix, a.end() - suffix), midB(b.begin() + prefix, b.end() - suffix);
  std::vector<Edit> edits;
  for (size_t i = 0; i < prefix; ++i) edits.push_back({Op::Keep, i});
  for (Edit e : editScript(midA, midB)) edits.push_back({e.op, e.line + prefix});
  for (size_t i = a.size() - suffix; i < a.size(); ++i) edits.push_back({Op::Keep, i});

  // Each edit's position in both texts, then hunks: changes with up to 3 kept lines around them,
  // joined when fewer than 7 kept lines separate two changes.
  struct Placed {
    Edit edit;
    size_t ai, bi;
  };
  std::vector<Placed> placed;
  size_t ai = 0, bi = 0;
  for (Edit e : edits) {
    placed.push_back({e, ai, bi});
    if (e.op != Op::Add) ++ai;
    if (e.op != Op::Remove) ++bi;
  }
  constexpr size_t kContext = 3;
  std::string out = "--- " + beforeName + "\n+++ " + afterName + "\n";
  size_t i = 0;
  while (i < placed.size()) {
    while (i < placed.size() && placed[i].edit.op == Op::Keep) ++i;
    if (i == placed.size()) break;
    size_t begin = i >= kContext ? i - kContext : 0, end = i;
    // Extend over changes closer than 2 * context kept lines.
    for (size_t j = i, kept = 0; j < placed.size(); ++j) {
      if (placed[j].edit.op == Op::Keep) {
        if (++kept > 2 * kContext) break;
      } else {
        kept = 0;
        end = j + 1;
      }
    }
    size_t stop = std::min(placed.size(), end + kContext);
    size_t countA = 0, countB = 0;
    for (size_t j = begin; j < stop; ++j) {
      if (placed[j].edit.op != Op::Add) ++countA;
      if (placed[j].edit.op != Op::Remove) ++countB;
    }
    out += "@@ -" + range(placed[begin].ai, countA) + " +" + range(placed[begin].bi, countB) + " @@\n";
    for (size_t j = begin; j < stop; ++j) {
      const Edit& e = placed[j].edit;
      if (e.op == Op::Keep) appendLine(out, ' ', a[e.line]);
      else if (e.op == Op::Remove) appendLine(out, '-', a[e.line]);
      else appendLine(out, '+', b[e.line]);
    }
    i = stop;
  }
  return out;
}

}  // namespace stereoshift
