// Accuracy by execution on the corpus: every GLSL (330, ES 300, Vulkan 450) and HLSL pipeline whose last
// pre-rasterization stage gets the shift is run on lavapipe, original against transpiled, with
// eyeSign = 0 (bit-exact mono identity), -1 and +1 (stereo error against the double reference).
#include "transpiler/verify/stereo_verify.h"
#include "test/harness/vulkan_suite.h"
#include "transpiler/stereoshift.h"
#include "transpiler/source/file_io.h"
#include "transpiler/source/stage_rules.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace fs = std::filesystem;
using namespace stereoshift;
using namespace stereoshift::harness;

namespace {

// Known limitations, each asserted to still fail (like lit's XFAIL): when one is fixed, this test
// fails until the entry is removed.
const std::map<std::string, std::string> kKnownLimitations = {};

struct PipelineCase {
  std::string name;
  std::vector<fs::path> stages;  // pre-rasterization stages, in pipeline order
};

std::vector<PipelineCase> corpusPipelines() {
  std::map<std::string, std::vector<fs::path>> groups;
  for (const char* dialect : {"gl330", "es300", "vk450", "hlsl"})
    for (auto& e : fs::directory_iterator(fs::path(CORPUS_DIR) / dialect)) {
      if (!e.is_regular_file()) continue;
      auto stage = stageFromPath(e.path().string());
      if (!stage || !isPreRasterization(*stage)) continue;
      groups[pipelineKey(e.path().string())].push_back(e.path());
    }
  auto order = [](const fs::path& p) { return static_cast<int>(*stageFromPath(p.string())); };
  std::vector<PipelineCase> cases;
  for (auto& [key, stages] : groups) {
    std::sort(stages.begin(), stages.end(), [&](auto& a, auto& b) { return order(a) < order(b); });
    cases.push_back({fs::relative(key, CORPUS_DIR).string(), stages});
  }
  return cases;
}

class CorpusExecution : public VulkanSuite<::testing::TestWithParam<PipelineCase>> {};

TEST_P(CorpusExecution, StereoMatchesReference) {
  ASSERT_TRUE(context_) << "no Vulkan device: " << setupError_;
  const PipelineCase& c = GetParam();
  std::vector<SourceFile> sources;
  for (const auto& p : c.stages) {
    sources.push_back({p.string(), {}});
    ASSERT_TRUE(readFile(p.string(), &sources.back().contents)) << p;
  }
  TranspileOptions options;
  options.includeDirs = {(c.stages.front().parent_path() / "include").string()};
  std::vector<StageModules> stages;
  std::string lastClassification;
  Diagnostics diags;
  ASSERT_TRUE(buildStageModules(sources, options, &stages, &lastClassification, diags)) << diags.format();
  if (lastClassification != "perspective") GTEST_SKIP() << c.name << " needs no shift (" << lastClassification << ")";
  VerifySettings settings;
  VerifyResult r = verifyStereo(*context_, stages, settings);
  if (!r.error.empty() && r.error.find("harness cannot") != std::string::npos) GTEST_SKIP() << r.error;
  ASSERT_TRUE(r.error.empty()) << c.name << ": " << r.error;
  std::cout << "[verify] " << c.name << ": vertices " << r.vertices << ", mono identical " << r.monoIdentical
            << ", max stereo error " << r.maxStereoUlps << " ULP, cutoff vertices " << r.cutoffVertices << "\n";
  if (auto known = kKnownLimitations.find(c.name); known != kKnownLimitations.end()) {
    EXPECT_FALSE(r.ok) << c.name << " now verifies: remove it from kKnownLimitations (" << known->second << ")";
    EXPECT_TRUE(r.monoIdentical) << c.name;
    std::cout << "[verify] " << c.name << ": known limitation, still failing as expected: " << known->second << "\n";
    return;
  }
  EXPECT_GT(r.vertices, 0u);
  EXPECT_TRUE(r.monoIdentical) << c.name;
  EXPECT_TRUE(r.otherOutputsUnchanged) << c.name << ": " << (r.problems.empty() ? "" : r.problems.front());
  EXPECT_LE(r.maxStereoUlps, settings.maxUlps) << c.name;

  // --compensated-shift: the same pipeline within the 1 ULP bound.
  TranspileOptions compensated = options;
  compensated.compensatedShift = true;
  std::vector<StageModules> precise;
  ASSERT_TRUE(buildStageModules(sources, compensated, &precise, &lastClassification, diags)) << diags.format();
  VerifySettings tight;
  tight.maxUlps = 1.0;  // one final rounding of a nearly exact sum: 0.5 ulp(x') <= 1 ULP of max
  VerifyResult rc = verifyStereo(*context_, precise, tight);
  ASSERT_TRUE(rc.error.empty()) << c.name << ": " << rc.error;
  std::cout << "[verify] " << c.name << " compensated: max stereo error " << rc.maxStereoUlps << " ULP\n";
  EXPECT_TRUE(rc.monoIdentical) << c.name;
  EXPECT_LE(rc.maxStereoUlps, 1.0) << c.name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusExecution, ::testing::ValuesIn(corpusPipelines()),
                         [](const ::testing::TestParamInfo<PipelineCase>& info) {
                           std::string n = info.param.name;
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

}  // namespace
