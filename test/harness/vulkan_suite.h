// A GoogleTest fixture base for suites that run on lavapipe: one Vulkan context for the whole suite
// (creating one costs more than most of the tests), made before the first test and dropped after the
// last. When there is none, `context_` is null and `setupError_` says why; each suite decides where
// it checks that.
#pragma once

#include "transpiler/verify/vk_harness.h"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

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

// Clip positions as vertex attribute 0 (vec4): a pass-through vertex shader (gl_Position = the
// attribute) then reaches the shift's guard with exactly these x and w (the numerical tests).
inline VertexBuffer clipVertices(const std::vector<std::array<float, 4>>& clips) {
  VertexBuffer vb;
  vb.stride = 16;
  vb.attributes = {{0, VK_FORMAT_R32G32B32A32_SFLOAT, 0}};
  vb.bytes.resize(clips.size() * 16);
  std::memcpy(vb.bytes.data(), clips.data(), vb.bytes.size());
  return vb;
}

}  // namespace stereoshift::harness
