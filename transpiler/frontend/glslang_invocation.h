// How the front end runs glslang: this turns a shader text, its stage and language, a client (Vulkan
// or OpenGL rules, or for re-compiles the dialect's own AST-only rules) and the conversion's options
// into one glslang parse, link and SPIR-V generation, with its diagnostics and what the source says
// that SPIR-V does not keep (explicit qualifiers, multiview's view count). compileToSpirv decides
// which attempts to make; verifyCompiles re-compiles emitted text with the same environment.
#pragma once

#include "core/diagnostics.h"
#include "core/shader.h"
#include "transpiler/frontend/front_end_options.h"

#include <glslang/Public/ShaderLang.h>

#include <cstdint>
#include <string>
#include <vector>

namespace stereoshift {

// How glslang reads a shader: Vulkan or OpenGL rules, each producing SPIR-V, or (for checking
// emitted OpenGL GLSL/ESSL as a driver would) the dialect's own rules without SPIR-V.
enum class Client { Vulkan, OpenGL, AstOnly };

EShLanguage toGlslang(Stage stage);

// `-D` definitions (and, for GLSL, the include extension) as the preamble glslang reads first.
std::string buildPreamble(const std::vector<std::string>& defines, bool glsl);

// Sets the input language, client and target environment of `shader`; returns the messages to
// parse and link with. HLSL always goes through Vulkan rules (descriptor sets, registers).
// `options` (absent when checking emitted text) carries --target-env and --target-spv.
int configureEnvironment(glslang::TShader& shader, Stage stage, SourceLanguage language, Client client,
                         const std::string& entry, const FrontEndOptions* options = nullptr);

// One glslang run over `text` (the input's text, or its legacy translation) as `client`.
struct Attempt {
  bool ok = false;
  std::vector<uint32_t> spirv;
  Diagnostics diags;
  SourceInfo info;
  std::vector<std::string> included;
  // A user input or output without a location, or a uniform / storage block or opaque uniform
  // without a binding ("input 'uv' has no location"; empty: none): OpenGL gives those meaning (names, glBindAttribLocation,
  // glUniformBlockBinding), Vulkan GLSL does not (glslangValidator -V refuses them; this front end
  // auto-maps them only to make SPIR-V).
  std::string openGLStyleInterface;
};
Attempt compileGlslangOnce(const SourceFile& input, const std::string& text, Stage stage, SourceLanguage language,
                           Client client, const std::string& entry, const FrontEndOptions& options);

}  // namespace stereoshift
