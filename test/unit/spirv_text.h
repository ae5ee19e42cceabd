// The IR tests' one helper: SPIR-V assembly text as a parsed module; a text that does not assemble
// or parse fails the calling test.
#pragma once

#include "passes/ir/module.h"

#include <gtest/gtest.h>

#include <string>

namespace stereoshift::spirv::test {

inline Module parseOrDie(const char* text) {
  std::string error;
  auto words = assemble(text, &error);
  EXPECT_FALSE(words.empty()) << error;
  auto m = Module::parse(words, &error);
  EXPECT_TRUE(m.has_value()) << error;
  return std::move(*m);
}

}  // namespace stereoshift::spirv::test
