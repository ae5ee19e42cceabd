// How a shader's stage is told, and the other rules that read a shader's file name: the one place
// every layer asks (the front end, the driver, the command line, `build`, the benchmarks). The
// enums they answer in (Stage, TargetEnv) stay with what the passes know (core/shader.h); the
// stage pragma is read through the lexer, so a commented-out one is no pragma.
#pragma once

#include "core/shader.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stereoshift {

// How a shader's stage is told, in one place (see decideStage). A file name is read as
//   <stem>[.<stage extension>][.<language extension>]
// where the language extension is .glsl .hlsl .fx (and the stage extension a stage token: vert,
// frag, vs, fs, ps, tcs, tes, ..., optionally followed by `h` or `shader`: .vsh, .fragmentshader),
// or an extension of `extraExtensions` (--stage-ext). Without a stage extension, a file with a
// language extension may name its stage as a separate part of the stem: parts are split at `.`,
// `_`, `-`, and where the case changes (basicVS, VS_water, water_ps, SkinnedPixel), and the last
// part that is a stage word decides. Include-only names (.hlsli .fxh .inc .glslinc .h) have none.
struct StagedName {
  std::optional<Stage> stage;
  std::string key;     // the name without the stage part and the language extension (the pipeline)
  std::string reason;  // "extension .vs", "name part 'PS'", ... for the report
};
StagedName readStagedName(const std::string& path, const std::map<std::string, Stage>& extraExtensions = {});

// What decided a shader's stage, with where a bad `#pragma shader_stage(...)` is.
struct StageDecision {
  std::optional<Stage> stage;
  std::string reason;   // "-S vert", "#pragma shader_stage(vertex)", "extension .vs", ...
  std::string problem;  // non-empty: an error at problemLine:problemColumn of the text
  int problemLine = 0, problemColumn = 0;
};
// The stage of the shader at `path` with text `text`: -S (`flag`) wins; then glslc's
// `#pragma shader_stage(vertex|fragment|...)` in the text; then the file name (readStagedName).
StageDecision decideStage(const std::string& path, const std::string& text, std::optional<Stage> flag,
                          const std::map<std::string, Stage>& extraExtensions = {});
// glslc's `#pragma shader_stage(...)` in `text`: the stage, or a problem when the name is unknown.
StageDecision stageFromPragma(const std::string& text);
// The words an error asks for when the stage cannot be told.
std::string stageHint(const std::string& path);

// Where `#include` looks for the shader at `shaderPath`, in order: the -I directories `userDirs`, the
// shader's own directory, and an `include` directory beside the shader when there is one. The one
// rule for single-shader runs, pipelines and `build` (each directory once).
std::vector<std::string> includeSearchPath(const std::string& shaderPath, const std::vector<std::string>& userDirs);

// 3Dmigoto's dumps (ShaderFixes/ names 3Dmigoto loads back by hash): a decompiled shader,
// `<16 hex digits>-<vs|ps|gs|hs|ds|cs>_replace.txt` (HLSL with the entry point `main`), or its
// assembly, `<16 hex digits>-<vs|...>.txt` (read by the assembly route, d3dasm/). The stage, from
// the two letters; nullopt for any other name.
std::optional<Stage> stageOf3DMigotoDump(const std::string& path);
// The decompiled-HLSL name only.
std::optional<Stage> stageOfDecompiledDump(const std::string& path);

// Names that hold code for other files only: never a pipeline stage.
bool isIncludeOnlyName(const std::string& path);

// The pipeline a shader belongs to: its directory and file name without the stage part and the
// language extension (shaders/terrain.vert.hlsl -> shaders/terrain, 5.1.parallax.vs -> 5.1.parallax,
// basicVS.hlsl -> basic, water_ps.hlsl -> water).
std::string pipelineKey(const std::string& path, const std::map<std::string, Stage>& extraExtensions = {});
std::optional<Stage> stageFromPath(const std::string& path, const std::map<std::string, Stage>& extraExtensions = {});
std::optional<Stage> stageFromName(const std::string& name);  // vert, frag, vertex, ...
// The stage of an HLSL compile profile (`vs_5_0`, `ps_4_0_level_9_1`, `cs_6_0`; any case), Unknown otherwise.
Stage stageFromHlslProfile(std::string_view profile);
// "vulkan1.2" -> TargetEnv::Vulkan1_2 ("opengl" and "opengl4.5" -> OpenGL45); nullopt when unknown.
std::optional<TargetEnv> targetEnvFromName(const std::string& name);

}  // namespace stereoshift
