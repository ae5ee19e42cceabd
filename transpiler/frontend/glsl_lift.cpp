// See glsl_lift.h. The versions are those of the OpenGL specifications that took each extension
// into core (the "promoted to core in OpenGL X" of each extension's specification).
#include "transpiler/frontend/glsl_lift.h"

#include "transpiler/frontend/glsl_version.h"
#include "transpiler/source/lexer.h"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace stereoshift {

std::optional<int> coreVersionOf(std::string_view extension) {
  static constexpr std::array<std::pair<std::string_view, int>, 36> kCore = {{
      {"GL_EXT_gpu_shader4", 130},
      {"GL_ARB_uniform_buffer_object", 140}, {"GL_ARB_texture_rectangle", 140}, {"GL_ARB_draw_instanced", 140},
      {"GL_ARB_texture_multisample", 150},
      {"GL_ARB_explicit_attrib_location", 330}, {"GL_ARB_shader_bit_encoding", 330},
      {"GL_ARB_gpu_shader5", 400}, {"GL_ARB_gpu_shader_fp64", 400}, {"GL_ARB_texture_query_lod", 400},
      {"GL_ARB_tessellation_shader", 400}, {"GL_ARB_texture_cube_map_array", 400}, {"GL_ARB_texture_gather", 400},
      {"GL_ARB_sample_shading", 400},
      {"GL_ARB_separate_shader_objects", 410}, {"GL_ARB_viewport_array", 410}, {"GL_ARB_vertex_attrib_64bit", 410},
      {"GL_ARB_shading_language_420pack", 420}, {"GL_ARB_shader_image_load_store", 420},
      {"GL_ARB_shader_atomic_counters", 420}, {"GL_ARB_conservative_depth", 420},
      {"GL_ARB_shading_language_packing", 420},
      {"GL_ARB_arrays_of_arrays", 430}, {"GL_ARB_texture_query_levels", 430},
      {"GL_ARB_shader_storage_buffer_object", 430}, {"GL_ARB_compute_shader", 430},
      {"GL_ARB_explicit_uniform_location", 430}, {"GL_ARB_fragment_layer_viewport", 430},
      {"GL_ARB_shader_image_size", 430},
      {"GL_ARB_enhanced_layouts", 440},
      {"GL_ARB_derivative_control", 450}, {"GL_ARB_shader_texture_image_samples", 450}, {"GL_ARB_cull_distance", 450},
      {"GL_ARB_shader_draw_parameters", 460}, {"GL_ARB_shader_atomic_counter_ops", 460},
      {"GL_ARB_gl_spirv", 460},
  }};
  for (const auto& [name, version] : kCore)
    if (name == extension) return version;
  return std::nullopt;
}

namespace {

// Backslash-newlines removed; each logical line ends with as many line breaks as it was long.
std::string joinContinuations(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  int owed = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && (text.compare(i + 1, 1, "\n") == 0 || text.compare(i + 1, 2, "\r\n") == 0)) {
      i += text[i + 1] == '\r' ? 2 : 1;
      ++owed;
      continue;
    }
    out += text[i];
    if (text[i] == '\n')
      for (; owed > 0; --owed) out += '\n';
  }
  return out;
}

}  // namespace

bool enablesAnExtension(const std::string& text) {
  source::LexedText lexed(text);
  for (size_t k = 0; k < lexed.size(); ++k) {
    if (lexed[k].kind != source::TokenKind::Directive || lexed[k].directive != source::DirectiveKind::Extension) continue;
    std::string line = source::spelledString(text, lexed[k]);
    if (line.find("include") == std::string::npos && line.find("disable") == std::string::npos) return true;
  }
  return false;
}

LiftedGlsl liftGlsl(const std::string& text) {
  LiftedGlsl result;
  result.text = joinContinuations(text);
  if (result.text != text) result.what = "line continuations joined";
  VersionLine v = findVersion(result.text);
  // Comments or blank lines before #version (ESSL wants it first; glslang refuses, some drivers
  // do not): the directive moved to the first line, the lines before it left blank, so every line
  // after it keeps its number.
  if (v.problem.empty() && v.begin != std::string::npos && v.begin > 0) {
    std::string before = result.text.substr(0, v.begin);
    size_t breaks = static_cast<size_t>(std::count(before.begin(), before.end(), '\n'));
    result.text = result.text.substr(v.begin, v.end - v.begin) + std::string(breaks, '\n') + result.text.substr(v.end);
    if (!result.what.empty()) result.what += "; ";
    result.what += "the text before #version moved after it";
    v = findVersion(result.text);
  }
  if (!v.problem.empty() || v.es || v.begin == std::string::npos) {
    result.lifted = result.text != text;
    return result;
  }
  int wanted = v.version;
  std::string because;
  source::LexedText lexed(result.text);
  struct ExtensionLine {
    size_t begin, end;  // the directive line, without its line break
    int core;
  };
  std::vector<ExtensionLine> extensionLines;
  for (size_t k = 0; k < lexed.size(); ++k) {
    // A built-in block redeclared (`out gl_PerVertex { vec4 gl_Position; };`, `in gl_PerVertex {...}
    // gl_in[];`): glslang takes it from GLSL 410 (GL_ARB_separate_shader_objects' core version) on.
    if (lexed.isIdentifier(k) && lexed.text(k) == "gl_PerVertex" && lexed.isPunct(lexed.nextNonComment(k), '{') &&
        wanted < 410) {
      wanted = 410;
      because = "a gl_PerVertex redeclaration";
    }
    if (lexed[k].kind != source::TokenKind::Directive || lexed[k].directive != source::DirectiveKind::Extension) continue;
    size_t name = lexed.firstOperand(k);
    if (name >= lexed.size()) continue;
    std::string line = source::spelledString(result.text, lexed[k]);
    if (line.find("disable") != std::string::npos) continue;
    std::string extension(lexed.text(name));
    auto core = coreVersionOf(extension);
    if (!core) continue;
    size_t lineEnd = result.text.find('\n', lexed[k].begin);
    if (lineEnd == std::string::npos) lineEnd = result.text.size();
    if (lineEnd > lexed[k].begin && result.text[lineEnd - 1] == '\r') --lineEnd;
    extensionLines.push_back({lexed[k].begin, lineEnd, *core});
    if (*core > wanted) {
      wanted = *core;
      because = extension;
    }
  }
  // An extension that is core at the raised version needs no #extension line, and glslang does not
  // know some of them by name (GL_ARB_arrays_of_arrays: "extension not supported", an error under
  // `require`): blanked with spaces, so every byte keeps its offset.
  if (wanted > v.version)
    for (const auto& line : extensionLines)
      if (line.core <= wanted) result.text.replace(line.begin, line.end - line.begin, line.end - line.begin, ' ');
  if (wanted > v.version) {
    // `#version 150 compatibility` -> `#version 400 compatibility`: the number only.
    std::string directive = result.text.substr(v.begin, v.end - v.begin);
    std::string number = std::to_string(v.version);
    size_t at = directive.find(number);
    if (at != std::string::npos) {
      directive.replace(at, number.size(), std::to_string(wanted));
      result.text.replace(v.begin, v.end - v.begin, directive);
      if (!result.what.empty()) result.what += "; ";
      result.what += "the analysis copy's #version " + number + " raised to " + std::to_string(wanted) + " for " + because;
    }
  }
  result.lifted = result.text != text;
  return result;
}

}  // namespace stereoshift
