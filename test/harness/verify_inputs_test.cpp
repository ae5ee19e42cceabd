// `verify` on shaders written the way public samples write them, one per resource family, vertex
// input shape and stage combination the harness feeds (test/harness/shaders/verify/): each must
// run on lavapipe — original against transpiled — and verify, with the shift actually exercised
// (vertices beyond the cutoff). Plus the data check: a shadow-map coordinate computed with its own
// matrix must not look like an unshifted copy of the position.
#include "transpiler/verify/stereo_verify.h"
#include "test/harness/vulkan_suite.h"
#include "transpiler/stereoshift.h"
#include "transpiler/source/file_io.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace stereoshift;
using namespace stereoshift::harness;

namespace {

class VerifyInputs : public VulkanSuite<> {
 protected:
  // Builds the given shaders (pipeline order) and runs verify on them.
  VerifyResult verify(const std::vector<std::string>& files, const TranspileOptions& options = {}) {
    std::vector<SourceFile> sources;
    for (const auto& f : files) {
      sources.push_back({std::string(VERIFY_SHADER_DIR) + "/" + f, {}});
      EXPECT_TRUE(readFile(sources.back().path, &sources.back().contents)) << f;
    }
    std::vector<StageModules> stages;
    std::string classification;
    Diagnostics diags;
    VerifyResult failed;
    if (!buildStageModules(sources, options, &stages, &classification, diags)) {
      failed.error = "does not build: " + diags.format();
      return failed;
    }
    EXPECT_EQ(classification, "perspective") << files.back();
    return verifyStereo(*context_, stages, VerifySettings{});
  }

  void expectVerified(const VerifyResult& r, const std::string& what) {
    ASSERT_TRUE(r.error.empty()) << what << ": " << r.error;
    EXPECT_TRUE(r.ok) << what << ": " << (r.problems.empty() ? "" : r.problems.front());
    EXPECT_TRUE(r.monoIdentical) << what;
    EXPECT_GT(r.vertices, 0u) << what;
    EXPECT_LT(r.cutoffVertices, r.vertices) << what << ": the cutoff kept every vertex, the shift was never checked";
  }

  void SetUp() override {
    if (!context_) {
      if (HARNESS_REQUIRE_VULKAN) FAIL() << "no Vulkan device: " << setupError_;
      GTEST_SKIP() << "no Vulkan device: " << setupError_;
    }
  }
};

// sampler2DArray, samplerCube, sampler3D and an integer usampler2D, in two descriptor sets.
TEST_F(VerifyInputs, TextureArraysCubesVolumesAndIntegerTextures) {
  expectVerified(verify({"texture_kinds.vert"}), "texture_kinds.vert");
}

// HLSL Texture2D / SamplerState apart (two bindings) and together (one binding), Texture2DArray.
TEST_F(VerifyInputs, SeparateTexturesAndSamplersHlsl) {
  expectVerified(verify({"separate_samplers.vert.hlsl"}), "separate_samplers.vert.hlsl");
}

// A readonly std430 buffer of per-instance structs and storage images of two formats.
TEST_F(VerifyInputs, StorageBuffersAndImages) {
  expectVerified(verify({"storage_resources.vert"}), "storage_resources.vert");
}

// uniform Light { ... } lights[3], sampler2D detailMaps[2], samplerBuffer.
TEST_F(VerifyInputs, DescriptorArraysAndTexelBuffers) {
  VerifyResult r = verify({"descriptor_arrays.vert"});
  expectVerified(r, "descriptor_arrays.vert");
}

// ivec4, uvec2, mat4 (four locations), float[4] (four locations), dvec3.
TEST_F(VerifyInputs, IntegerMatrixArrayAndDoubleVertexInputs) {
  expectVerified(verify({"vertex_input_types.vert"}), "vertex_input_types.vert");
}

// A lone OpenGL 3.3 geometry shader (points in, loose uniforms) behind a synthesized vertex stage.
TEST_F(VerifyInputs, LoneGeometryShaderGetsAVertexStage) {
  VerifyResult r = verify({"billboard.geom"});
  expectVerified(r, "billboard.geom");
  ASSERT_EQ(r.synthesizedStages.size(), 1u);
  EXPECT_EQ(r.synthesizedStages[0], "vertex (synthesized pass-through)");
}

// A lone tessellation-evaluation shader with per-vertex and patch inputs behind synthesized
// vertex and tessellation-control stages.
TEST_F(VerifyInputs, LoneTessEvaluationShaderGetsVertexAndControlStages) {
  VerifyResult r = verify({"pn_patch.tese"});
  expectVerified(r, "pn_patch.tese");
  ASSERT_EQ(r.synthesizedStages.size(), 2u);
  EXPECT_EQ(r.synthesizedStages[1], "tessellation-control (synthesized pass-through)");
}

// 516 bytes of push constants: over lavapipe's limit, so bound as a uniform buffer.
TEST_F(VerifyInputs, PushConstantsOverTheDeviceLimit) {
  const uint32_t limit = context_->properties().limits.maxPushConstantsSize;
  if (limit >= 516) GTEST_SKIP() << "this device takes " << limit << " bytes of push constants";
  VerifyResult r = verify({"big_push_constants.vert"});
  expectVerified(r, "big_push_constants.vert");
  EXPECT_TRUE(r.pushConstantsAsBuffer);
}

// MVP and DepthBiasMVP are different uniforms: ShadowCoord differs from the position, so it is
// neither a stale copy (halo) nor re-derived, and stays the same for both eyes.
TEST_F(VerifyInputs, ShadowCoordinateIsNotReportedAsAHalo) {
  VerifyResult r = verify({"shadow_coord.vert"});
  expectVerified(r, "shadow_coord.vert");
  EXPECT_TRUE(r.otherOutputsUnchanged);
  EXPECT_EQ(r.haloComponentsChanged, 0u);
  for (const auto& p : r.problems) EXPECT_EQ(p.find("halo"), std::string::npos) << p;
}

// D3D registers: b0, t0 and s0 are three namespaces that glslang maps onto one binding; verify
// moves each register class to its own binding range (original and transpiled alike), register
// spaces becoming descriptor sets. Both shaders were refused before ("shares its binding").
TEST_F(VerifyInputs, D3dRegisterClassesAreBoundApart) {
  for (const char* file : {"d3d_registers.vert.hlsl", "cbuffer_spaces_skinned.vert.hlsl"}) expectVerified(verify({file}), file);
}

// OpenGL binding points: a texture unit, a uniform block and a storage block numbered 0 each are
// three resources, which glslang leaves at one Vulkan binding; verify moves each class to its own
// range (original and transpiled alike), as for D3D registers. Both were refused before ("shares
// its binding"): one taken as OpenGL GLSL (a loose uniform), one glslang also accepts as Vulkan GLSL.
TEST_F(VerifyInputs, OpenGLBindingClassesAreBoundApart) {
  for (const char* file : {"particle_binding_points.vert", "terrain_binding_points.vert"}) expectVerified(verify({file}), file);
}

// Loose dmat4 / dvec3 uniforms: std140 gives them 8-byte scalars and 32-byte dvec4 columns. The
// harness's default block laid them out as floats (16-byte columns), so the matrices overlapped and
// the eye parameters appended in the transpiled copy overwrote the projection: eyeSign 0 differed.
TEST_F(VerifyInputs, DoublePrecisionLooseUniforms) {
  VerifyResult r = verify({"double_precision_camera.vert"});
  expectVerified(r, "double_precision_camera.vert");
  // The fp32 bound, with the reason it applies to a shader computing in fp64 (docs/stereo-math.md).
  EXPECT_NE(r.boundBasis.find("computes in fp64"), std::string::npos) << r.boundBasis;
}

// An OpenGL `uniform bool` toggle: glslang's SPIR-V for it does not validate (a Bool variable in
// UniformConstant storage), so verify refused the shader. The harness stores it in the default
// block as a uint and compares its loads with 0, in the original and the transpiled module alike.
TEST_F(VerifyInputs, OpenGLUniformBoolIsStoredAsUint) {
  expectVerified(verify({"flip_y_toggle.vert"}), "flip_y_toggle.vert");
}

// Pre-rasterization shaders in tutorial / SDK conventions: skinning with integer bone ids,
// instancing with a mat4 attribute, a lone tessellated-terrain evaluation stage with a height map,
// geometry billboards and a one-pass shadow cube map (gl_Layer).
TEST_F(VerifyInputs, TutorialAndSampleConventions) {
  for (const char* file : {"skinned_mesh.vert", "instanced_asteroids.vert", "terrain_heightmap.tese",
                           "sprite_billboards.geom", "shadow_cubemap.geom"})
    expectVerified(verify({file}), file);
}

// Memory reached through buffer device addresses: pointers held in the push constants and a 64-bit
// address cast in the code each get a buffer of generated data (before, the draw read wild memory).
TEST_F(VerifyInputs, BufferDeviceAddresses) {
  for (const char* file : {"buffer_reference_mesh.vert", "buffer_address_camera.vert"})
    expectVerified(verify({file}), file);
}

// WebGL1 code with no #version or precision statement that writes ESSL 3's `transpose` itself and
// builds a matrix from a matrix: ESSL 100, analysed with its helper named apart.
TEST_F(VerifyInputs, WebGL1MatrixHelpers) {
  expectVerified(verify({"webgl1_matrix_helpers.vert"}), "webgl1_matrix_helpers.vert");
}

// Halo by value on the driver: outputs that recompute the clip position (inline and through a
// helper) and a position read back from its varying (a mirror's projective lookup) carry, per eye
// and vertex, bit for bit the shifted x of gl_Position (verify compares each copy with the captured
// position). With the halo pass off the same shaders fail as stale copies: the check can fail.
TEST_F(VerifyInputs, RecomputedAndReadBackPositionsCarryTheShift) {
  for (const auto& [file, copies] : std::vector<std::pair<std::string, uint32_t>>{{"halo_recomputed.vert", 2},
                                                                                {"halo_read_back.vert", 1}}) {
    VerifyResult r = verify({file});
    expectVerified(r, file);
    // Each copy's x moved in both eyes on every vertex past the cutoff, and only those components.
    EXPECT_EQ(r.haloComponentsChanged, 2 * copies * (r.vertices - r.cutoffVertices)) << file;
    TranspileOptions noHalo;
    noHalo.haloFix = false;
    VerifyResult mono = verify({file}, noHalo);
    ASSERT_TRUE(mono.error.empty()) << file << ": " << mono.error;
    EXPECT_FALSE(mono.ok) << file << ": a mono copy of the position went unnoticed";
    ASSERT_FALSE(mono.problems.empty()) << file;
    EXPECT_NE(mono.problems.front().find("halo"), std::string::npos) << mono.problems.front();
  }
}

}  // namespace
