// HLSL effect-file (.fx) text for glslang, and the entry points an HLSL file's text names: turns an effect file into HLSL glslang can parse by
// blanking what only the D3D effect framework reads (technique / pass blocks, state-object blocks,
// shader-object variables), and finds the entry points the techniques compile. Blanked text keeps
// every line break, so glslang's line numbers stay those of the file.
#pragma once

#include "passes/shader.h"

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

}  // namespace stereoshift
