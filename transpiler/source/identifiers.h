// What an identifier is in shader source text, defined once for every layer above: GLSL and HLSL
// spell identifiers alike, [A-Za-z_][A-Za-z0-9_]*, in ASCII only (a byte of a UTF-8 sequence is
// never part of one, whatever the locale says).
#pragma once

#include <string_view>

namespace stereoshift {

// A character that may begin an identifier: [A-Za-z_].
constexpr bool isIdentifierStart(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

// A character that may appear in an identifier: [A-Za-z0-9_].
constexpr bool isIdentifierChar(char c) { return isIdentifierStart(c) || (c >= '0' && c <= '9'); }

constexpr bool isDecimalDigit(char c) { return c >= '0' && c <= '9'; }

// Whether all of `s` is one identifier (names the user gives on the command line, for example).
constexpr bool isValidIdentifier(std::string_view s) {
  if (s.empty() || !isIdentifierStart(s[0])) return false;
  for (char c : s)
    if (!isIdentifierChar(c)) return false;
  return true;
}

}  // namespace stereoshift
