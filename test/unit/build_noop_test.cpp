// The no-op record of `stereoshift build` (cli/build_noop.h): a rebuild replays it only where the
// key and every stamp are the recorded ones; an edit, a new or removed file, another key each make
// the rebuild plan again. The stamps are taken against the file system's clock, so an edit made
// right after the record (within the same clock tick as the files it recorded) is still seen.
#include "cli/build_noop.h"
#include "cli/output_commit.h"
#include "transpiler/source/file_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace stereoshift {
namespace {

class BuildNoop : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("stereoshift-noop-" + std::to_string(::getpid()) + "-" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_ / "src" / "sub");
    fs::create_directories(root_ / "out" / "sub");
    write(root_ / "src" / "scene.vert", "void main() {}\n");
    write(root_ / "src" / "sub" / "hud.vert", "void main() {}\n");
    write(root_ / "out" / "scene.vert", "converted\n");
    write(root_ / "out" / "sub" / "hud.vert", "converted\n");
    outcome_.reportPath = root_ / "out" / "stereoshift-report.json";
    outcome_.reportText = "{\"up_to_date\": 2}\n";
    outcome_.messages = "";
    dependencies_ = {(root_ / "src" / "scene.vert").string(), (root_ / "src" / "sub").string(),
                     (root_ / "src" / "sub" / "hud.vert").string()};
    recordNoop(root_ / "src", root_ / "out", "key", outcome_, dependencies_);
  }
  void TearDown() override { fs::remove_all(root_); }
  static void write(const fs::path& path, const std::string& text) { ASSERT_TRUE(writeAtomically(path, text)); }

  fs::path root_;
  NoopOutcome outcome_;
  std::vector<std::string> dependencies_;
};

TEST_F(BuildNoop, NothingChangedReplaysTheRecordedReport) {
  ASSERT_TRUE(replayNoop(root_ / "out", "key"));
  std::string report;
  ASSERT_TRUE(readFile(outcome_.reportPath.string(), &report));
  EXPECT_EQ(report, outcome_.reportText);
  EXPECT_TRUE(replayNoop(root_ / "out", "key"));  // the report it wrote is none of the stamps
}

TEST_F(BuildNoop, AnotherKeyPlans) { EXPECT_FALSE(replayNoop(root_ / "out", "other key")); }

TEST_F(BuildNoop, AnEditOfTheSameSizeRightAfterTheRecordPlans) {
  // In place (the same inode), as many bytes as before: only the times can tell.
  std::ofstream(root_ / "src" / "scene.vert", std::ios::binary | std::ios::trunc) << "void main() {}\r";
  EXPECT_FALSE(replayNoop(root_ / "out", "key"));
}

TEST_F(BuildNoop, ANewFileInASourceDirectoryPlans) {
  write(root_ / "src" / "sub" / "new.vert", "void main() {}\n");
  EXPECT_FALSE(replayNoop(root_ / "out", "key"));
}

TEST_F(BuildNoop, ANewFileAtTheSourceRootPlans) {
  write(root_ / "src" / "new.vert", "void main() {}\n");
  EXPECT_FALSE(replayNoop(root_ / "out", "key"));
}

TEST_F(BuildNoop, AnOutputRemovedOrEditedPlans) {
  fs::remove(root_ / "out" / "sub" / "hud.vert");
  EXPECT_FALSE(replayNoop(root_ / "out", "key"));
}

TEST_F(BuildNoop, AnOutputEditedPlans) {
  write(root_ / "out" / "scene.vert", "edited!!!\n");
  EXPECT_FALSE(replayNoop(root_ / "out", "key"));
}

TEST_F(BuildNoop, ForgottenRecordPlans) {
  forgetNoop(root_ / "out");
  EXPECT_FALSE(replayNoop(root_ / "out", "key"));
}

}  // namespace
}  // namespace stereoshift
