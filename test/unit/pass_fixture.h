// The single-pass test fixture (in the spirit of SPIRV-Tools' SinglePassRunAndCheck): SPIR-V
// assembly in, exactly one pass run through the pass manager (plus the passes it requires, as
// `--pass NAME` does), and the disassembly, the pass's Changed / Unchanged result, the report and
// the diagnostics out for the test to check (typed, and as the report renders them).
#pragma once

#include "passes/ir/module.h"
#include "passes/pass.h"
#include "transpiler/transpile_options.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace stereoshift::test {

struct SinglePassRun {
  bool ok = false;                   // the pipeline ran to the end (no pass failed)
  PassResult result = PassResult::Failed;  // what the named pass returned
  std::string disassembly;           // the module afterwards (friendly names)
  RunRecord record;                  // what each pass that ran did and found
  nlohmann::json report;             // the record as the report renders it: report["passes"][name]
  std::string diagnostics;           // every diagnostic, one per line
  std::vector<std::string> ran;      // the passes that ran, in the order they ran
};

// The options a test starts from: the tool's defaults, plus --validate-each (every changed module
// is validated, and every analysis a pass claims to preserve is checked).
TranspileOptions singlePassOptions();

// Assembles and parses `assembly` as a module of `spirvVersion` (the optimizer behind the analyses'
// folded copy takes SPIR-V 1.0); a module that does not assemble or parse fails the calling test.
std::optional<spirv::Module> assembleModule(const std::string& assembly, uint32_t spirvVersion = 0x00010000);

// Assembles `assembly` (a SPIR-V 1.0 module unless it says otherwise through `spirvVersion`) and runs
// `pass` on it with `options`. A module that does not assemble fails the calling test.
SinglePassRun runSinglePass(const std::string& assembly, const std::string& pass,
                            TranspileOptions options = singlePassOptions(), uint32_t spirvVersion = 0x00010000);

// Small modules several pass tests share (written by hand, in the style of test/lit/pass/). The
// values the tests look for carry an OpName: the disassembly numbers unnamed ids.
// A vertex shader writing `gl_PerVertex.gl_Position = camera.viewProj * vec4(inPosition, 1)`
// and, when `withCopy`, `vClip = gl_Position` read back from the position (a halo candidate).
std::string perspectiveVertexShader(bool withCopy);
// A vertex shader writing `gl_Position = vec4(inPosition, 0, 1)`: provably 2D (the literal w = 1).
std::string flatVertexShader();

// Whether each of `lines` occurs in `text`, in this order (each after the end of the previous match).
::testing::AssertionResult containsInOrder(const std::string& text, const std::vector<std::string>& lines);

}  // namespace stereoshift::test
