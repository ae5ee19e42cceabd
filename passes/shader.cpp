#include "passes/shader.h"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace stereoshift {

bool readFile(const std::string& path, std::string* contents) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream text;
  text << in.rdbuf();
  *contents = text.str();
  return true;
}

std::string pipelineKey(const std::string& path) {
  size_t slash = path.find_last_of('/');
  size_t nameStart = slash == std::string::npos ? 0 : slash + 1;
  return path.substr(0, path.find('.', nameStart));
}

std::optional<Stage> stageFromName(const std::string& raw) {
  std::string n = raw;
  std::transform(n.begin(), n.end(), n.begin(), ::tolower);
  if (n == "vert" || n == "vertex" || n == "vs") return Stage::Vertex;
  if (n == "tesc" || n == "tesscontrol" || n == "hs" || n == "hull") return Stage::TessControl;
  if (n == "tese" || n == "tesseval" || n == "tessevaluation" || n == "ds" || n == "domain") return Stage::TessEvaluation;
  if (n == "geom" || n == "geometry" || n == "gs") return Stage::Geometry;
  if (n == "frag" || n == "fragment" || n == "ps" || n == "pixel") return Stage::Fragment;
  if (n == "comp" || n == "compute" || n == "cs") return Stage::Compute;
  if (n == "mesh" || n == "ms") return Stage::Mesh;
  if (n == "task" || n == "as" || n == "amplification") return Stage::Task;
  return std::nullopt;
}

std::optional<Stage> stageFromPath(const std::string& path) {
  // name.vert, name.vert.glsl, name.vert.hlsl, name.vs.hlsl
  std::string file = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  std::vector<std::string> parts;
  for (size_t start = 0, dot; start <= file.size(); start = dot + 1) {
    dot = file.find('.', start);
    if (dot == std::string::npos) dot = file.size();
    parts.push_back(file.substr(start, dot - start));
  }
  for (size_t i = parts.size(); i-- > 1;)
    if (auto s = stageFromName(parts[i])) return s;
  return std::nullopt;
}

const char* stageName(Stage stage) {
  switch (stage) {
    case Stage::Vertex: return "vert";
    case Stage::TessControl: return "tesc";
    case Stage::TessEvaluation: return "tese";
    case Stage::Geometry: return "geom";
    case Stage::Fragment: return "frag";
    case Stage::Compute: return "comp";
    case Stage::Task: return "task";
    case Stage::Mesh: return "mesh";
    default: return "unknown";
  }
}

bool isPreRasterization(Stage stage) {
  return stage == Stage::Vertex || stage == Stage::TessControl || stage == Stage::TessEvaluation ||
         stage == Stage::Geometry || stage == Stage::Mesh;
}

}  // namespace stereoshift
