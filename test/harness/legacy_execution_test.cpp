// Accuracy by execution of the legacy GLSL text route (ESSL 100, desktop 110-150): the *text* a user
// gets back (the original with `main` renamed and the shifting `main` appended) is compiled again by
// stereoshift's own front end (its ESSL 310 / GLSL 330 translation) and run on lavapipe against the
// original, with eyeSign = 0 (bit-exact mono identity), -1 and +1 (stereo error against the double
// reference). `stereoshift verify` checks the SPIR-V route; this checks the spliced text itself.
#include "transpiler/frontend/front_end.h"
#include "transpiler/stereoshift.h"
#include "transpiler/verify/stereo_verify.h"
#include "test/harness/vulkan_suite.h"
#include "transpiler/source/file_io.h"
#include "transpiler/source/stage_rules.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;
using namespace stereoshift;
using namespace stereoshift::harness;

namespace {

std::vector<std::string> legacyVertexShaders() {
  std::vector<std::string> paths;
  for (auto& e : fs::directory_iterator(fs::path(CORPUS_DIR) / "legacy-glsl"))
    if (e.is_regular_file() && stageFromPath(e.path().string()) == Stage::Vertex) paths.push_back(e.path().string());
  std::sort(paths.begin(), paths.end());
  return paths;
}

class LegacyTextExecution : public VulkanSuite<::testing::TestWithParam<std::string>> {};

TEST_P(LegacyTextExecution, SplicedTextMatchesReference) {
  ASSERT_TRUE(context_) << "no Vulkan device: " << setupError_;
  SourceFile input{GetParam(), {}};
  ASSERT_TRUE(readFile(input.path, &input.contents));
  // A pipeline's intermediate vertex stage is never shifted there (corpus header); on its own it would be.
  if (input.contents.find("stereoshift-expect: intermediate") != std::string::npos) GTEST_SKIP() << "intermediate stage";
  TranspileOptions options;
  TranspileResult converted = transpile(input, options);
  ASSERT_TRUE(converted.ok) << converted.diagnostics.format();
  if (converted.report.value("classification", "") != "perspective") GTEST_SKIP() << "needs no shift";
  ASSERT_EQ(converted.report.value("route", ""), "glsl-source-splice");

  // The emitted text, through the front end as an application's driver would get it.
  Diagnostics diags;
  FrontEndResult stereo = compileToSpirv(SourceFile{input.path, converted.output}, options, diags);
  ASSERT_TRUE(stereo.ok) << diags.format();
  StageModules stage;
  stage.stage = VK_SHADER_STAGE_VERTEX_BIT;
  stage.original = converted.originalSpirv;
  stage.transpiled = stereo.spirv;
  for (const auto& n : converted.report.value("halo_copies", nlohmann::json::array()))
    stage.haloOutputs.push_back(n.get<std::string>());
  VerifySettings settings;
  VerifyResult r = verifyStereo(*context_, {stage}, settings);
  if (!r.error.empty() && r.error.find("harness cannot") != std::string::npos) GTEST_SKIP() << r.error;
  ASSERT_TRUE(r.error.empty()) << r.error;
  std::cout << "[verify] " << fs::path(input.path).filename().string() << ": vertices " << r.vertices
            << ", mono identical " << r.monoIdentical << ", max stereo error " << r.maxStereoUlps
            << " ULP, cutoff vertices " << r.cutoffVertices << "\n";
  EXPECT_GT(r.vertices, 0u);
  EXPECT_TRUE(r.monoIdentical);
  EXPECT_TRUE(r.otherOutputsUnchanged) << (r.problems.empty() ? "" : r.problems.front());
  EXPECT_LE(r.maxStereoUlps, settings.maxUlps);
}

INSTANTIATE_TEST_SUITE_P(Corpus, LegacyTextExecution, ::testing::ValuesIn(legacyVertexShaders()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string n = fs::path(info.param).stem().string();
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

}  // namespace
