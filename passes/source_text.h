// Small facts about shader source text shared by the front end, the back end, the HLSL splice and
// the diagnostics (GLSL and HLSL spell identifiers alike).
#pragma once

#include <cctype>

namespace stereoshift {

// A character that may appear in an identifier: [A-Za-z0-9_].
inline bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace stereoshift
