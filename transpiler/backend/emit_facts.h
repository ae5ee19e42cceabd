// What a back-end route did, as typed facts for the stage's record (transpiler/report.h renders them).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace stereoshift {

// An entry point of an HLSL file as the vertex splice saw it (report["entry_points"]).
struct EntryPointFacts {
  std::string stage;                         // "vert", "geom", ...
  std::optional<std::string> classification; // set for the entry points converted
  bool shifted = false;
  std::string foundBy;                       // how the file names it (signature, technique, ...)
  std::string note;
};

// What a route did, for the report.
struct EmitFacts {
  std::string route;                        // "hlsl-source-splice", "glsl-source-splice"
  std::vector<std::string> notes;
  std::optional<std::map<std::string, EntryPointFacts>> entryPoints;
  std::vector<std::string> haloCopies, notCarried;
  std::optional<int> spliceSites;           // sites the splice shifted (the report's stereo-shift sites)
};

}  // namespace stereoshift
