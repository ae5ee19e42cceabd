// The HLSL splice's geometry rewriter: this turns every `stream.Append(v)` of a geometry shader
// into `stream.Append(stereoshift_shift_T(v))` (T the stream element struct), Append calls in
// `#define` bodies included, and declares the eye parameters and the helper before the first
// function that appends.
#include "transpiler/backend/hlsl_splice/rewriters.h"

#include <algorithm>
#include <set>

namespace stereoshift::hlsl_splice {

namespace {

class GeometryRewriter : Rewriter {
 public:
  using Rewriter::Rewriter;

  std::optional<SpliceError> run(const std::vector<const Function*>& entries) {
    const Param* entryStream = nullptr;
    if (auto err = findStream(entries, entryStream)) return err;
    const std::string elem = entryStream->streamElement;
    const StructDef* sd = findStruct(elem);
    if (!sd) {
      return errAt(entryStream->nameTok != npos ? entryStream->nameTok : entryStream->begin,
                   "the stream element type '" + elem +
                       "' is not a struct defined in this file (structs from #include files are not seen)");
    }
    std::optional<std::string> path = positionPath(elem);
    if (!path) return errAt(sd->nameTok, "struct '" + elem + "' has no member with semantic SV_Position");
    ShiftHelper shift{elem, std::string(kPrefix) + "_shift_" + elem, *path, {}};

    const std::set<std::string> buffers = appendBufferNames();
    std::vector<const Function*> candidates(entries.begin(), entries.end());
    if (auto err = wrapAppendCalls(shift, buffers, candidates)) return err;
    wrapMacroAppendCalls(shift, buffers, candidates);
    if (sites_ == 0) {
      return errAt(entries.front()->nameTok, "geometry shader '" + opt_.entryPoint + "' has no Append call");
    }

    size_t first = npos;
    for (const Function* f : candidates) first = std::min(first, toks_[f->declBegin].begin);
    size_t structEnd = toks_[sd->endTok].end;
    if (first < structEnd) {
      return errAt(sd->nameTok, "struct '" + elem + "' is defined after its first use at " + where(first));
    }
    if (auto err = checkConflicts({opt_.cbufferName, opt_.eyeSignName, opt_.separationName,
                                   opt_.convergenceName, shift.function})) {
      return err;
    }
    insertBlockBefore(first, structEnd, preambleText({shift}));
    return std::nullopt;
  }

 private:
  // The stream parameter of the entry points (its element type is the struct to shift); every
  // stream of the file must carry that type.
  std::optional<SpliceError> findStream(const std::vector<const Function*>& entries, const Param*& entryStream) const {
    for (const Function* f : entries) {
      for (const auto& p : f->params) {
        if (!p.streamElement.empty() && !entryStream) entryStream = &p;
      }
    }
    if (!entryStream) {
      return errAt(entries.front()->nameTok, "geometry entry point '" + opt_.entryPoint +
                                                 "' has no TriangleStream/LineStream/PointStream parameter");
    }
    for (const auto& f : functions_) {
      for (const auto& p : f.params) {
        if (!p.streamElement.empty() && p.streamElement != entryStream->streamElement) {
          return errAt(p.nameTok != npos ? p.nameTok : p.begin,
                       "streams of different element types ('" + entryStream->streamElement + "' and '" +
                           p.streamElement + "') are not supported");
        }
      }
    }
    return std::nullopt;
  }

  // Names that are not streams: AppendStructuredBuffer<T> objects.
  std::set<std::string> appendBufferNames() const {
    std::set<std::string> buffers;
    for (size_t k = 0; k + 1 < toks_.size(); ++k) {
      if (!isWord(k, "AppendStructuredBuffer") || !isPunct(k + 1, '<')) continue;
      size_t t = k + 1;
      int depth = 0;
      do {
        if (isPunct(t, '<')) ++depth;
        if (isPunct(t, '>')) --depth;
        ++t;
      } while (t < toks_.size() && depth > 0);
      if (isIdent(t)) buffers.insert(std::string(text(t)));
    }
    return buffers;
  }

  // Append calls in function bodies (and anywhere else outside directives); the functions that
  // make them join `candidates`.
  std::optional<SpliceError> wrapAppendCalls(const ShiftHelper& shift, const std::set<std::string>& buffers,
                                             std::vector<const Function*>& candidates) {
    auto isBufferReceiver = [&](const std::string& recv, const Function* f) {
      if (f) {
        for (const auto& p : f->params) {
          if (p.name == recv) return p.streamElement.empty() && p.typeName == "AppendStructuredBuffer";
        }
      }
      return buffers.count(recv) != 0;
    };
    for (size_t k = 0; k + 2 < toks_.size(); ++k) {
      if (!isPunct(k, '.') || !isWord(k + 1, "Append") || !isPunct(k + 2, '(')) continue;
      const Function* f = enclosingFunction(k);
      std::string recv;
      if (k > 0 && isIdent(k - 1) && !(k > 1 && isPunct(k - 2, '.'))) recv = std::string(text(k - 1));
      if (!recv.empty() && isBufferReceiver(recv, f)) continue;
      size_t close = match_[k + 2];
      if (close == k + 3) return errAt(k + 1, "Append() without an argument");
      for (size_t t = k + 3; t < close; ++t) {
        if (isPunct(t, '(') || isPunct(t, '[') || isPunct(t, '{')) t = match_[t];
        else if (isPunct(t, ',')) return errAt(k + 1, "Append() with more than one argument");
      }
      addEdit(toks_[k + 2].end, 0, shift.function + "(");
      addEdit(toks_[close].begin, 0, ")");
      ++sites_;
      if (f) candidates.push_back(f);
    }
    return std::nullopt;
  }

  // Append calls inside #define bodies (the directive's own tokens): the functions that use such a
  // macro need the helper too.
  void wrapMacroAppendCalls(const ShiftHelper& shift, const std::set<std::string>& buffers,
                            std::vector<const Function*>& candidates) {
    std::set<std::string> appendMacros;
    for (const auto& d : directives_) {
      if (d.name != "define" || d.body.empty() || !d.bodyReadable) continue;
      const auto& st = d.body;
      auto stext = [&](size_t k) { return std::string_view(s_).substr(st[k].begin, st[k].end - st[k].begin); };
      auto spunct = [&](size_t k, char c) {
        return k < st.size() && st[k].kind == TokKind::Punct && s_[st[k].begin] == c;
      };
      for (size_t k = 0; k + 2 < st.size(); ++k) {
        if (!spunct(k, '.') || stext(k + 1) != "Append" || !spunct(k + 2, '(')) continue;
        if (k > 0 && st[k - 1].kind == TokKind::Ident && buffers.count(std::string(stext(k - 1)))) continue;
        int depth = 0;
        size_t close = npos;
        for (size_t t = k + 2; t < st.size(); ++t) {
          if (spunct(t, '(')) ++depth;
          if (spunct(t, ')') && --depth == 0) {
            close = t;
            break;
          }
        }
        if (close == npos || close == k + 3) continue;
        addEdit(st[k + 2].end, 0, shift.function + "(");
        addEdit(st[close].begin, 0, ")");
        ++sites_;
        appendMacros.insert(d.macroName);
      }
    }
    if (appendMacros.empty()) return;
    for (const auto& f : functions_) {
      for (size_t t = f.bodyOpen; t < f.bodyClose; ++t) {
        if (isIdent(t) && appendMacros.count(std::string(text(t)))) {
          candidates.push_back(&f);
          break;
        }
      }
    }
  }
};

}  // namespace

std::optional<SpliceError> rewriteGeometry(SpliceUnit& unit, const std::vector<const Function*>& entries) {
  return GeometryRewriter(unit).run(entries);
}

}  // namespace stereoshift::hlsl_splice
