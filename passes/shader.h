// What the passes know about a shader and about the conversion asked for: the stage, the language
// and dialect it was written in, and the options of a conversion (the passes read the middle part;
// the front and back ends read theirs). The bottom layer: everything above includes it.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "passes/pass_options.h"

namespace stereoshift {

// The ray-tracing stages (GL_EXT_ray_tracing) draw nothing a camera projects: they are recognised so that
// a tree's ray-tracing shaders are classified and copied like compute shaders, never dropped.
enum class Stage {
  Vertex, TessControl, TessEvaluation, Geometry, Fragment, Compute, Task, Mesh,
  RayGen, Intersection, AnyHit, ClosestHit, Miss, Callable,
  Unknown
};
enum class SourceLanguage { Glsl, Hlsl, Spirv };
// How the input language was decided: a language extension in the file name (.hlsl, .fx, .glsl),
// the -x flag, or the text itself (#version, HLSL-only constructs, the SPIR-V magic number).
enum class LanguageSource { Extension, Flag, Content };

// The SPIR-V environment of a conversion (glslc's --target-env): which client rules glslang
// parses with and which spirv-val environment checks the result. `OpenGL45` is glslc's `opengl`
// and `opengl4.5`.
enum class TargetEnv { Vulkan1_0, Vulkan1_1, Vulkan1_2, Vulkan1_3, OpenGL45 };

// Which output language: `Auto` keeps the input's own language and version.
enum class TargetLanguage { Auto, Glsl, Essl, Hlsl, Msl, Spirv, SpirvAsm };

// The options of one conversion, one part per layer: FrontEndOptions (transpiler/frontend),
// PassOptions (passes/pass_options.h), BackEndOptions (transpiler/backend). Each layer reads its own.
struct FrontEndOptions {
  std::optional<Stage> stage;        // -S; default: decideStage (file name, #pragma shader_stage)
  // --stage-ext / the manifest's [stages]: more stage extensions (lower case, no dot: "vp" -> vert).
  std::map<std::string, Stage> stageExtensions;
  std::optional<TargetEnv> targetEnv;  // --target-env; default: Vulkan 1.0 or OpenGL, from the source
  std::optional<int> targetSpv;        // --target-spv: the SPIR-V minor version (spv1.4 -> 4)
  std::optional<SourceLanguage> language;  // -x glsl|hlsl; default: from the file name, else the content
  std::string entryPoint;            // HLSL entry point; default `main`, then VSMain/PSMain/...
  std::vector<std::string> defines;  // NAME or NAME=VALUE
  std::vector<std::string> includeDirs;
};

struct BackEndOptions {
  TargetLanguage target = TargetLanguage::Auto;
  std::optional<int> targetVersion;  // GLSL/ESSL version or HLSL shader model (50, 51, 60, ...)
  bool verify = false;               // recompile emitted GLSL/HLSL with glslang
  bool forceReemit = false;          // re-emit even when nothing changed
};

struct TranspileOptions : FrontEndOptions, PassOptions, BackEndOptions {};

// What the back end must know about the original source to emit a drop-in replacement.
struct SourceInfo {
  SourceLanguage language = SourceLanguage::Glsl;
  LanguageSource languageSource = LanguageSource::Extension;
  std::string languageReason;  // what decided the language, for the report
  // HLSL written for Vulkan with [[vk::binding(N)]]: every resource class shares one binding space,
  // unlike D3D's per-class registers (b, t, s, u); the injected cbuffer must avoid all of them.
  bool vulkanBindings = false;
  Stage stage = Stage::Unknown;
  int version = 0;         // GLSL #version; 0 for HLSL and SPIR-V
  bool es = false;         // ESSL
  bool vulkan = false;     // Vulkan GLSL semantics (sets, push constants)
  std::string entryPoint;  // the source's entry-point name
  // Names (variable names, and block type names) that carried explicit qualifiers in the source.
  // glslang must auto-assign locations and bindings to make SPIR-V; the back end strips the ones
  // the source did not have, so OpenGL shaders keep relying on glBindAttribLocation & co.
  std::set<std::string> explicitLocation;
  std::set<std::string> explicitBinding;
  // GL_OVR_multiview's `layout(num_views = N) in;` (0: none). SPIR-V does not carry N, and an OpenGL
  // GLSL output of a multiview shader must declare it again.
  int multiviewViews = 0;
  // Legacy GLSL that uses compatibility built-ins (gl_Vertex, gl_ModelViewProjectionMatrix, ...),
  // which the front end's translation declares as stereoshift_* inputs and uniforms.
  bool compatibilityBuiltIns = false;
};

struct SourceFile {
  std::string path;      // as given; used in diagnostics and for the extension
  std::string contents;  // raw bytes
};

// Stage and file helpers shared by every layer.
bool readFile(const std::string& path, std::string* contents);  // false when it cannot be read

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
const char* targetEnvName(TargetEnv env);
const char* stageName(Stage stage);
bool isPreRasterization(Stage stage);
// rgen, rint, rahit, rchit, rmiss, rcall.
bool isRayTracing(Stage stage);
}  // namespace stereoshift
