#include "transpiler/back_end.h"

#include <spirv_cross/spirv_glsl.hpp>
#include <spirv_cross/spirv_hlsl.hpp>
#include <spirv_cross/spirv_msl.hpp>

#include <regex>

namespace stereoshift {

TargetLanguage resolveTarget(const SourceInfo& info, const TranspileOptions& options) {
  if (options.target != TargetLanguage::Auto) return options.target;
  switch (info.language) {
    case SourceLanguage::Hlsl: return TargetLanguage::Hlsl;
    case SourceLanguage::Spirv: return TargetLanguage::Spirv;
    case SourceLanguage::Glsl: return info.es ? TargetLanguage::Essl : TargetLanguage::Glsl;
  }
  return TargetLanguage::Glsl;
}

namespace {

// SPIRV-Cross gives every location-assigned varying the semantic TEXCOORD<location>; put back the
// semantic strings of the source inside the SPIRV_Cross_Input / SPIRV_Cross_Output structs.
std::string restoreSemantics(const std::string& text, const std::string& structName,
                             const std::map<uint32_t, std::string>& semantics) {
  if (semantics.empty()) return text;
  size_t begin = text.find("struct " + structName + "\n");
  if (begin == std::string::npos) return text;
  size_t end = text.find("};", begin);
  if (end == std::string::npos) return text;
  std::string body = text.substr(begin, end - begin);
  static const std::regex texcoord(R"(: TEXCOORD(\d+);)");
  std::string rebuilt;
  auto it = std::sregex_iterator(body.begin(), body.end(), texcoord);
  size_t last = 0;
  for (; it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    rebuilt += body.substr(last, static_cast<size_t>(m.position(0)) - last);
    uint32_t location = static_cast<uint32_t>(std::stoul(m[1]));
    auto found = semantics.find(location);
    rebuilt += found != semantics.end() ? ": " + found->second + ";" : m.str(0);
    last = static_cast<size_t>(m.position(0) + m.length(0));
  }
  rebuilt += body.substr(last);
  return text.substr(0, begin) + rebuilt + text.substr(end);
}

std::string replaceWord(const std::string& text, const std::string& from, const std::string& to) {
  return std::regex_replace(text, std::regex("\\b" + from + "\\b"), to);
}

}  // namespace

EmitResult emitSource(const std::vector<uint32_t>& words, const SourceInfo& info, const TranspileOptions& options,
                      const EmitHints& hints, const std::string& file, Diagnostics& diags) {
  EmitResult result;
  result.language = resolveTarget(info, options);
  try {
    switch (result.language) {
      case TargetLanguage::Glsl:
      case TargetLanguage::Essl: {
        spirv_cross::CompilerGLSL compiler(words);
        auto o = compiler.get_common_options();
        bool sameDialect = info.language == SourceLanguage::Glsl && (result.language == TargetLanguage::Essl) == info.es;
        o.es = result.language == TargetLanguage::Essl;
        o.version = static_cast<uint32_t>(
            options.targetVersion.value_or(sameDialect ? info.version : (o.es ? 310 : 450)));
        // Vulkan GLSL in, Vulkan GLSL out; HLSL / SPIR-V carry descriptor sets, so they keep them too.
        o.vulkan_semantics = info.vulkan && (sameDialect || info.language != SourceLanguage::Glsl);
        o.enable_420pack_extension = false;  // never add an extension the source did not ask for
        o.separate_shader_objects = false;
        o.vertex.support_nonzero_base_instance = false;  // no stray SPIRV_Cross_BaseInstance uniform
        o.emit_line_directives = false;
        compiler.set_common_options(o);
        result.text = compiler.compile();
        result.version = static_cast<int>(o.version);
        result.es = o.es;
        result.vulkanSemantics = o.vulkan_semantics;
        break;
      }
      case TargetLanguage::Hlsl: {
        spirv_cross::CompilerHLSL compiler(words);
        auto h = compiler.get_hlsl_options();
        h.shader_model = static_cast<uint32_t>(options.targetVersion.value_or(50));
        h.support_nonzero_base_vertex_base_instance = false;
        compiler.set_hlsl_options(h);
        if (info.stage == Stage::Vertex)
          for (const auto& [location, semantic] : hints.inputSemantics)
            compiler.add_vertex_attribute_remap({location, semantic});
        std::string text = compiler.compile();
        if (info.stage != Stage::Vertex) text = restoreSemantics(text, "SPIRV_Cross_Input", hints.inputSemantics);
        text = restoreSemantics(text, "SPIRV_Cross_Output", hints.outputSemantics);
        // cbuffer members keep the names the application looks up.
        for (const auto& [mangled, plain] : hints.cbufferMemberNames) text = replaceWord(text, mangled, plain);
        // SPIRV-Cross always calls the HLSL entry point `main`.
        if (!info.entryPoint.empty() && info.entryPoint != "main")
          text = std::regex_replace(text, std::regex(R"(\b(SPIRV_Cross_Output|void) main\()"),
                                    "$1 " + info.entryPoint + "(");
        result.text = std::move(text);
        result.version = static_cast<int>(h.shader_model);
        break;
      }
      case TargetLanguage::Msl: {
        spirv_cross::CompilerMSL compiler(words);
        auto msl = compiler.get_msl_options();
        // 2.1 is the first MSL with [[invariant]] positions; default to it unless asked otherwise.
        int v = options.targetVersion.value_or(21);
        msl.msl_version = spirv_cross::CompilerMSL::Options::make_msl_version(uint32_t(v / 10), uint32_t(v % 10));
        compiler.set_msl_options(msl);
        result.text = compiler.compile();
        break;
      }
      default:
        diags.error(file, "internal error: emitSource called for a SPIR-V target");
        return result;
    }
  } catch (const std::exception& e) {
    diags.error(file, std::string("SPIRV-Cross could not emit the shader: ") + e.what());
    return result;
  }
  result.ok = true;
  return result;
}

}  // namespace stereoshift
