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

// Names and facts of the enums above. How a stage is told from a file's name and text, and reading
// files, are the source-text layer's (transpiler/source/stage_rules.h, file_io.h).
const char* targetEnvName(TargetEnv env);
const char* stageName(Stage stage);
bool isPreRasterization(Stage stage);
// rgen, rint, rahit, rchit, rmiss, rcall.
bool isRayTracing(Stage stage);
}  // namespace stereoshift
