// The front end's #include resolution for glslang (see include_resolver.h), and the include-guard
// reader it decides cycles with.
#include "transpiler/frontend/include_resolver.h"

#include "transpiler/frontend/source_limits.h"
#include "transpiler/source/file_io.h"
#include "transpiler/source/lexer.h"

#include <algorithm>
#include <cctype>
#include <string_view>

namespace fs = std::filesystem;

namespace stereoshift {

namespace {

// The words of the directive `lexer` has just read, as spelled.
std::vector<std::string> directiveWords(const std::string& text, source::Lexer& lexer) {
  std::vector<std::string> words;
  for (const source::Token& t : lexer.directiveWords()) words.push_back(source::spelledString(text, t));
  return words;
}

// The file `header` names under `dir` as a Windows compiler finds it: `\` separates directories
// (`#include "shaders\common.hlsli"`), and a part that does not exist as spelled is the one entry
// of its directory that matches it without regard to case (`Common.hlsli` for `common.hlsli`).
// Empty when there is no such file, or more than one entry matches.
fs::path windowsSpelling(const fs::path& dir, std::string header) {
  std::replace(header.begin(), header.end(), '\\', '/');
  fs::path found = dir;
  std::error_code ec;
  for (const fs::path& part : fs::path(header)) {
    if (part == "." || part == ".." || fs::exists(found / part, ec)) {
      found /= part;
      continue;
    }
    auto lower = [](std::string text) {
      std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
      return text;
    };
    const std::string wanted = lower(part.string());
    fs::path match;
    for (const auto& entry : fs::directory_iterator(found, ec)) {
      if (lower(entry.path().filename().string()) != wanted) continue;
      if (!match.empty()) return {};  // `a.h` and `A.h`: ambiguous
      match = entry.path();
    }
    if (match.empty()) return {};
    found = match;
  }
  return found;
}

}  // namespace

bool hasIncludeGuard(const std::string& text) {
  source::Lexer lexer(text);
  source::Token t;
  auto nextCode = [&] {
    while (lexer.next(t))
      if (t.kind != source::TokenKind::Comment) return true;
    return false;
  };
  if (!nextCode() || t.kind != source::TokenKind::Directive) return false;
  const source::DirectiveKind first = t.directive;
  std::vector<std::string> words = directiveWords(text, lexer);
  if (first == source::DirectiveKind::Pragma) return words == std::vector<std::string>{"pragma", "once"};
  if (first != source::DirectiveKind::Ifndef || words.size() != 2 || !isValidIdentifier(words[1])) return false;
  if (!nextCode() || t.kind != source::TokenKind::Directive || t.directive != source::DirectiveKind::Define) return false;
  std::vector<std::string> define = directiveWords(text, lexer);
  return define.size() >= 2 && define[1] == words[1];
}

RestrictedIncluder::RestrictedIncluder(std::string mainFile, std::vector<std::string> includeDirs, size_t mainBytes)
    : mainFile_(std::move(mainFile)), includeDirs_(std::move(includeDirs)), totalBytes_(mainBytes) {
  std::error_code ec;
  chain_.push_back({mainFile_, fs::weakly_canonical(mainFile_, ec)});
}

RestrictedIncluder::IncludeResult* RestrictedIncluder::includeLocal(const char* header, const char* includer, size_t depth) {
  if (!beginDirective(header, includer, depth)) return nullptr;
  fs::path base = (depth <= 1 || !includer || !*includer) ? fs::path(mainFile_).parent_path()
                                                          : fs::path(includer).parent_path();
  if (auto* r = tryOpen(base, header)) return r;
  if (refusedThisDirective_) return nullptr;
  return searchIncludeDirs(header);
}

RestrictedIncluder::IncludeResult* RestrictedIncluder::includeSystem(const char* header, const char* includer, size_t depth) {
  // glslang asks here too after includeLocal found nothing; a refusal there stands.
  if (refusedThisDirective_ && currentHeader_ == header && currentIncluder_ == (includer ? includer : "") &&
      currentDepth_ == depth)
    return nullptr;
  if (!beginDirective(header, includer, depth)) return nullptr;
  return searchIncludeDirs(header);
}

void RestrictedIncluder::releaseInclude(IncludeResult* result) {
  if (!result) return;
  delete static_cast<std::string*>(result->userData);
  delete result;
}

// Starts resolving one directive: `depth` files are open once it succeeds (glslang counts the
// shader itself as 0), so the include stack is the first `depth` entries of chain_.
bool RestrictedIncluder::beginDirective(const char* header, const char* includer, size_t depth) {
  currentHeader_ = header;
  currentIncluder_ = includer ? includer : "";
  currentDepth_ = depth;
  refusedThisDirective_ = false;
  if (chain_.size() > depth) chain_.resize(depth);
  if (depth > kMaxIncludeDepth) {
    refuse("#include nests deeper than " + std::to_string(kMaxIncludeDepth) + " files (the front end's limit)");
    return false;
  }
  return true;
}

RestrictedIncluder::IncludeResult* RestrictedIncluder::searchIncludeDirs(const char* header) {
  for (const auto& dir : includeDirs_) {
    if (auto* r = tryOpen(dir, header)) return r;
    if (refusedThisDirective_) return nullptr;
  }
  return nullptr;
}

void RestrictedIncluder::refuse(std::string message) {
  IncludeRefusal r;
  r.includer = currentIncluder_;
  r.header = currentHeader_;
  r.replacement.message = std::move(message);
  refusals_.push_back(std::move(r));
  refusedThisDirective_ = true;
}

RestrictedIncluder::IncludeResult* RestrictedIncluder::tryOpen(const fs::path& dir, const char* header) {
  fs::path candidate = (dir.empty() ? fs::path(".") : dir) / header;
  std::error_code ec;
  if (!fs::is_regular_file(candidate, ec)) {
    // Shaders written on Windows: `\` paths and headers whose case differs from the file's.
    candidate = windowsSpelling(dir.empty() ? fs::path(".") : dir, header);
    if (candidate.empty() || !fs::is_regular_file(candidate, ec)) return nullptr;
  }
  fs::path root = fs::weakly_canonical(dir.empty() ? fs::path(".") : dir, ec);
  fs::path resolved = fs::weakly_canonical(candidate, ec);
  auto rel = resolved.lexically_relative(root);
  // A build sandbox (Bazel's) lays declared inputs out as symbolic links to the real files: a file
  // inside the directory as named is inside it, wherever its link points.
  auto named = candidate.lexically_normal().lexically_relative((dir.empty() ? fs::path(".") : dir).lexically_normal());
  auto escapes = [](const fs::path& r) { return r.empty() || *r.begin() == ".."; };
  if (escapes(rel) && escapes(named)) return nullptr;  // escapes the allowed directory
  std::string name = candidate.lexically_normal().string();

  // A file that is already open: with an include guard (or #pragma once) its inner copy would
  // be skipped anyway, so it is included as empty text; without one nothing ends the recursion.
  auto open = std::find_if(chain_.begin(), chain_.end(), [&](const OpenFile& f) { return f.identity == resolved; });
  if (open != chain_.end()) {
    if (!open->guarded) {
      refuse("#include cycle: " + describeCycle(resolved, name));
      return nullptr;
    }
    chain_.push_back({name, resolved, true});
    return new IncludeResult(name, "", 0, new std::string);
  }
  uintmax_t bytes = fs::file_size(candidate, ec);
  if (ec || bytes > kMaxSourceBytes - std::min(totalBytes_, kMaxSourceBytes)) {
    refuse("including " + name + " takes the shader's source past " + describeBytes(kMaxSourceBytes) +
           " (the front end's limit)");
    return nullptr;
  }
  auto* text = new std::string;
  if (!readFile(candidate.string(), text)) {
    delete text;
    return nullptr;
  }
  totalBytes_ += text->size();
  if (auto violation = findNestingViolation(*text)) {
    refuse(violation->message);
    refusals_.back().replacement.file = name;
    refusals_.back().replacement.line = violation->line;
    refusals_.back().replacement.column = violation->column;
    refusals_.back().ownLocation = true;
    delete text;
    return nullptr;
  }
  sources_.emplace_back(name, *text);
  if (std::find(included_.begin(), included_.end(), name) == included_.end()) included_.push_back(name);
  chain_.push_back({name, resolved, hasIncludeGuard(*text)});
  return new IncludeResult(name, text->data(), text->size(), text);
}

// "a.vert -> x.glsl -> x.glsl": the include stack from the shader up to the first file that
// repeats, with `next` (about to be opened) last.
std::string RestrictedIncluder::describeCycle(const fs::path& nextIdentity, const std::string& nextName) const {
  std::vector<OpenFile> path = chain_;
  path.push_back({nextName, nextIdentity});
  std::string text;
  for (size_t k = 0; k < path.size(); ++k) {
    text += (k ? " -> " : "") + path[k].name;
    bool repeats = std::any_of(path.begin(), path.begin() + static_cast<long>(k),
                               [&](const OpenFile& f) { return f.identity == path[k].identity; });
    if (repeats) break;
  }
  return text;
}

Diagnostics explainRefusedIncludes(const Diagnostics& raw, const std::vector<IncludeRefusal>& refusals) {
  static constexpr std::string_view kCouldNotInclude = "'#include' : Could not process include directive for header name: ";
  Diagnostics out;
  for (Diagnostic d : raw.all()) {
    if (d.message.starts_with(kCouldNotInclude)) {
      std::string header = d.message.substr(kCouldNotInclude.size());
      for (const auto& r : refusals) {
        if (r.header != header || (!r.includer.empty() && r.includer != d.file)) continue;
        if (r.ownLocation) {
          d = r.replacement;
        } else {
          d.message = r.replacement.message;
        }
        break;
      }
    }
    out.add(std::move(d));
  }
  return out;
}

}  // namespace stereoshift
