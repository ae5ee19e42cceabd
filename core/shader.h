// What every layer knows about a shader: its stage, the language and dialect it was written in
// (SourceInfo), the output languages and environments there are. The bottom layer: everything
// above includes it. The options of a conversion are per layer: PassOptions (passes/pass_options.h),
// FrontEndOptions and BackEndOptions (transpiler/frontend, transpiler/backend), all three in
// TranspileOptions (transpiler/transpile_options.h).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>


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
  // GLSL glslang refused as written and parsed as a lifted copy (transpiler/frontend/glsl_lift.h):
  // what was lifted. The analysis ran on the copy; the output is the original text.
  std::string liftedBecause;
  // GLSL without #version whose text is of a version from 330 / ESSL 300 on (the loader prepends
  // one): the front end parsed it with `version` put before it; a re-compile of the output (which
  // stays without one) goes through the front end, which decides the same again.
  bool versionPrepended = false;
  // A text spliced back without #version whose #extension lines give it, at a lower version, what
  // glslang knows only at `version` (GL_ARB_gpu_shader5's uaddCarry at 400): the loader may prepend
  // any version from the extensions' own, so the splice writes only what GLSL `spliceVersionCap` has
  // (no `precise` / `fma`). 0: no cap.
  int spliceVersionCap = 0;
};

// Whether a GLSL/ESSL output keeps Vulkan GLSL's semantics (descriptor sets, push constants): the
// input is Vulkan GLSL of the same dialect, or HLSL / SPIR-V (which carry sets), and no
// --target-version asks for OpenGL. One below ESSL 310 or GLSL 430 does, unless it is at or above
// the input's own version in the same dialect: Vulkan GLSL is written from 430 on in practice, and
// below it the std430 blocks a Vulkan module's push constants and buffers are emitted as do not
// compile, while an older OpenGL target is what such a request means.
bool vulkanGlslOutput(const SourceInfo& source, bool esOutput, std::optional<int> targetVersion);
// Whether GLSL/ESSL `version` has inverse(). ESSL 300 has it; desktop GLSL 1.40's specification
// does too, but glslang, which re-compiles every output, declares it from 150 on: an output must
// pass both, so 150.
bool glslHasInverse(int version, bool es);

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
