// See output_version.h.
#include "transpiler/output_version.h"

namespace stereoshift {

std::optional<int> singlePassRaisedGlslVersion(const SourceInfo& source, const TranspileOptions& options,
                                               std::string* why) {
  const auto& eye = options.eye;
  if (eye.select == EyeSelect::Parameter || options.targetVersion || source.compatibilityBuiltIns) return std::nullopt;
  bool keptAsGlsl = options.target == TargetLanguage::Auto || options.target == TargetLanguage::Glsl;
  if (source.language != SourceLanguage::Glsl || source.es || source.vulkan || !keptAsGlsl) return std::nullopt;
  bool last = options.shiftThisStage;  // the stage that rasterizes
  int needed = 0;
  if (eye.select == EyeSelect::ViewIndex) {
    if (source.stage == Stage::Vertex) {
      needed = 330;
      *why = "GL_OVR_multiview2 needs GLSL 330";
    }
  } else if ((source.stage == Stage::Vertex || source.stage == Stage::TessEvaluation) && last) {
    needed = 410;
    *why = "the eye is written to gl_Layer / gl_ViewportIndex from this stage through "
           "GL_ARB_shader_viewport_layer_array, which needs GLSL 410";
  } else if (source.stage == Stage::Vertex) {
    needed = 330;
    *why = "the eye is handed to the next stage as a flat int varying";
  } else if (source.stage == Stage::Geometry && eye.route == EyeRoute::Viewport) {
    needed = 410;
    *why = "a geometry shader writes gl_ViewportIndex from GLSL 410";
  }
  if (!needed || source.version >= needed) return std::nullopt;
  return needed;
}

}  // namespace stereoshift
