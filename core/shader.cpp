// The names of a shader's stage and target environment, and the stage facts the passes ask.
#include "core/shader.h"

namespace stereoshift {

const char* targetEnvName(TargetEnv env) {
  switch (env) {
    case TargetEnv::Vulkan1_0: return "vulkan1.0";
    case TargetEnv::Vulkan1_1: return "vulkan1.1";
    case TargetEnv::Vulkan1_2: return "vulkan1.2";
    case TargetEnv::Vulkan1_3: return "vulkan1.3";
    case TargetEnv::OpenGL45: return "opengl4.5";
  }
  return "?";
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
    case Stage::RayGen: return "rgen";
    case Stage::Intersection: return "rint";
    case Stage::AnyHit: return "rahit";
    case Stage::ClosestHit: return "rchit";
    case Stage::Miss: return "rmiss";
    case Stage::Callable: return "rcall";
    default: return "unknown";
  }
}

bool isRayTracing(Stage stage) {
  return stage == Stage::RayGen || stage == Stage::Intersection || stage == Stage::AnyHit ||
         stage == Stage::ClosestHit || stage == Stage::Miss || stage == Stage::Callable;
}

bool isPreRasterization(Stage stage) {
  return stage == Stage::Vertex || stage == Stage::TessControl || stage == Stage::TessEvaluation ||
         stage == Stage::Geometry || stage == Stage::Mesh;
}

bool vulkanGlslOutput(const SourceInfo& source, bool esOutput, std::optional<int> targetVersion) {
  const bool sameDialect = source.language == SourceLanguage::Glsl && esOutput == source.es;
  if (!source.vulkan || !(sameDialect || source.language != SourceLanguage::Glsl)) return false;
  if (!targetVersion) return true;
  if (sameDialect && *targetVersion >= source.version) return true;
  return *targetVersion >= (esOutput ? 310 : 430);
}

bool glslHasInverse(int version, bool es) { return version >= (es ? 300 : 150); }

}  // namespace stereoshift
