// Run time against error, side by side in one run: for each option that trades speed or code size
// for accuracy, the transpile time per shader, the injected instruction count and the stereo error
// measured on lavapipe (corpus pipelines + the stress sweep of test/harness/stress_test.cpp).
//
//   build/bench/stereoshift_bench [--reps N]
#include "transpiler/verify/stereo_verify.h"
#include "passes/ir/module.h"
#include "transpiler/source/file_io.h"
#include "transpiler/source/stage_rules.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace fs = std::filesystem;
using namespace stereoshift;
using namespace stereoshift::harness;

namespace {

size_t instructionCount(const std::vector<uint32_t>& words) {
  std::string error;
  auto m = spirv::Module::parse(words, &error);
  if (!m) return 0;
  size_t n = 0;
  for (const auto& fn : m->functions)
    for (const auto& b : fn.blocks) n += b.instructions.size() + 1;
  return n;
}

struct Config {
  const char* name;
  TranspileOptions options;
};

}  // namespace

int main(int argc, char** argv) {
  int reps = 20;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--reps") == 0) reps = std::atoi(argv[i + 1]);

  std::vector<Config> configs;
  auto add = [&](const char* name, auto tweak) {
    TranspileOptions o;
    tweak(o);
    configs.push_back({name, o});
  };
  add("default (branch, eps 1e-5, invariant)", [](TranspileOptions&) {});
  add("exact cutoff (w != 1)", [](TranspileOptions& o) { o.cutoff = CutoffMode::Exact; });
  add("no cutoff", [](TranspileOptions& o) { o.cutoff = CutoffMode::None; });
  add("select (branch-free)", [](TranspileOptions& o) { o.shiftForm = ShiftForm::Select; });
  add("fused multiply-add", [](TranspileOptions& o) { o.fusedShift = true; });
  add("compensated (error-free transformations)", [](TranspileOptions& o) { o.compensatedShift = true; });
  add("no invariant / NoContraction", [](TranspileOptions& o) { o.invariantPosition = false; });
  add("push constants", [](TranspileOptions& o) { o.eye.source = EyeSource::PushConstant; });
  add("spec constants", [](TranspileOptions& o) { o.eye.source = EyeSource::SpecConstant; });

  // Vulkan GLSL pipelines of the corpus (push constants need Vulkan), grouped by base name.
  std::map<std::string, std::vector<SourceFile>> pipelines;
  for (auto& e : fs::directory_iterator(fs::path(CORPUS_DIR) / "vk450")) {
    auto stage = stageFromPath(e.path().string());
    if (!stage || !isPreRasterization(*stage)) continue;
    SourceFile source{e.path().string(), {}};
    if (!readFile(source.path, &source.contents)) continue;
    pipelines[pipelineKey(source.path)].push_back(std::move(source));
  }
  std::string error;
  auto context = VulkanContext::create(&error);
  if (!context) {
    std::fprintf(stderr, "no Vulkan device: %s\n", error.c_str());
    return 1;
  }
  // Warm-up: glslang's first compile builds its symbol tables; keep that out of every row.
  for (auto& [name, sources] : pipelines)
    for (const auto& source : sources) {
      TranspileOptions o;
      o.includeDirs = {(fs::path(CORPUS_DIR) / "vk450" / "include").string()};
      transpile(source, o);
    }
  std::printf("| configuration | transpile ms/shader | injected instructions (mean) | max stereo error, corpus (ULP) | mono identity |\n");
  std::printf("| --- | ---: | ---: | ---: | --- |\n");
  int failures = 0;
  for (const auto& config : configs) {
    double ms = 0, injected = 0, worst = 0;
    int shaders = 0, pipelinesRun = 0;
    bool mono = true;
    for (auto& [name, sources] : pipelines) {
      TranspileOptions o = config.options;
      o.includeDirs = {(fs::path(CORPUS_DIR) / "vk450" / "include").string()};
      std::vector<StageModules> stages;
      std::string classification;
      Diagnostics diags;
      if (!buildStageModules(sources, o, &stages, &classification, diags) || classification != "perspective") continue;
      // Transpile time of the shifted stage, the option's own cost.
      const SourceFile& last = *std::find_if(sources.begin(), sources.end(), [&](const SourceFile& s) {
        return s.path.find(".vert") == std::string::npos || sources.size() == 1;
      });
      auto t0 = std::chrono::steady_clock::now();
      for (int r = 0; r < reps; ++r) {
        TranspileOptions timed = o;
        timed.target = TargetLanguage::Spirv;
        timed.forceReemit = true;
        auto result = transpile(last, timed);
        if (!result.ok) break;
      }
      ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / reps;
      ++shaders;
      injected += double(instructionCount(stages.back().transpiled)) - double(instructionCount(stages.back().original));
      VerifySettings s;
      s.cutoff = o.cutoff;
      s.cutoffEpsilon = o.cutoffEpsilon;
      VerifyResult r = verifyStereo(*context, stages, s);
      if (!r.error.empty()) continue;
      ++pipelinesRun;
      worst = std::max(worst, r.maxStereoUlps);
      mono &= r.monoIdentical;
    }
    failures += mono ? 0 : 1;
    std::printf("| %s | %.2f | %.1f | %.2f (%d pipelines) | %s |\n", config.name, shaders ? ms / shaders : 0.0,
                shaders ? injected / shaders : 0.0, worst, pipelinesRun, mono ? "bit-exact" : "DIFFERS");
  }
  return failures ? 1 : 0;
}
