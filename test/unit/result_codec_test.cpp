// cli/result_codec: every message the CLI's processes hand each other survives the trip with every
// field it carries, binary bytes included, and a message cut short or of another kind is refused.
#include "cli/result_codec.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace stereoshift {
namespace {

using namespace std::string_literals;

// Bytes no text codec would carry as they are: NULs, a high byte, a CR/LF pair, a length-like prefix.
const std::string kBinary = "\x03\x02\x23\x07\0\0\0\0\xff\r\n"s + std::string(8, '\0') + "tail";

TEST(ResultCodec, StringsRoundTripAndRefuseATruncatedWire) {
  std::string wire;
  putString(wire, "");
  putString(wire, kBinary);
  size_t at = 0;
  std::string a = "not cleared", b;
  ASSERT_TRUE(getString(wire, at, &a));
  ASSERT_TRUE(getString(wire, at, &b));
  EXPECT_EQ(a, "");
  EXPECT_EQ(b, kBinary);
  EXPECT_EQ(at, wire.size());
  EXPECT_FALSE(getString(wire, at, &a));  // nothing left
  for (size_t cut = 1; cut < wire.size(); ++cut) {
    std::string shorter = wire.substr(0, wire.size() - cut), x, y;
    size_t from = 0;
    EXPECT_FALSE(getString(shorter, from, &x) && getString(shorter, from, &y)) << "cut " << cut;
  }
}

TEST(ResultCodec, ConversionRunKeepsEveryField) {
  ConversionRun run;
  run.errors = 3;
  run.outputs = {{"out/a.spv", kBinary}, {"-", "void main() {}\n"}, {"", ""}};
  run.hasReport = true;
  run.report = {{"ok", false}, {"passes", {{"halo", {{"shifted_outputs", {"vPos"}}}}}}, {"classification", "perspective"}};
  run.depfileText = "out/a.spv: \\\n  a\\ b.vert\n";
  ConversionRun back;
  ASSERT_TRUE(decodeConversionRun(encodeConversionRun(run), &back));
  EXPECT_EQ(back.errors, 3);
  ASSERT_EQ(back.outputs.size(), 3u);
  for (size_t i = 0; i < run.outputs.size(); ++i) {
    EXPECT_EQ(back.outputs[i].path, run.outputs[i].path);
    EXPECT_EQ(back.outputs[i].bytes, run.outputs[i].bytes);
  }
  EXPECT_TRUE(back.hasReport);
  EXPECT_EQ(back.report, run.report);
  EXPECT_EQ(back.depfileText, run.depfileText);

  ConversionRun noReport;
  noReport.errors = 0;
  ASSERT_TRUE(decodeConversionRun(encodeConversionRun(noReport), &back));
  EXPECT_FALSE(back.hasReport);
  EXPECT_EQ(back.errors, 0);
  EXPECT_TRUE(back.outputs.empty());
  EXPECT_TRUE(back.depfileText.empty());

  const std::string wire = encodeConversionRun(run);
  EXPECT_FALSE(decodeConversionRun(wire.substr(0, wire.size() - 1), &back));  // the last output cut short
}

TEST(ResultCodec, JobResultKeepsEveryFieldOnTheWire) {
  JobResult r;
  r.errors = 2;
  r.log = "a.vert:1:2: error: x\n";
  r.reports = nlohmann::json::array({{{"ok", true}, {"file", "a.vert"}}, {{"ok", false}}});
  r.outputs = {kBinary, "", "#version 450\n"};
  r.dependencies = {"a.vert", "include/common.glsl"};
  r.key = "0123abcd";
  r.replayable = false;
  JobResult back;
  back.replayable = true;
  ASSERT_TRUE(decodeJobResult(encodeJobResult(r), &back));
  EXPECT_EQ(back.errors, 2);
  EXPECT_EQ(back.log, r.log);
  EXPECT_EQ(back.reports, r.reports);
  EXPECT_EQ(back.outputs, r.outputs);
  EXPECT_EQ(back.dependencies, r.dependencies);
  EXPECT_EQ(back.key, r.key);
  EXPECT_FALSE(back.replayable);
  r.replayable = true;
  ASSERT_TRUE(decodeJobResult(encodeJobResult(r), &back));
  EXPECT_TRUE(back.replayable);

  // Up-to-date jobs' fields are not sent: no worker converts such a job.
  r.reportTexts = {"{}"};
  r.reportFacts = {{true, "perspective"}};
  JobResult fresh;
  ASSERT_TRUE(decodeJobResult(encodeJobResult(r), &fresh));
  EXPECT_TRUE(fresh.reportTexts.empty());
  EXPECT_TRUE(fresh.reportFacts.empty());

  const std::string wire = encodeJobResult(r);
  EXPECT_FALSE(decodeJobResult(wire.substr(0, wire.size() - 2), &back));
  EXPECT_FALSE(decodeJobResult("", &back));
}

TEST(ResultCodec, ServiceRequestKeepsEveryField) {
  ServiceRequest r;
  r.identity = "00ff00ff00ff00ff";
  r.arguments = {"stereoshift", "a b.vert", "-o", "", kBinary};
  r.workingDirectory = "/work/dir with space";
  r.fileModeMask = 027;
  r.environment = {{"STEREOSHIFT_NO_FORK", "1"}, {"STEREOSHIFT_UNSET", std::nullopt}, {"STEREOSHIFT_EMPTY", ""}};
  r.standardInput = kBinary;
  ServiceRequest back;
  ASSERT_TRUE(decodeServiceRequest(encodeServiceRequest(r), &back));
  EXPECT_EQ(back.identity, r.identity);
  EXPECT_EQ(back.arguments, r.arguments);
  EXPECT_EQ(back.workingDirectory, r.workingDirectory);
  EXPECT_EQ(back.fileModeMask, 027u);
  EXPECT_EQ(back.environment, r.environment);
  EXPECT_EQ(back.standardInput, r.standardInput);

  r.standardInput.reset();
  ASSERT_TRUE(decodeServiceRequest(encodeServiceRequest(r), &back));
  EXPECT_FALSE(back.standardInput.has_value());

  const std::string wire = encodeServiceRequest(r);
  EXPECT_FALSE(decodeServiceRequest(wire + "x", &back));                      // trailing bytes
  EXPECT_FALSE(decodeServiceRequest(wire.substr(0, wire.size() - 1), &back));  // cut short
  EXPECT_FALSE(decodeServiceRequest(encodeServiceAnswer(ServiceAnswer{}), &back));  // another message
}

TEST(ResultCodec, ServiceAnswerKeepsEveryField) {
  ServiceAnswer a;
  a.exitStatus = 2;
  a.standardOutput = kBinary;
  a.standardError = "stereoshift: error: x\n1 error generated.\n";
  ServiceAnswer back;
  ASSERT_TRUE(decodeServiceAnswer(encodeServiceAnswer(a), &back));
  EXPECT_EQ(back.exitStatus, 2);
  EXPECT_EQ(back.standardOutput, a.standardOutput);
  EXPECT_EQ(back.standardError, a.standardError);

  a.exitStatus = 256;  // not an exit status
  EXPECT_FALSE(decodeServiceAnswer(encodeServiceAnswer(a), &back));
  a.exitStatus = 0;
  const std::string wire = encodeServiceAnswer(a);
  EXPECT_FALSE(decodeServiceAnswer(wire + "x", &back));
  EXPECT_FALSE(decodeServiceAnswer(wire.substr(0, wire.size() - 1), &back));
}

TEST(ResultCodec, ConverterCommandLineAndReplyKeepEveryField) {
  const std::vector<std::string> args = {"stereoshift", "--timeout", "5", "", kBinary};
  EXPECT_EQ(decodeCommandLine(encodeCommandLine(args)), args);
  EXPECT_TRUE(decodeCommandLine(encodeCommandLine({})).empty());
  // The arguments before one cut short are kept.
  const std::string wire = encodeCommandLine(args);
  EXPECT_EQ(decodeCommandLine(wire.substr(0, wire.size() - 1)),
            std::vector<std::string>(args.begin(), args.end() - 1));

  int status = -1;
  std::string output;
  ASSERT_TRUE(decodeCommandReply(encodeCommandReply(1, kBinary), &status, &output));
  EXPECT_EQ(status, 1);
  EXPECT_EQ(output, kBinary);
  const std::string reply = encodeCommandReply(0, "done\n");
  EXPECT_FALSE(decodeCommandReply(reply.substr(0, reply.size() - 1), &status, &output));
}

}  // namespace
}  // namespace stereoshift
