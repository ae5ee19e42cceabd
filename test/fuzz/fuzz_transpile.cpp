// libFuzzer target: this turns an arbitrary byte string into one call of stereoshift::transpile, the
// library's whole conversion (front end, passes, back end), for one input language. Built three
// times (test/fuzz/CMakeLists.txt) with FUZZ_INPUT_LANGUAGE set to 0 (GLSL), 1 (HLSL) or 2 (SPIR-V).
//
// Input layout (make_seeds.py writes the seed corpus in it):
//   byte 0   conversion options (see optionsFromByte): target language, eye source, shift form, ...
//   byte 1   the stage, for GLSL and HLSL: it names the file (fuzz.vert / fuzz.vert.hlsl), as the tool
//            takes the stage from the extension; ignored for SPIR-V, whose module names its stage
//   rest     the shader: source text, or the SPIR-V binary
// A crash, an ASan/UBSan report or a broken promise of the API (below) is a finding.
#include "transpiler/stereoshift.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#ifndef FUZZ_INPUT_LANGUAGE
#error "FUZZ_INPUT_LANGUAGE must be 0 (GLSL), 1 (HLSL) or 2 (SPIR-V)"
#endif

namespace {

using namespace stereoshift;

// The options byte: every output language and eye source, and the switches that change which
// passes run or which maths they insert, so mutating one byte walks the back ends and the passes.
TranspileOptions optionsFromByte(uint8_t bits) {
  static constexpr TargetLanguage targets[] = {TargetLanguage::Auto, TargetLanguage::Glsl, TargetLanguage::Essl,
                                               TargetLanguage::Hlsl, TargetLanguage::Msl,  TargetLanguage::Spirv,
                                               TargetLanguage::SpirvAsm, TargetLanguage::Auto};
  static constexpr EyeSource sources[] = {EyeSource::Auto,         EyeSource::UniformBlock,  EyeSource::PushConstant,
                                          EyeSource::SpecConstant, EyeSource::LooseUniforms, EyeSource::Auto,
                                          EyeSource::UniformBlock, EyeSource::Auto};
  TranspileOptions options;
  options.target = targets[bits & 7];
  options.eye.source = sources[(bits >> 3) & 7];
  if (bits & 0x40) options.shiftForm = ShiftForm::Select;
  if (bits & 0x80) {
    // The less travelled maths: exact cutoff, compensated shift, HUD at depth, per-eye specular.
    options.cutoff = CutoffMode::Exact;
    options.compensatedShift = true;
    options.hudAtDepth = true;
    options.perEyeSpecular = true;
  }
  return options;
}

std::string fileNameForStage(uint8_t selector) {
  static const char* const extensions[] = {"vert", "tesc", "tese", "geom", "frag", "comp", "task", "mesh"};
  std::string name = std::string("fuzz.") + extensions[selector % 8];
  if (FUZZ_INPUT_LANGUAGE == 1) name += ".hlsl";
  if (FUZZ_INPUT_LANGUAGE == 2) name = "fuzz.spv";
  return name;
}

[[noreturn]] void brokenPromise(const char* what, const TranspileResult& result) {
  std::fprintf(stderr, "fuzz_transpile: %s\n%s\n", what, result.diagnostics.format().c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  SourceFile input;
  input.path = fileNameForStage(data[1]);
  input.contents.assign(reinterpret_cast<const char*>(data) + 2, size - 2);
  TranspileResult result = transpile(input, optionsFromByte(data[0]));

  // What callers rely on: a failed conversion says why; a successful one has no error among its
  // diagnostics; a binary output is whole SPIR-V words.
  if (!result.ok && !result.diagnostics.hasErrors()) brokenPromise("conversion failed without an error", result);
  if (result.ok && result.diagnostics.hasErrors()) brokenPromise("conversion succeeded with an error", result);
  if (result.ok && result.binaryOutput && result.output.size() % 4 != 0)
    brokenPromise("binary output is not a whole number of SPIR-V words", result);
  return 0;
}
