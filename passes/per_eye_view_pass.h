// What the per-eye-view pass needs to know about the stage that consumes a vertex shader's outputs.
//
// A vertex shader that writes `vViewTS = TBN * (camera - world)` cannot tell on its own whether the
// next stage steps texture coordinates along it (relief / parallax occlusion mapping: needs the
// per-eye camera) or only shades with it (specular: the mono eye is fine). transpilePipeline()
// analyses the fragment stage first and hands these facts to the last pre-rasterization stage.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace stereoshift {

namespace spirv {
class Module;
}
struct PassContext;

struct StageInputUse {
  uint32_t location = 0;
  bool hasLocation = false;
  std::string name;                 // OpName of the input variable (OpenGL links by name)
  bool read = false;                // the stage loads it at all
  bool feedsTexcoord = false;       // some texture coordinate is computed from it
  bool feedsTexcoordAsDirection = false;  // ... after it became a direction (normalize, v.xy / v.z, reflect)
};

struct NextStageFacts {
  std::string file;                 // the consuming stage, for the report
  bool linkByName = false;          // OpenGL GLSL: outputs match inputs by name, not by location
  std::vector<StageInputUse> inputs;
};

// Analyses the inputs of a (fragment) stage: which ones feed texture coordinates. Reads only the
// shared folded copy of the context's module; changes nothing.
NextStageFacts analyseStageInputs(PassContext& context);

// Whether the module subtracts vec3/vec4 values anywhere: a view vector (`camera - P`) needs one, and
// inlining and folding never create one, so without it per-eye-view has nothing to look at.
bool hasVectorSubtraction(const spirv::Module& module);

}  // namespace stereoshift
