// The front end's limits on untrusted shader text, and the cheap scan that enforces the bracket
// limit before glslang sees the text: glslang parses HLSL brackets by recursion, so a deep enough
// input overflows its stack before any tree exists. The scan reads the lexer's tokens, so brackets
// inside comments and string literals never count (those of directive lines do: macro bodies are code).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace stereoshift {

// Bytes of shader source glslang reads for one shader: the file and everything it includes.
inline constexpr size_t kMaxSourceBytes = 16u << 20;
// Files open at once through nested #include, the shader itself not counted.
inline constexpr size_t kMaxIncludeDepth = 32;
// Open brackets ( [ { at once, every kind together.
inline constexpr int kMaxBracketNesting = 256;
// Levels of the syntax tree glslang builds (checked on the tree, so macros count): its SPIR-V
// generation walks the tree by recursion and overflows its stack near 20,000 levels.
inline constexpr int kMaxSyntaxTreeDepth = 2000;
// Nested if / ?: / loop / switch: SPIRV-Tools' validator checks structured control flow in time
// that grows with the cube of this depth (400 levels: seconds; 1,000: most of a minute).
inline constexpr int kMaxControlFlowNesting = 128;

// Where a text goes past a limit: 1-based line and column of the construct, and why.
struct LimitViolation {
  int line = 1, column = 1;
  std::string message;
};

// The first place `text` goes past a limit glslang cannot be trusted with, if any: kMaxBracketNesting
// brackets, kMaxControlFlowNesting nested statements (if / loops / switch, read from the text as the
// grammar nests them), or an expression whose operators at one bracket level run past
// kMaxSyntaxTreeDepth. (The same tree limits are checked again on glslang's tree, after parsing and
// before anything walks it, where macros count too.)
std::optional<LimitViolation> findNestingViolation(const std::string& text);

// The words of the control-flow nesting error, the same from the text scan and the tree check.
std::string controlFlowNestingMessage();

// "16 MiB", "3.2 MiB", "812 KiB": a byte count for messages.
std::string describeBytes(size_t bytes);

}  // namespace stereoshift
