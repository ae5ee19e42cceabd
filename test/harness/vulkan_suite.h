// A GoogleTest fixture base for suites that run on lavapipe: one Vulkan context for the whole suite
// (creating one costs more than most of the tests), made before the first test and dropped after the
// last. When there is none, `context_` is null and `setupError_` says why; each suite decides where
// it checks that.
#pragma once

#include "transpiler/verify/vk_harness.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace stereoshift::harness {

template <class Base = ::testing::Test>
class VulkanSuite : public Base {
 protected:
  static void SetUpTestSuite() {
    std::string error;
    context_ = VulkanContext::create(&error);
    setupError_ = error;
  }
  static void TearDownTestSuite() { context_.reset(); }

  static inline std::unique_ptr<VulkanContext> context_;
  static inline std::string setupError_;
};

}  // namespace stereoshift::harness
