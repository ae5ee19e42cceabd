// HLSL effect-file (.fx) text for glslang, and the entry points an HLSL file's text names: turns an
// effect file into HLSL glslang can parse by blanking what only the D3D effect framework reads
// (technique / pass blocks, state-object blocks, shader-object variables), finds the entry points
// the techniques compile, and chooses the one to compile. Blanked text keeps every line break, so
// glslang's line numbers stay those of the file.
#pragma once

#include "core/shader.h"

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace stereoshift {

// `text` with every effect-only block replaced by spaces (line breaks kept); `text` itself when it
// has none. Blanked: `technique`/`technique10`/`technique11` blocks (case-insensitive, as in effect
// files), `BlendState`/`DepthStencilState`/`RasterizerState` blocks and `VertexShader name = ...;`
// style shader-object variables.
std::string blankEffectBlocks(const std::string& text);

// The entry points the techniques of `text` compile, with the stage of their profile, in the order
// written: `CompileShader(vs_5_0, Name())` (effects 10/11) and `compile vs_3_0 Name()` (effects 9).
std::vector<std::pair<Stage, std::string>> techniqueEntryPoints(const std::string& text);

// The first function of HLSL `text` that its signature marks as a `stage` entry point and that no
// other function calls: for a vertex shader an output with semantic SV_Position (the return value,
// a member of the returned struct, an `out` parameter), for a pixel shader SV_Target. Empty when
// there is none (or for other stages).
std::string entryPointBySignature(const std::string& text, Stage stage);

// The identifiers of HLSL `text` followed by `(`: the functions it defines or calls (and the
// function-like macros it uses), by name; a mention in a comment or a string is none.
std::set<std::string> mentionedFunctions(const std::string& text);

// The entry-point name samples use for `stage` (VSMain, PSMain, ...), null where there is none.
const char* conventionalHlslEntry(Stage stage);

// The HLSL entry point to compile: `requested` (-e), else `main`, else the stage's conventional
// name, else the first function of this stage a technique compiles, else the one its signature
// marks (entryPointBySignature), else `main`; `functions` is mentionedFunctions(text).
std::string chooseHlslEntry(const std::string& text, const std::set<std::string>& functions, Stage stage,
                            const std::string& requested);

}  // namespace stereoshift
