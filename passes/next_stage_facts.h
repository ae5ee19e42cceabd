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

}  // namespace stereoshift
