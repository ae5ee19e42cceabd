// One result shape for the layers above the passes: a value, or the located diagnostic that says
// why there is none, in the form every error of the tool is printed (`file:line:col: error:
// message`; the file is filled in by the caller that knows it, `located`). Readers of text (the D3D
// assembly reader first) return it instead of a bool and an error out-parameter.
#pragma once

#include "core/diagnostics.h"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>

namespace stereoshift {

// An error at a 1-based line and column of the text being read (0: the whole file / unknown).
inline Diagnostic errorAt(size_t line, size_t column, std::string message) {
  return Diagnostic{Severity::Error, "", static_cast<int>(line), static_cast<int>(column), std::move(message)};
}

// An error with no line or column: about a whole file, an action on it or a run (`file: error:
// message` once located).
inline Diagnostic plainError(std::string message) { return errorAt(0, 0, std::move(message)); }

// `error` placed in `file` (kept when it names one already).
inline Diagnostic located(Diagnostic error, const std::string& file) {
  if (error.file.empty()) error.file = file;
  return error;
}

template <class T>
class Result;

// A result with no value: done, or the diagnostic that says why not.
struct Done {};
using Status = Result<Done>;

template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : value_(std::move(value)) {}
  Result(Diagnostic error) : error_(std::move(error)) {}

  bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }
  T& operator*() { return *value_; }
  const T& operator*() const { return *value_; }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }
  // Why there is no value (meaningful only when !ok()).
  const Diagnostic& error() const { return error_; }

 private:
  std::optional<T> value_;
  Diagnostic error_;
};

}  // namespace stereoshift
