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

// Where the eye parameters (eyeSign, separation, convergence) come from.
enum class EyeSource {
  Auto,           // loose uniforms for OpenGL GLSL shaders that use loose uniforms, else UniformBlock
  UniformBlock,   // uniform block / cbuffer `StereoParams`
  PushConstant,   // members of the push-constant block (merged into an existing one)
  SpecConstant,   // specialization constants: a build can bake left and right variants
  LooseUniforms,  // OpenGL default-block uniforms
};

// Where eyeSign comes from. `Parameter`: one of the EyeSource kinds above (two passes, the
// application changes it between them). The single-pass modes derive it per vertex instead, so
// both eyes are drawn in one pass (separation and convergence stay where EyeSource puts them):
// `ViewIndex`: multiview (view 0 left, view 1 right); `InstanceIndex`: instanced stereo (the low bit
// of the instance index, the eye written to the render-target layer or viewport index).
enum class EyeSelect { Parameter, ViewIndex, InstanceIndex };
// Where instanced stereo sends each eye: a layer of a layered target, or a viewport (side by side).
enum class EyeRoute { Layer, Viewport };

enum class CutoffMode { Epsilon, Exact, None };
enum class ShiftForm { Branch, Select };

struct EyeParamOptions {
  EyeSource source = EyeSource::Auto;
  std::string blockName = "StereoParams";
  std::string instanceName = "stereo";
  std::string eyeSignName = "eyeSign";
  std::string separationName = "separation";
  std::string convergenceName = "convergence";
  std::string hudDepthName = "hudDepth";        // declared only with --hud-at-depth
  std::string eyeOffsetXName = "eyeOffsetX";    // declared only for per-eye view vectors that have
  std::string eyeOffsetYName = "eyeOffsetY";    // no matrix to derive the eye centre from
  std::string eyeOffsetZName = "eyeOffsetZ";
  std::string projScaleXName = "projScaleX";    // declared only for view rays with no projection at hand
  std::optional<uint32_t> descriptorSet;  // default 0
  std::optional<uint32_t> binding;        // default: first binding unused in the set
  std::optional<uint32_t> hlslRegister;   // cbuffer register b<N>; default: first unused
  std::optional<uint32_t> glBinding;      // OpenGL uniform-block binding; default: none (by name)
  uint32_t specIdBase = 100;              // SpecId of eyeSign; separation and convergence follow
  // Single-pass stereo (--eye-source multiview|instanced): see EyeSelect.
  EyeSelect select = EyeSelect::Parameter;
  bool swapEyes = false;                  // view / instance eye 0 is the right eye (+1)
  EyeRoute route = EyeRoute::Layer;       // instanced: --eye-route layer|viewport
  std::string eyeVaryingName = "stereoEye";  // instanced: the flat varying that hands the eye on
  uint32_t eyeVaryingLocation = 15;       // its location (15: the last one every Vulkan device has)
};

struct TranspileOptions {
  // Front end
  std::optional<Stage> stage;        // -S; default: decideStage (file name, #pragma shader_stage)
  // --stage-ext / the manifest's [stages]: more stage extensions (lower case, no dot: "vp" -> vert).
  std::map<std::string, Stage> stageExtensions;
  std::optional<TargetEnv> targetEnv;  // --target-env; default: Vulkan 1.0 or OpenGL, from the source
  std::optional<int> targetSpv;        // --target-spv: the SPIR-V minor version (spv1.4 -> 4)
  std::optional<SourceLanguage> language;  // -x glsl|hlsl; default: from the file name, else the content
  std::string entryPoint;            // HLSL entry point; default `main`, then VSMain/PSMain/...
  std::vector<std::string> defines;  // NAME or NAME=VALUE
  std::vector<std::string> includeDirs;
  // Passes
  EyeParamOptions eye;
  CutoffMode cutoff = CutoffMode::Epsilon;
  float cutoffEpsilon = 1e-5f;
  ShiftForm shiftForm = ShiftForm::Branch;
  bool invariantPosition = true;  // mark the position invariant + NoContraction on the shift
  bool fusedShift = false;        // x' = fma(eyeSign*separation, w - convergence, x): one rounding less
  bool compensatedShift = false;  // error-free transformations: x' within ~0.5 ULP of the exact shift
  bool haloFix = true;
  bool shiftThisStage = true;     // false for an intermediate stage of a pipeline
  // Per-eye pixel maths (docs/stereo-math.md sections 2-4)
  bool perEyeView = true;             // per-eye camera position where a view vector offsets texture coordinates
  bool perEyeSpecular = false;        // also where it only feeds lighting (specular looks fine mono)
  std::string cameraUniform;          // --camera-uniform: this uniform (or block member) is the camera position
  bool deferredUnprojection = true;   // stereo-correct `InvM * vec4(ndc, depth, 1)` in deferred passes
  bool hudAtDepth = false;            // place proven-2D shaders at the eye depth `hudDepth`
  std::vector<std::string> onlyPasses;  // --pass: run only these (by name()); empty: all
  bool validateEach = false;
  bool printAll = false;          // dump SPIR-V after every pass to the report log
  // Back end
  TargetLanguage target = TargetLanguage::Auto;
  std::optional<int> targetVersion;  // GLSL/ESSL version or HLSL shader model (50, 51, 60, ...)
  bool verify = false;               // recompile emitted GLSL/HLSL with glslang
  bool forceReemit = false;          // re-emit even when nothing changed
};

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
