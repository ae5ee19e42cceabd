// Front end: GLSL (desktop, ES, Vulkan) and HLSL through glslang to SPIR-V; SPIR-V binaries as is.
#pragma once

#include "transpiler/stereoshift.h"

#include <set>
#include <string>
#include <vector>

namespace stereoshift {

// What the back end must know about the original source to emit a drop-in replacement.
struct SourceInfo {
  SourceLanguage language = SourceLanguage::Glsl;
  Stage stage = Stage::Unknown;
  int version = 0;         // GLSL #version; 0 for HLSL and SPIR-V
  bool es = false;         // ESSL
  bool vulkan = false;     // Vulkan GLSL semantics (sets, push constants)
  bool versionRaised = false;  // glslang needed a higher version to make SPIR-V
  std::string entryPoint;  // the source's entry-point name
  // Names (variable names, and block type names) that carried explicit qualifiers in the source.
  // glslang must auto-assign locations and bindings to make SPIR-V; the back end strips the ones
  // the source did not have, so OpenGL shaders keep relying on glBindAttribLocation & co.
  std::set<std::string> explicitLocation;
  std::set<std::string> explicitBinding;
  std::set<std::string> explicitSet;
};

struct FrontEndResult {
  bool ok = false;
  std::vector<uint32_t> spirv;
  SourceInfo info;
  std::vector<std::string> includedFiles;
};

// The first `#version N [es|core|compatibility]` directive at the start of a line of GLSL `text`.
struct VersionLine {
  int version = 110;  // GLSL's default without #version
  bool es = false;
  size_t begin = std::string::npos, end = std::string::npos;  // span of the directive's text
};
VersionLine findVersion(const std::string& text);

// Parses `input` into SPIR-V. Errors go to `diags` in file:line:col form.
FrontEndResult compileToSpirv(const SourceFile& input, const TranspileOptions& options, Diagnostics& diags);

// Re-compiles emitted GLSL/HLSL text to check that it is valid (`--verify`).
bool verifyCompiles(const std::string& text, SourceLanguage language, Stage stage, const std::string& entryPoint,
                    bool vulkanSemantics, const std::string& displayName, Diagnostics& diags);

// glslang's process-wide initialisation, done once.
void ensureGlslangInitialized();

}  // namespace stereoshift
