// D3D shader assembly as text (the SM4/SM5 disassembly 3Dmigoto dumps as `<hash>-vs.txt`): this
// turns the text into lines the assembly route edits and the interpreter runs, each line kept as
// written. A line is a comment, blank, the shader-model line (`vs_5_0`), a declaration (`dcl_*`) or
// an instruction; an opcode with a bracketed part (`ld_indexable(texture2d)(float,float,float,float)`)
// is one opcode, operands are split at the commas outside brackets (a declaration's at blanks too:
// `(float,float,float,float) t0` is two), and a declaration that opens a
// brace (`dcl_immediateConstantBuffer { {...},`) runs on until its braces close.
#pragma once

#include "core/result.h"
#include "core/shader.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stereoshift::d3dasm {

enum class LineKind { Blank, Comment, ShaderModel, Declaration, Instruction, Continuation };

struct Operand {
  std::string text;  // as written, without the blanks around it
  size_t column = 0; // 1-based, in the line
};

struct AsmLine {
  LineKind kind = LineKind::Blank;
  size_t number = 0;             // 1-based
  std::string text;              // as written, without the line ending
  std::string indent;            // the blanks before the opcode
  std::string opcode;            // "mad_sat", "dcl_temps", "ld_indexable(texture2d)(float,float,float,float)"
  std::vector<Operand> operands;
  size_t lastLine = 0;           // a declaration: the index of its last line (its braces' close)
  // The opcode without its modifiers and bracketed parts: "mad" for "mad_sat", "ld_indexable".
  std::string baseOpcode() const;
  bool saturates() const;        // the `_sat` modifier
};

struct ShaderModel {
  char kind = 0;        // 'v', 'p', 'g', 'h', 'd', 'c'
  int major = 0, minor = 0;
  std::string text;     // "vs_5_0", "vs_4_0_level_9_3"
};

struct AsmText {
  std::vector<AsmLine> lines;
  std::string newline = "\n";    // the text's own line ending
  bool endsWithNewline = true;
  ShaderModel model;
  size_t modelLine = 0;          // index of the shader-model line
};

// An error of the assembly reader, the shift or the interpreter: the tool's located diagnostic
// (core/result.h), its file left to the caller.
using AsmError = Diagnostic;

// The shader model of `word` (`vs_5_0`, `ps_4_1`, `gs_4_0`, `vs_4_0_level_9_1`), or nullopt.
std::optional<ShaderModel> readShaderModel(std::string_view word);
std::optional<Stage> stageOfShaderModel(const ShaderModel& model);

// Whether `text` is D3D shader assembly: its first line that is not blank or a `//` comment is a
// shader-model line. (The disassembler's header is all comments; the file name does not decide it:
// 3Dmigoto writes `<hash>-vs.txt` for assembly and `<hash>-vs_replace.txt` for HLSL.)
bool isD3DAssembly(const std::string& text);

// Splits `text` into lines; an error where the text is not assembly the route can edit (no
// shader-model line, unbalanced brackets in an operand list).
Result<AsmText> parseAssembly(const std::string& text);

// The text again: every line as stored, joined with the text's line ending.
std::string joinLines(const AsmText& text);

// Where the identifier `name` is a whole register token in `line` after its opcode (not a swizzle
// after a '.', not inside a longer identifier, not in a trailing comment): 0-based offsets.
std::vector<size_t> registerTokenOffsets(const AsmLine& line, std::string_view name);

}  // namespace stereoshift::d3dasm
