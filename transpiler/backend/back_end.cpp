#include "transpiler/backend/back_end.h"

#include "core/crash_phase.h"
#include "transpiler/source/identifiers.h"

#include <spirv_cross/spirv_glsl.hpp>
#include <spirv_cross/spirv_hlsl.hpp>
#include <spirv_cross/spirv_msl.hpp>

#include <cctype>
#include <string_view>

namespace stereoshift {

namespace {

// SPIRV-Cross gives every location-assigned varying the semantic TEXCOORD<location>; put back the
// semantic strings of the source inside the SPIRV_Cross_Input / SPIRV_Cross_Output structs.
// (Hand-written scans here and below: std::regex cost 6% of a whole tree conversion.)
std::string restoreSemantics(const std::string& text, const std::string& structName,
                             const std::map<uint32_t, std::string>& semantics) {
  if (semantics.empty()) return text;
  size_t begin = text.find("struct " + structName + "\n");
  if (begin == std::string::npos) return text;
  size_t end = text.find("};", begin);
  if (end == std::string::npos) return text;
  static constexpr std::string_view kTexcoord = ": TEXCOORD";
  std::string rebuilt = text.substr(0, begin);
  size_t last = begin;
  for (size_t at = text.find(kTexcoord, begin); at != std::string::npos && at < end;
       at = text.find(kTexcoord, at + 1)) {
    size_t digits = at + kTexcoord.size(), stop = digits;
    while (stop < end && std::isdigit(static_cast<unsigned char>(text[stop]))) ++stop;
    if (stop == digits || stop - digits > 9 || text[stop] != ';') continue;
    auto found = semantics.find(static_cast<uint32_t>(std::stoul(text.substr(digits, stop - digits))));
    if (found == semantics.end()) continue;
    rebuilt.append(text, last, at - last);
    rebuilt += ": " + found->second;
    last = stop;  // keeps the ';'
  }
  rebuilt.append(text, last, std::string::npos);
  return rebuilt;
}

// Renames every whole identifier (a maximal run of [A-Za-z0-9_]) that `names` maps, in one scan, so
// a new name is never renamed again by a later entry.
std::string renameIdentifiers(const std::string& text, const std::map<std::string, std::string, std::less<>>& names) {
  if (names.empty()) return text;
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    if (!isIdentifierChar(text[i])) {
      out += text[i++];
      continue;
    }
    size_t j = i;
    while (j < text.size() && isIdentifierChar(text[j])) ++j;
    std::string_view word(text.data() + i, j - i);
    auto found = names.find(word);
    if (found != names.end())
      out += found->second;
    else
      out += word;
    i = j;
  }
  return out;
}

// SPIRV-Cross always names the HLSL entry point `main`: `void main(` / `SPIRV_Cross_Output main(`.
std::string renameEntryPoint(std::string text, const std::string& entryPoint) {
  static constexpr std::string_view kMain = " main(";
  for (size_t at = text.find(kMain); at != std::string::npos; at = text.find(kMain, at + 1)) {
    std::string_view before(text.data(), at);
    bool returnType = false;
    for (std::string_view type : {"void", "SPIRV_Cross_Output"})
      if (before.ends_with(type) && (before.size() == type.size() || !isIdentifierChar(before[before.size() - type.size() - 1])))
        returnType = true;
    if (returnType) text.replace(at + 1, 4, entryPoint);
  }
  return text;
}

// The HLSL text of `words` (SPIRV-Cross, with the source's semantics and cbuffer member names put
// back); nullopt, with the reason in `diags`, for a stage SPIRV-Cross cannot write as HLSL.
std::optional<std::string> emitHlsl(const std::vector<uint32_t>& words, const SourceInfo& info,
                                    const BackEndOptions& options, const EmitHints& hints, const std::string& file,
                                    Diagnostics& diags) {
  // HLSL vertex, geometry and domain shaders back to HLSL take the source splice
  // (splice_route.h); this serves the cross-language route (GLSL/SPIR-V in) and the HLSL re-emits
  // left: changed pixel shaders, vertex fallbacks. SPIRV-Cross's HLSL writer has no geometry, hull
  // or domain stage: refused with that said, rather than its "Unsupported builtin in HLSL: 13".
  if (info.stage == Stage::Geometry || info.stage == Stage::TessControl || info.stage == Stage::TessEvaluation ||
      info.stage == Stage::Mesh || info.stage == Stage::Task) {
    const char* what = info.stage == Stage::Geometry      ? "geometry"
                       : info.stage == Stage::TessControl ? "hull (tessellation control)"
                       : info.stage == Stage::TessEvaluation ? "domain (tessellation evaluation)"
                       : info.stage == Stage::Mesh        ? "mesh"
                                                          : "amplification (task)";
    diags.error(file, std::string("--target hlsl: SPIRV-Cross, which writes the HLSL, has no ") + what +
                          " shaders; nothing was written (convert this stage for a GLSL, ESSL or SPIR-V target, "
                          "or keep an HLSL version of it written by hand)");
    return std::nullopt;
  }
  spirv_cross::CompilerHLSL compiler(words);
  auto h = compiler.get_hlsl_options();
  h.shader_model = static_cast<uint32_t>(options.targetVersion.value_or(50));
  // SV_ViewID (single-pass multiview) exists from shader model 6.1 on.
  if (!options.targetVersion)
    for (spv::Capability c : compiler.get_declared_capabilities())
      if (c == spv::CapabilityMultiView) h.shader_model = 61;
  // From 6.2 on SPIRV-Cross writes buffer loads as templates (Load<float4>), which glslang, the
  // check every output passes, cannot parse; 6.1's text is valid at any later model. Only
  // 16-bit types need 6.2's own text.
  if (h.shader_model >= 62) {
    bool sixteenBit = false;
    for (spv::Capability c : compiler.get_declared_capabilities())
      sixteenBit |= c == spv::CapabilityFloat16 || c == spv::CapabilityInt16 ||
                    c == spv::CapabilityStorageBuffer16BitAccess || c == spv::CapabilityStorageInputOutput16;
    if (!sixteenBit) h.shader_model = 61;
  }
  h.support_nonzero_base_vertex_base_instance = false;
  compiler.set_hlsl_options(h);
  if (info.stage == Stage::Vertex)
    for (const auto& [location, semantic] : hints.inputSemantics)
      compiler.add_vertex_attribute_remap({location, semantic});
  std::string text = compiler.compile();
  if (info.stage != Stage::Vertex) text = restoreSemantics(text, "SPIRV_Cross_Input", hints.inputSemantics);
  text = restoreSemantics(text, "SPIRV_Cross_Output", hints.outputSemantics);
  // cbuffer members keep the names the application looks up.
  text = renameIdentifiers(text, hints.cbufferMemberNames);
  if (!info.entryPoint.empty() && info.entryPoint != "main") text = renameEntryPoint(std::move(text), info.entryPoint);
  return text;
}

}  // namespace

EmittedSource emitSource(const std::vector<uint32_t>& words, const SourceInfo& info, const BackEndOptions& options,
                         EyeSelect eyeSelect,
                      const EmitHints& hints, const std::string& file, Diagnostics& diags) {
  ScopedCrashPhase phase(kSpirvCrossPhase);
  EmittedSource result;
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
        // Vulkan GLSL in, Vulkan GLSL out; HLSL / SPIR-V carry descriptor sets, so they keep them too;
        // an older --target-version asks for OpenGL GLSL: push constants become plain uniforms, sets
        // go (core/shader.h, vulkanGlslOutput).
        o.vulkan_semantics = vulkanGlslOutput(info, o.es, options.targetVersion);
        o.enable_420pack_extension = false;  // never add an extension the source did not ask for
        o.separate_shader_objects = false;
        o.vertex.support_nonzero_base_instance = false;  // no stray SPIRV_Cross_BaseInstance uniform
        o.emit_line_directives = false;
        // OpenGL multiview (GL_OVR_multiview2) needs `layout(num_views = N) in;`, which SPIR-V does not
        // carry: the source's own N, else 2 (a stereo pair) for a Vulkan multiview source.
        if (!o.vulkan_semantics)
          for (spv::Capability c : compiler.get_declared_capabilities())
            if (c == spv::CapabilityMultiView) o.ovr_multiview_view_count = info.multiviewViews > 0 ? info.multiviewViews : 2;
        // gl_Layer / gl_ViewportIndex written before the geometry stage (instanced single-pass stereo):
        // SPIRV-Cross writes them without the extension that allows it.
        if (info.stage != Stage::Geometry)
          for (spv::Capability c : compiler.get_declared_capabilities())
            if (c == spv::CapabilityShaderViewportIndexLayerEXT) compiler.require_extension("GL_ARB_shader_viewport_layer_array");
        compiler.set_common_options(o);
        // OpenGL GLSL has no separate textures and samplers (HLSL's Texture2D + SamplerState, Vulkan
        // GLSL's texture2D + sampler): each pair used together becomes one combined sampler named
        // <texture>_<sampler>, a texel fetch without a sampler reads through a dummy one.
        if (!o.vulkan_semantics) {
          uint32_t dummy = compiler.build_dummy_sampler_for_combined_images();
          compiler.build_combined_image_samplers();
          for (const auto& pair : compiler.get_combined_image_samplers()) {
            std::string image = compiler.get_name(pair.image_id), sampler = compiler.get_name(pair.sampler_id);
            bool alone = pair.sampler_id == dummy || sampler.empty();
            compiler.set_name(pair.combined_id, alone ? image : image + "_" + sampler);
          }
        }
        result.text = compiler.compile();
        result.vulkanSemantics = o.vulkan_semantics;
        break;
      }
      case TargetLanguage::Hlsl: {
        std::optional<std::string> text = emitHlsl(words, info, options, hints, file, diags);
        if (!text) return result;
        result.text = std::move(*text);
        break;
      }
      case TargetLanguage::Msl: {
        // Metal has no geometry stage (tessellation it has: SPIRV-Cross turns tesc into a compute kernel
        // and tese into a post-tessellation vertex function); mesh and task stages SPIRV-Cross cannot
        // write as Metal either. Refused, never written as text that is not Metal.
        if (info.stage == Stage::Geometry || info.stage == Stage::Mesh || info.stage == Stage::Task) {
          const char* what = info.stage == Stage::Geometry ? "geometry" : info.stage == Stage::Mesh ? "mesh" : "task";
          diags.error(file, std::string("--target msl: Metal has no ") + what +
                                " shader that SPIRV-Cross can write (convert this stage for another target, or move "
                                "its work into a vertex, compute or post-tessellation stage)");
          return result;
        }
        spirv_cross::CompilerMSL compiler(words);
        auto msl = compiler.get_msl_options();
        // 2.1 is the first MSL with [[invariant]] positions; default to it unless asked otherwise.
        int v = options.targetVersion.value_or(21);
        msl.msl_version = spirv_cross::CompilerMSL::Options::make_msl_version(uint32_t(v / 10), uint32_t(v % 10));
        // Single-pass multiview: Metal has no view index of its own; SPIRV-Cross emulates it with
        // instancing (the application draws instanceCount * 2 and binds the view mask buffer), the
        // view going to [[render_target_array_index]] of a two-layer target.
        if (eyeSelect == EyeSelect::ViewIndex) {
          msl.multiview = true;
          msl.multiview_layered_rendering = true;
        }
        compiler.set_msl_options(msl);
        result.text = compiler.compile();
        // SPIRV-Cross writes `unknown` where it has no Metal function qualifier for the entry point.
        if (result.text.find("\nunknown ") != std::string::npos) {
          diags.error(file, std::string("--target msl: SPIRV-Cross cannot express this ") + stageName(info.stage) +
                                " shader as a Metal function; nothing was written");
          return result;
        }
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
