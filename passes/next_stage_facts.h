// What the per-eye-view pass needs to know about the stage that consumes a vertex shader's outputs.
//
// A vertex shader that writes `vViewTS = TBN * (camera - world)` cannot tell on its own whether the
// next stage steps texture coordinates along it (relief / parallax occlusion mapping: needs the
// per-eye camera) or only shades with it (specular: the mono eye is fine). Nor can one that writes
// the camera itself, `TangentViewPos = TBN * viewPos`, beside `TangentFragPos = TBN * FragPos`, for
// the fragment stage to subtract (the tutorial form). The driver analyses the fragment
// stage first (AnalysisManager::stageInputUses) and hands these facts to the last pre-rasterization stage.
//
// "Offsets texture coordinates" means `uv +- f(v)`: a coordinate that is only computed from the
// view vector (a BRDF table at dot(N, V), a reflection lookup) is shading, not relief.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace stereoshift {

struct StageInputUse {
  uint32_t location = 0;
  bool hasLocation = false;
  std::string name;                 // OpName of the input variable, or the member's name in a block
  std::string blockName;            // a member of an interface block: the block's type name (OpenGL
                                    // links blocks by block name and member name)
  bool read = false;                // the stage loads it at all
  bool feedsTexcoord = false;       // taken as a direction, it offsets texture coordinates
  bool feedsTexcoordAsDirection = false;  // ... after it became a direction here (normalize, v.xy / v.z)
  bool subtractedForOffset = false;  // one side of `a - b` (b varying too) whose direction offsets
                                     // texture coordinates: `normalize(TangentViewPos - TangentFragPos)`
  bool operator==(const StageInputUse&) const = default;
};

struct NextStageFacts {
  std::string file;                 // the consuming stage, for the report
  bool linkByName = false;          // OpenGL GLSL: outputs match inputs by name, not by location
  std::vector<StageInputUse> inputs;
  bool operator==(const NextStageFacts&) const = default;
};

}  // namespace stereoshift
