// Tests of the execution harness itself, on lavapipe. Each test asserts concrete values computed
// independently on the host; tolerances are stated next to each check.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>

#include "transpiler/verify/vk_harness.h"

using namespace stereoshift::harness;

namespace {

// ------------------------------------------------------------------------------------------------
// Helpers
// ------------------------------------------------------------------------------------------------

std::vector<uint32_t> spv(const std::string& name) {
  std::string err;
  std::vector<uint32_t> words = loadSpirv(std::string(HARNESS_SPV_DIR) + "/" + name + ".spv", &err);
  EXPECT_FALSE(words.empty()) << err;
  return words;
}

ShaderStage stage(VkShaderStageFlagBits s, const std::string& name) { return ShaderStage{s, spv(name), "main"}; }

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (auto& m : v) s += m + "\n";
  return s;
}

// Distance in units in the last place between two finite floats of the same sign region.
int64_t ulpDistance(float a, float b) {
  auto key = [](float f) {
    int32_t i;
    std::memcpy(&i, &f, 4);
    return i < 0 ? int64_t(int32_t(0x80000000u) - i) : int64_t(i);  // monotonic mapping
  };
  return std::llabs(key(a) - key(b));
}

struct Mat4 {
  double m[16];  // column-major: m[col * 4 + row], as GLSL / std140 store a mat4
  double at(int row, int col) const { return m[col * 4 + row]; }
};

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int c = 0; c < 4; ++c)
    for (int rr = 0; rr < 4; ++rr) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a.at(rr, k) * b.at(k, c);
      r.m[c * 4 + rr] = s;
    }
  return r;
}

// Minimal PNG reader for what encodePng writes (stored deflate blocks): verifies the signature,
// every chunk CRC, the zlib header and Adler-32, and returns the RGBA pixels.
uint32_t be32(const uint8_t* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }
uint32_t crc32Ref(const uint8_t* d, size_t n) {
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < n; ++i) {
    c ^= d[i];
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1)));
  }
  return ~c;
}
bool decodeStoredPng(const std::vector<uint8_t>& png, int* w, int* h, std::vector<uint8_t>* rgba, std::string* why) {
  static const uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (png.size() < 8 || std::memcmp(png.data(), sig, 8) != 0) return *why = "bad signature", false;
  size_t pos = 8;
  std::vector<uint8_t> idat;
  bool sawEnd = false;
  while (pos + 12 <= png.size()) {
    uint32_t len = be32(&png[pos]);
    if (pos + 12 + len > png.size()) return *why = "truncated chunk", false;
    std::string type(reinterpret_cast<const char*>(&png[pos + 4]), 4);
    if (crc32Ref(&png[pos + 4], len + 4) != be32(&png[pos + 8 + len])) return *why = "bad CRC in " + type, false;
    const uint8_t* d = &png[pos + 8];
    if (type == "IHDR") {
      *w = int(be32(d));
      *h = int(be32(d + 4));
      if (d[8] != 8 || d[9] != 6 || d[10] || d[11] || d[12]) return *why = "unexpected IHDR", false;
    } else if (type == "IDAT") {
      idat.insert(idat.end(), d, d + len);
    } else if (type == "IEND") {
      sawEnd = true;
    }
    pos += 12 + len;
  }
  if (!sawEnd || pos != png.size()) return *why = "missing IEND or trailing bytes", false;
  if (idat.size() < 6 || (idat[0] * 256 + idat[1]) % 31 != 0 || (idat[0] & 0x0F) != 8)
    return *why = "bad zlib header", false;
  std::vector<uint8_t> raw;
  size_t p = 2;
  for (bool last = false; !last;) {
    if (p + 5 > idat.size()) return *why = "truncated deflate", false;
    last = idat[p] & 1;
    if ((idat[p] >> 1) != 0) return *why = "non-stored deflate block", false;
    uint32_t n = idat[p + 1] | idat[p + 2] << 8, nn = idat[p + 3] | idat[p + 4] << 8;
    if ((n ^ 0xFFFF) != nn) return *why = "bad stored block length", false;
    p += 5;
    if (p + n > idat.size()) return *why = "truncated stored block", false;
    raw.insert(raw.end(), idat.begin() + long(p), idat.begin() + long(p + n));
    p += n;
  }
  uint32_t a = 1, b = 0;
  for (uint8_t byte : raw) a = (a + byte) % 65521, b = (b + a) % 65521;
  if (p + 4 != idat.size() || be32(&idat[p]) != ((b << 16) | a)) return *why = "bad Adler-32", false;
  size_t row = size_t(*w) * 4 + 1;
  if (raw.size() != row * size_t(*h)) return *why = "wrong image data size", false;
  rgba->clear();
  for (int y = 0; y < *h; ++y) {
    if (raw[y * row] != 0) return *why = "unexpected filter type", false;
    rgba->insert(rgba->end(), raw.begin() + long(y * row + 1), raw.begin() + long((y + 1) * row));
  }
  return true;
}

// ------------------------------------------------------------------------------------------------
// Fixture: one context per test process; skip only when no Vulkan device exists at all.
// ------------------------------------------------------------------------------------------------

class Harness : public ::testing::Test {
 protected:
  static std::unique_ptr<VulkanContext>& ctxPtr() {
    static std::unique_ptr<VulkanContext> c;
    return c;
  }
  static std::string& skipReason() {
    static std::string s;
    return s;
  }
  static std::string& createError() {
    static std::string s;
    return s;
  }
  static void SetUpTestSuite() {
    // The shared context validates whenever VK_LAYER_KHRONOS_validation is installed, unless the
    // caller chose otherwise (STEREOSHIFT_VK_VALIDATION=0); TearDown fails a test on any message.
    setenv("STEREOSHIFT_VK_VALIDATION", "auto", /*overwrite=*/0);
    std::string why;
    if (!VulkanContext::anyDeviceAvailable(&why)) {
      skipReason() = why;
      return;
    }
    ctxPtr() = VulkanContext::create(&createError());
  }
  static void TearDownTestSuite() { ctxPtr().reset(); }

  void SetUp() override {
    if (!skipReason().empty()) {
      const char* req = std::getenv("STEREOSHIFT_REQUIRE_VULKAN");
      if (HARNESS_REQUIRE_VULKAN || (req && std::string(req) == "1"))
        FAIL() << "Vulkan required (STEREOSHIFT_HARNESS_REQUIRE_VULKAN / STEREOSHIFT_REQUIRE_VULKAN) but unavailable: "
               << skipReason();
      GTEST_SKIP() << "no Vulkan device: " << skipReason();
    }
    ASSERT_NE(ctxPtr(), nullptr) << createError();
    ctxPtr()->clearValidationMessages();
  }
  void TearDown() override {
    if (ctxPtr()) {
      auto msgs = ctxPtr()->validationMessages();
      EXPECT_TRUE(msgs.empty()) << "validation layer messages:\n" << joined(msgs);
    }
  }
  VulkanContext& ctx() { return *ctxPtr(); }
};

// ------------------------------------------------------------------------------------------------
// No-device tests
// ------------------------------------------------------------------------------------------------

TEST(DescriptorLayout, GroupsBySetSortsBindingsAndRejectsDuplicates) {
  PipelineInputs in;
  in.uniformBuffers = {{2, 5, {1, 2, 3, 4}}, {0, 3, {1, 2, 3, 4}}, {2, 1, {1, 2, 3, 4}}};
  in.textures = {{0, 0, 1, 1, {0, 0, 0, 0}}};
  std::vector<std::vector<DescriptorSlot>> sets;
  std::string err;
  ASSERT_TRUE(buildDescriptorLayout(in, &sets, &err)) << err;
  ASSERT_EQ(sets.size(), 3u);
  ASSERT_EQ(sets[0].size(), 2u);
  EXPECT_EQ(sets[0][0].binding, 0u);
  EXPECT_EQ(sets[0][0].type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  EXPECT_EQ(sets[0][1].binding, 3u);
  EXPECT_EQ(sets[0][1].resourceIndex, 1u);
  EXPECT_TRUE(sets[1].empty());
  ASSERT_EQ(sets[2].size(), 2u);
  EXPECT_EQ(sets[2][0].binding, 1u);
  EXPECT_EQ(sets[2][0].resourceIndex, 2u);
  EXPECT_EQ(sets[2][1].binding, 5u);

  in.textures.push_back({2, 5, 1, 1, {0, 0, 0, 0}});
  EXPECT_FALSE(buildDescriptorLayout(in, &sets, &err));
  EXPECT_NE(err.find("duplicate descriptor (set 2, binding 5)"), std::string::npos) << err;
}

TEST(Png, RoundTripsThroughAStrictReader) {
  // 200x100 RGBA = 80,100 bytes of scanlines: two stored deflate blocks.
  const int w = 200, h = 100;
  std::vector<uint8_t> rgba(size_t(w) * h * 4);
  for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = uint8_t((i * 7919u) >> 3);
  std::vector<uint8_t> png = encodePng(w, h, rgba.data());
  int dw = 0, dh = 0;
  std::vector<uint8_t> back;
  std::string why;
  ASSERT_TRUE(decodeStoredPng(png, &dw, &dh, &back, &why)) << why;
  EXPECT_EQ(dw, w);
  EXPECT_EQ(dh, h);
  EXPECT_EQ(back, rgba);
  EXPECT_TRUE(encodePng(0, 4, rgba.data()).empty());
  EXPECT_FALSE(writePng("/nonexistent-dir/x.png", w, h, rgba.data()));
}

// ------------------------------------------------------------------------------------------------
// Context
// ------------------------------------------------------------------------------------------------

TEST_F(Harness, PicksTheCpuDeviceWithVulkan11) {
  if (!std::getenv("STEREOSHIFT_VK_DEVICE")) {
    EXPECT_EQ(ctx().deviceType(), VK_PHYSICAL_DEVICE_TYPE_CPU) << ctx().deviceName();
  }
  EXPECT_GE(ctx().apiVersion(), uint32_t(VK_API_VERSION_1_1));
  EXPECT_FALSE(ctx().deviceName().empty());
  EXPECT_NE(ctx().device(), VkDevice(VK_NULL_HANDLE));
  std::printf("device: %s, Vulkan %u.%u, validation %s\n", ctx().deviceName().c_str(),
              VK_API_VERSION_MAJOR(ctx().apiVersion()), VK_API_VERSION_MINOR(ctx().apiVersion()),
              ctx().validationEnabled() ? "on" : "off");
}

// A private context with validation when the layer is installed: a capture and a render, then
// destruction. The sink sees the messages emitted at vkDestroyDevice / vkDestroyInstance too, where
// the layer reports any object the harness forgot to destroy.
TEST_F(Harness, PrivateContextLifecycleIsCleanUnderValidation) {
  std::vector<std::string> messages;
  ContextOptions options;
  options.validation = Validation::IfAvailable;
  options.messageSink = [&](const std::string& m) { messages.push_back(m); };
  std::string err;
  {
    auto own = VulkanContext::create(&err, options);
    ASSERT_NE(own, nullptr) << err;
    std::printf("validation layer %s\n", own->validationEnabled() ? "enabled" : "not installed: skipped");
    CaptureRequest req;
    req.pipeline.stages = {stage(VK_SHADER_STAGE_VERTEX_BIT, "capture_push_spec.vert")};
    const std::vector<float> pos = {1, 2, 3, 1};
    req.pipeline.vertices = {toBytes(pos), 16, {{0, VK_FORMAT_R32G32B32A32_SFLOAT, 0}}};
    req.pipeline.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    req.pipeline.vertexCount = 1;
    req.pipeline.pushConstants.resize(32);
    req.xfbStride = 32;
    req.expectedVertices = 1;
    CaptureResult c = own->capture(req);
    ASSERT_TRUE(c.ok()) << c.error;
    EXPECT_EQ(c.f32(0, 2), 3.f);
    RenderRequest rr;
    rr.width = rr.height = 8;
    rr.readDepth = true;
    Draw d;
    d.pipeline.stages = {stage(VK_SHADER_STAGE_VERTEX_BIT, "render_solid.vert"),
                         stage(VK_SHADER_STAGE_FRAGMENT_BIT, "render_textured.frag")};
    const std::vector<float> tri = {-1, -1, 0.5f, 3, -1, 0.5f, -1, 3, 0.5f};
    d.pipeline.vertices = {toBytes(tri), 12, {{0, VK_FORMAT_R32G32B32_SFLOAT, 0}}};
    d.pipeline.vertexCount = 3;
    d.pipeline.textures = {{0, 0, 1, 1, {0.f, 1.f, 0.f, 1.f}}};
    d.pipeline.pushConstants.resize(16);
    const float rect[4] = {0, 0, 8, 8};
    std::memcpy(d.pipeline.pushConstants.data(), rect, 16);
    rr.draws = {d};
    RenderResult r = own->render(rr);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.pixel(3, 3)[1], 255);
    EXPECT_EQ(r.depthAt(3, 3), 0.5f);
  }
  EXPECT_TRUE(messages.empty()) << joined(messages);
}

// ------------------------------------------------------------------------------------------------
// Capture
// ------------------------------------------------------------------------------------------------

struct MvpVertex {
  float pos[3];
  float color[4];
};

CaptureRequest mvpRequest(const std::vector<MvpVertex>& verts, const float mvp[16], uint32_t capacity) {
  CaptureRequest req;
  PipelineInputs& p = req.pipeline;
  p.stages = {stage(VK_SHADER_STAGE_VERTEX_BIT, "capture_mvp.vert")};
  p.vertices.bytes = toBytes(verts);
  p.vertices.stride = sizeof(MvpVertex);
  p.vertices.attributes = {{0, VK_FORMAT_R32G32B32_SFLOAT, 0}, {1, VK_FORMAT_R32G32B32A32_SFLOAT, 12}};
  p.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  p.vertexCount = uint32_t(verts.size());
  p.uniformBuffers = {{0, 0, toBytes(mvp, 16)}};
  req.xfbStride = 32;
  req.expectedVertices = capacity;
  return req;
}

// All inputs are small dyadic rationals: every product and partial sum of mat4*vec4 is exactly
// representable in fp32, so the result is exact whatever the evaluation order or FMA contraction.
// Tolerance: bit-exact (compared with ==).
TEST_F(Harness, CaptureMvpIsExactForDyadicInputs) {
  const float mvp[16] = {0.5f,  0.25f, -1.f,  0.125f,  // column 0
                         -0.75f, 1.5f, 0.5f,  0.f,     // column 1
                         2.f,   -0.5f, 0.25f, 1.f,     // column 2
                         0.125f, 3.f,  -2.f,  4.f};    // column 3
  const std::vector<MvpVertex> verts = {
      {{1.f, -2.f, 0.5f}, {0.5f, 0.25f, 1.f, 0.75f}},     {{3.25f, 0.75f, -1.5f}, {0.f, 1.f, 0.125f, 1.f}},
      {{-4.f, 2.5f, 6.f}, {1.f, 0.5f, 0.25f, 0.f}},       {{0.375f, -0.625f, 2.f}, {0.75f, 0.75f, 0.5f, 0.5f}},
      {{10.f, 20.f, -30.f}, {0.0625f, 0.f, 1.f, 0.25f}},  {{-1.5f, -2.5f, -3.5f}, {1.f, 1.f, 1.f, 1.f}},
  };
  CaptureResult r = ctx().capture(mvpRequest(verts, mvp, 6));
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.bytes.size(), 6u * 32u);
  ASSERT_EQ(r.vertexCount(), 6u);
  EXPECT_EQ(r.primitivesWritten, 2u);
  EXPECT_EQ(r.primitivesNeeded, 2u);
  for (uint32_t v = 0; v < 6; ++v) {
    const double x[4] = {verts[v].pos[0], verts[v].pos[1], verts[v].pos[2], 1.0};
    for (int i = 0; i < 4; ++i) {
      double e = 0;
      for (int j = 0; j < 4; ++j) e += double(mvp[j * 4 + i]) * x[j];
      EXPECT_EQ(r.f32(v, i), float(e)) << "vertex " << v << " gl_Position[" << i << "]";
      ASSERT_EQ(double(float(e)), e) << "test data must be exactly representable";
      double c = double(verts[v].color[i]) * 2.0 + v;
      EXPECT_EQ(r.f32(v, 4 + i), float(c)) << "vertex " << v << " vColor[" << i << "]";
    }
  }
}

// A real perspective * view matrix and non-dyadic positions. Reference: the same fp32 inputs,
// evaluated in double. Tolerance: the rigorous fp32 dot-product bound
//   |got - exact| <= gamma_4 * sum_j |M_ij * x_j|,  gamma_4 = 4u / (1 - 4u), u = 2^-24,
// valid for any summation order with or without FMA (Vulkan: OpFMul/OpFAdd correctly rounded).
// Where there is no cancellation this is ~2 ulp of the result; it is reported in ulps too.
TEST_F(Harness, CaptureMvpPerspectiveWithinFp32DotProductBound) {
  const double pi = 3.14159265358979323846;
  const double fovy = 60.0 * pi / 180.0, aspect = 16.0 / 9.0, n = 0.1, f = 100.0;
  const double t = 1.0 / std::tan(fovy / 2);
  Mat4 P{};  // Vulkan clip: y down, z in [0, 1]
  P.m[0] = t / aspect;
  P.m[5] = -t;
  P.m[10] = f / (n - f);
  P.m[11] = -1.0;
  P.m[14] = n * f / (n - f);
  const double a = 0.3, c = std::cos(a), s = std::sin(a);
  Mat4 V{};  // rotation about y, then translation
  V.m[0] = c, V.m[2] = -s, V.m[5] = 1, V.m[8] = s, V.m[10] = c, V.m[15] = 1;
  V.m[12] = 0.7, V.m[13] = -1.3, V.m[14] = -4.2;
  Mat4 M = multiply(P, V);
  float mvp[16];
  for (int i = 0; i < 16; ++i) mvp[i] = float(M.m[i]);

  std::vector<MvpVertex> verts;
  uint32_t seed = 12345;
  auto rnd = [&](double lo, double hi) {
    seed = seed * 1664525u + 1013904223u;
    return float(lo + (hi - lo) * (seed >> 8) / double(1u << 24));
  };
  for (int v = 0; v < 6; ++v)
    verts.push_back({{rnd(-3, 3), rnd(-2, 2), rnd(-20, 2)}, {rnd(0, 1), rnd(0, 1), rnd(0, 1), rnd(0, 1)}});

  CaptureResult r = ctx().capture(mvpRequest(verts, mvp, 6));
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.vertexCount(), 6u);
  EXPECT_EQ(r.primitivesWritten, 2u);
  const double u = std::ldexp(1.0, -24), gamma4 = 4 * u / (1 - 4 * u);
  int64_t maxUlp = 0;
  for (uint32_t v = 0; v < 6; ++v) {
    const double x[4] = {verts[v].pos[0], verts[v].pos[1], verts[v].pos[2], 1.0};
    for (int i = 0; i < 4; ++i) {
      double e = 0, mag = 0;
      for (int j = 0; j < 4; ++j) {
        e += double(mvp[j * 4 + i]) * x[j];
        mag += std::fabs(double(mvp[j * 4 + i]) * x[j]);
      }
      const double bound = gamma4 * mag + 1e-15 * mag;  // + the double reference's own rounding
      const float got = r.f32(v, i);
      EXPECT_LE(std::fabs(double(got) - e), bound) << "vertex " << v << " component " << i;
      maxUlp = std::max(maxUlp, ulpDistance(got, float(e)));
    }
  }
  RecordProperty("max_ulp_vs_correctly_rounded", std::to_string(maxUlp));
  std::printf("perspective capture: max %lld ulp from the correctly rounded result\n", (long long)maxUlp);
}

// Capacity for 3 vertices, draw 6: the query must report 1 written of 2 needed primitives, and
// exactly 96 bytes must come back.
TEST_F(Harness, CaptureReportsOverflowThroughTheStreamQuery) {
  const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  std::vector<MvpVertex> verts;
  for (int v = 0; v < 6; ++v) verts.push_back({{float(v), 0, 0}, {0, 0, 0, 0}});
  CaptureResult r = ctx().capture(mvpRequest(verts, identity, 3));
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.primitivesWritten, 1u);
  EXPECT_EQ(r.primitivesNeeded, 2u);
  ASSERT_EQ(r.bytes.size(), 96u);
  for (uint32_t v = 0; v < 3; ++v) EXPECT_EQ(r.f32(v, 0), float(v));

  // Capacity for 10, draw 6: the counter buffer says 192 bytes were written, and that is what
  // comes back (not the whole buffer).
  CaptureResult roomy = ctx().capture(mvpRequest(verts, identity, 10));
  ASSERT_TRUE(roomy.ok()) << roomy.error;
  EXPECT_EQ(roomy.primitivesWritten, 2u);
  EXPECT_EQ(roomy.primitivesNeeded, 2u);
  ASSERT_EQ(roomy.bytes.size(), 192u);
  for (uint32_t v = 0; v < 6; ++v) EXPECT_EQ(roomy.f32(v, 0), float(v));
}

TEST_F(Harness, CaptureGeometryShaderEmitsTwoVerticesPerPoint) {
  const uint32_t points = 5;
  std::vector<float> pos;
  for (uint32_t i = 0; i < points; ++i) pos.insert(pos.end(), {float(i) * 1.5f, -float(i), 0.25f * float(i), 1.f});
  CaptureRequest req;
  PipelineInputs& p = req.pipeline;
  p.stages = {stage(VK_SHADER_STAGE_VERTEX_BIT, "capture_passthrough.vert"),
              stage(VK_SHADER_STAGE_GEOMETRY_BIT, "capture_two_per_point.geom")};
  p.vertices = {toBytes(pos), 16, {{0, VK_FORMAT_R32G32B32A32_SFLOAT, 0}}};
  p.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
  p.vertexCount = points;
  req.xfbStride = 32;
  req.expectedVertices = 2 * points;
  CaptureResult r = ctx().capture(req);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.primitivesWritten, 2u * points);  // point primitives
  EXPECT_EQ(r.primitivesNeeded, 2u * points);
  ASSERT_EQ(r.vertexCount(), 2u * points);
  for (uint32_t i = 0; i < points; ++i)
    for (uint32_t k = 0; k < 2; ++k) {
      const uint32_t v = 2 * i + k;
      const float e[8] = {pos[i * 4] + 0.25f * k, pos[i * 4 + 1] - 0.5f * k, pos[i * 4 + 2], 1.f,
                          float(i), float(k), 0.f, 7.f};
      for (uint32_t c = 0; c < 8; ++c) EXPECT_EQ(r.f32(v, c), e[c]) << "vertex " << v << " component " << c;
    }
}

// Patch list of 3 control points, all tessellation levels 1: one triangle per patch whose three
// vertices are the patch corners. Their order inside the triangle is implementation-defined, so
// each captured triangle is checked as a set; coordinates are exact (1*p + 0*q + 0*r).
TEST_F(Harness, CaptureTessellationPatchListLevelOne) {
  const uint32_t patches = 2;
  std::vector<float> cps = {0, 0, 0, 1,  4, 0, 0, 1,  0, 4, 0, 1,   // patch 0
                            -1, -1, 2, 1, -3, 5, 2, 2, 7, 7, -2, 1};  // patch 1
  CaptureRequest req;
  PipelineInputs& p = req.pipeline;
  p.stages = {stage(VK_SHADER_STAGE_VERTEX_BIT, "capture_passthrough.vert"),
              stage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, "capture_patch.tesc"),
              stage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, "capture_patch.tese")};
  p.vertices = {toBytes(cps), 16, {{0, VK_FORMAT_R32G32B32A32_SFLOAT, 0}}};
  p.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
  p.patchControlPoints = 3;
  p.vertexCount = 3 * patches;
  req.xfbStride = 32;
  req.expectedVertices = 3 * patches;
  CaptureResult r = ctx().capture(req);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.primitivesWritten, patches);
  ASSERT_EQ(r.vertexCount(), 3 * patches);
  for (uint32_t prim = 0; prim < patches; ++prim) {
    std::set<int> corners;
    for (uint32_t k = 0; k < 3; ++k) {
      const uint32_t v = prim * 3 + k;
      EXPECT_EQ(r.f32(v, 7), float(prim)) << "gl_PrimitiveID of vertex " << v;
      int corner = -1, ones = 0;
      for (int c = 0; c < 3; ++c) {
        float tc = r.f32(v, 4 + c);
        EXPECT_TRUE(tc == 0.f || tc == 1.f) << "gl_TessCoord " << tc;
        if (tc == 1.f) corner = c, ++ones;
      }
      ASSERT_EQ(ones, 1) << "vertex " << v << " is not a corner";
      corners.insert(corner);
      for (int c = 0; c < 4; ++c)
        EXPECT_EQ(r.f32(v, c), cps[(prim * 3 + uint32_t(corner)) * 4 + uint32_t(c)])
            << "vertex " << v << " corner " << corner << " component " << c;
    }
    EXPECT_EQ(corners.size(), 3u) << "triangle " << prim << " repeats a corner";
  }
}

CaptureRequest pushSpecRequest(const float offset[4], uint32_t tag) {
  CaptureRequest req;
  PipelineInputs& p = req.pipeline;
  p.stages = {stage(VK_SHADER_STAGE_VERTEX_BIT, "capture_push_spec.vert")};
  std::vector<float> pos = {1, 2, 3, 1, -0.5f, 0.25f, 8, 1, 100, -100, 0.125f, 1};
  p.vertices = {toBytes(pos), 16, {{0, VK_FORMAT_R32G32B32A32_SFLOAT, 0}}};
  p.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
  p.vertexCount = 3;
  struct {
    float offset[4];
    uint32_t tag, pad[3];
  } push{{offset[0], offset[1], offset[2], offset[3]}, tag, {0, 0, 0}};
  p.pushConstants = toBytes(&push, 1);
  req.xfbStride = 32;
  req.expectedVertices = 3;
  return req;
}

TEST_F(Harness, CapturePushConstantsAndSpecializationConstants) {
  const float offset[4] = {10.f, -20.f, 0.5f, 0.f};
  CaptureRequest req = pushSpecRequest(offset, 0xC0FFEEu);
  req.pipeline.specConstants = {{7, floatBits(-2.5f)}, {8, 42u}, {9, VK_TRUE}};
  CaptureResult r = ctx().capture(req);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.vertexCount(), 3u);
  const float pos[3][4] = {{1, 2, 3, 1}, {-0.5f, 0.25f, 8, 1}, {100, -100, 0.125f, 1}};
  for (uint32_t v = 0; v < 3; ++v) {
    for (uint32_t c = 0; c < 4; ++c)  // dyadic values: exact
      EXPECT_EQ(r.f32(v, c), pos[v][c] * -2.5f + offset[c]) << "vertex " << v << " component " << c;
    EXPECT_EQ(r.u32(v, 4), 0xC0FFEEu);
    EXPECT_EQ(r.u32(v, 5), 42u);
    EXPECT_EQ(r.u32(v, 6), 1u);
    EXPECT_EQ(r.u32(v, 7), v);
  }

  // Same shader without specialization: the declared defaults (1.0, 3, false) must come back.
  CaptureRequest plain = pushSpecRequest(offset, 7u);
  CaptureResult d = ctx().capture(plain);
  ASSERT_TRUE(d.ok()) << d.error;
  ASSERT_EQ(d.vertexCount(), 3u);
  for (uint32_t v = 0; v < 3; ++v) {
    for (uint32_t c = 0; c < 4; ++c) EXPECT_EQ(d.f32(v, c), pos[v][c] + offset[c]);
    EXPECT_EQ(d.u32(v, 4), 7u);
    EXPECT_EQ(d.u32(v, 5), 3u);
    EXPECT_EQ(d.u32(v, 6), 0u);
  }
}

// 3 vertices x 2 instances, per-instance offsets on binding 1, a 4x2 RGBA32F texture sampled in the
// vertex stage with nearest filtering (texel values come back bit-exact), a UBO in set 2 with set 1
// empty. Transform feedback order is instance-major.
TEST_F(Harness, CaptureInstancingTextureAndSetGap) {
  std::vector<float> texels(4 * 2 * 4);
  for (size_t i = 0; i < texels.size(); ++i) texels[i] = 0.1f * float(i) + 1.f / 3.f;
  std::vector<float> pos = {0.f, 0.f, 1.f, 0.f, 0.f, 1.f};
  std::vector<float> inst = {10.f, 20.f, 30.f, 0.f, -1.f, -2.f, -3.f, 0.f};
  const float bias[4] = {0.5f, 0.25f, 0.125f, 0.f};
  CaptureRequest req;
  PipelineInputs& p = req.pipeline;
  p.stages = {stage(VK_SHADER_STAGE_VERTEX_BIT, "capture_instanced_texture.vert")};
  p.vertices = {toBytes(pos), 8, {{0, VK_FORMAT_R32G32_SFLOAT, 0}}};
  p.instances = VertexBuffer{toBytes(inst), 16, {{3, VK_FORMAT_R32G32B32A32_SFLOAT, 0}}};
  p.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
  p.vertexCount = 3;
  p.instanceCount = 2;
  p.textures = {{0, 1, 4, 2, texels}};
  p.uniformBuffers = {{2, 0, toBytes(bias, 4)}};
  req.xfbStride = 48;
  req.expectedVertices = 6;
  CaptureResult r = ctx().capture(req);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.vertexCount(), 6u);
  EXPECT_EQ(r.primitivesWritten, 6u);
  for (uint32_t instance = 0; instance < 2; ++instance)
    for (uint32_t vert = 0; vert < 3; ++vert) {
      const uint32_t v = instance * 3 + vert, t = vert + 3 * instance;
      const float e[4] = {pos[vert * 2] + inst[instance * 4] + bias[0], pos[vert * 2 + 1] + inst[instance * 4 + 1] + bias[1],
                          inst[instance * 4 + 2] + bias[2], 1.f + inst[instance * 4 + 3] + bias[3]};
      for (uint32_t c = 0; c < 4; ++c) {
        EXPECT_EQ(r.f32(v, c), e[c]) << "position, vertex " << v;
        EXPECT_EQ(floatBits(r.f32(v, 4 + c)), floatBits(texels[t * 4 + c])) << "texel " << t << " channel " << c;
      }
      EXPECT_EQ(int32_t(r.u32(v, 8)), int32_t(vert));
      EXPECT_EQ(int32_t(r.u32(v, 9)), int32_t(instance));
      EXPECT_EQ(int32_t(r.u32(v, 10)), 4);
      EXPECT_EQ(int32_t(r.u32(v, 11)), 2);
    }
}

TEST_F(Harness, CaptureErrorsAreReportedAndTheContextStaysUsable) {
  const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  std::vector<MvpVertex> verts(3, MvpVertex{{1, 2, 3}, {0, 0, 0, 0}});

  CaptureRequest bad = mvpRequest(verts, identity, 3);
  bad.pipeline.stages[0].spirv = {0xDEADBEEF, 1, 2, 3, 4};
  CaptureResult r = ctx().capture(bad);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error.find("not a SPIR-V module"), std::string::npos) << r.error;

  CaptureRequest dup = mvpRequest(verts, identity, 3);
  dup.pipeline.uniformBuffers.push_back({0, 0, toBytes(identity, 16)});
  r = ctx().capture(dup);
  EXPECT_NE(r.error.find("duplicate descriptor"), std::string::npos) << r.error;

  CaptureRequest patch = mvpRequest(verts, identity, 3);
  patch.pipeline.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
  r = ctx().capture(patch);
  EXPECT_NE(r.error.find("PATCH_LIST"), std::string::npos) << r.error;

  CaptureRequest small = mvpRequest(verts, identity, 3);
  small.pipeline.vertexCount = 4;  // reads past the 3 vertices given
  r = ctx().capture(small);
  EXPECT_NE(r.error.find("vertex buffer too small"), std::string::npos) << r.error;

  CaptureRequest stride = mvpRequest(verts, identity, 3);
  stride.xfbStride = 30;
  r = ctx().capture(stride);
  EXPECT_NE(r.error.find("xfbStride"), std::string::npos) << r.error;

  CaptureResult ok = ctx().capture(mvpRequest(verts, identity, 3));
  ASSERT_TRUE(ok.ok()) << ok.error;
  EXPECT_EQ(ok.f32(2, 2), 3.f);
}

// ------------------------------------------------------------------------------------------------
// Render
// ------------------------------------------------------------------------------------------------

Draw solidDraw(const std::vector<float>& xyz, const float colour[4]) {
  Draw d;
  PipelineInputs& p = d.pipeline;
  p.stages = {stage(VK_SHADER_STAGE_VERTEX_BIT, "render_solid.vert"),
              stage(VK_SHADER_STAGE_FRAGMENT_BIT, "render_solid.frag")};
  p.vertices = {toBytes(xyz), 12, {{0, VK_FORMAT_R32G32B32_SFLOAT, 0}}};
  p.vertexCount = uint32_t(xyz.size() / 3);
  p.uniformBuffers = {{0, 0, toBytes(colour, 4)}};
  return d;
}

// One solid triangle in a 64x64 target. Reference: for every pixel centre, its signed distance to
// the three edges (double). Pixels farther than tol = 1/64 px inside every edge must be the triangle
// colour, pixels farther than tol outside some edge must be the clear colour: bit-exact RGBA8.
// Pixels within tol of an edge (sub-pixel snapping: lavapipe has 8 sub-pixel bits) may be either.
// The covered count must lie in [strict inside, strict inside + ambiguous], and within
// sqrt(2) * perimeter + 2 of the analytic area (the band a pixel-centre count can deviate in).
TEST_F(Harness, RenderSolidTriangleCoverageColourAndPng) {
  const uint32_t W = 64, H = 64;
  const double px[3][2] = {{8.3, 5.1}, {57.7, 20.2}, {20.6, 60.9}};  // pixel coordinates
  std::vector<float> xyz;
  for (auto& v : px) xyz.insert(xyz.end(), {float(v[0] * 2 / W - 1), float(v[1] * 2 / H - 1), 0.5f});
  const float colour[4] = {1.f, 0.2f, 0.f, 1.f};  // -> (255, 51, 0, 255): 0.2*255 = 51.0000008
  RenderRequest req;
  req.width = W;
  req.height = H;
  req.clearColor[0] = 0.f, req.clearColor[1] = 0.f, req.clearColor[2] = 1.f, req.clearColor[3] = 1.f;
  req.draws = {solidDraw(xyz, colour)};
  RenderResult r = ctx().render(req);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.pixels.size(), size_t(W) * H * 4);

  // Snap the reference vertices the same way the device sees them (fp32 NDC -> pixels).
  double v[3][2];
  for (int i = 0; i < 3; ++i) {
    v[i][0] = (double(xyz[i * 3]) + 1) * W / 2;
    v[i][1] = (double(xyz[i * 3 + 1]) + 1) * H / 2;
  }
  const double area2 = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[2][0] - v[0][0]) * (v[1][1] - v[0][1]);
  const double sign = area2 > 0 ? 1 : -1, tol = 1.0 / 64;
  double perimeter = 0;
  for (int i = 0; i < 3; ++i) perimeter += std::hypot(v[(i + 1) % 3][0] - v[i][0], v[(i + 1) % 3][1] - v[i][1]);
  const uint8_t tri[4] = {255, 51, 0, 255}, clear[4] = {0, 0, 255, 255};
  uint32_t strictInside = 0, ambiguous = 0, covered = 0;
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x) {
      const double cx = x + 0.5, cy = y + 0.5;
      double dmin = 1e9;
      for (int i = 0; i < 3; ++i) {
        const double* a = v[i];
        const double* b = v[(i + 1) % 3];
        double d = sign * ((b[0] - a[0]) * (cy - a[1]) - (b[1] - a[1]) * (cx - a[0])) / std::hypot(b[0] - a[0], b[1] - a[1]);
        dmin = std::min(dmin, d);
      }
      const uint8_t* p = r.pixel(x, y);
      const bool isTri = std::memcmp(p, tri, 4) == 0, isClear = std::memcmp(p, clear, 4) == 0;
      ASSERT_TRUE(isTri || isClear) << "pixel " << x << "," << y << " has a third colour " << int(p[0]) << ","
                                    << int(p[1]) << "," << int(p[2]) << "," << int(p[3]);
      covered += isTri;
      if (dmin > tol) {
        ++strictInside;
        EXPECT_TRUE(isTri) << "pixel " << x << "," << y << " is inside by " << dmin << " px";
      } else if (dmin < -tol) {
        EXPECT_TRUE(isClear) << "pixel " << x << "," << y << " is outside by " << -dmin << " px";
      } else {
        ++ambiguous;
      }
    }
  const double area = std::fabs(area2) / 2;
  EXPECT_GE(covered, strictInside);
  EXPECT_LE(covered, strictInside + ambiguous);
  EXPECT_LE(std::fabs(double(covered) - area), std::sqrt(2.0) * perimeter + 2);
  std::printf("triangle: area %.2f px^2, covered %u, strictly inside %u, within 1/64 px of an edge %u\n", area,
              covered, strictInside, ambiguous);

  const std::string path = std::string(HARNESS_OUT_DIR) + "/harness_triangle.png";
  ASSERT_TRUE(writePng(path, int(W), int(H), r.pixels.data()));
  std::ifstream f(path, std::ios::binary);
  std::vector<uint8_t> file((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  ASSERT_GE(file.size(), 8u);
  EXPECT_EQ(std::memcmp(file.data(), sig, 8), 0);
  int dw = 0, dh = 0;
  std::vector<uint8_t> decoded;
  std::string why;
  ASSERT_TRUE(decodeStoredPng(file, &dw, &dh, &decoded, &why)) << why;
  EXPECT_EQ(dw, int(W));
  EXPECT_EQ(dh, int(H));
  EXPECT_EQ(decoded, r.pixels);
}

std::vector<float> quadNdc(double x0, double y0, double x1, double y1, double W, double H, float z) {
  auto nx = [&](double x) { return float(x * 2 / W - 1); };
  auto ny = [&](double y) { return float(y * 2 / H - 1); };
  return {nx(x0), ny(y0), z, nx(x1), ny(y0), z, nx(x1), ny(y1), z, nx(x0), ny(y1), z};
}

// A test scene in one render pass: an indexed "mesh" (near, red), a full-screen pass without vertex
// buffer (far, green; depth LESS keeps it behind the mesh), a textured HUD quad with depth test off (drawn over
// the mesh although farther), and an alpha-blended quad. All edges are on pixel boundaries, so
// every pixel is exact except blended ones (+-1: 0.5*255 rounds either way).
TEST_F(Harness, RenderSceneDepthHudBlendAndIndexBuffer) {
  const uint32_t W = 64, H = 64;
  RenderRequest req;
  req.width = W;
  req.height = H;
  req.readDepth = true;

  const float red[4] = {1, 0, 0, 1}, green[4] = {0, 1, 0, 1}, white[4] = {1, 1, 1, 0.5f};
  Draw mesh = solidDraw(quadNdc(0, 0, 48, 64, W, H, 0.25f), red);
  mesh.pipeline.indices = {0, 1, 2, 0, 2, 3};
  Draw background = solidDraw({}, green);  // full-screen pass: no vertex buffer at all
  background.pipeline.stages[0] = stage(VK_SHADER_STAGE_VERTEX_BIT, "render_fullscreen.vert");
  background.pipeline.vertices = {};
  background.pipeline.vertexCount = 3;

  Draw hud = solidDraw(quadNdc(4, 4, 20, 20, W, H, 0.9f), red);
  hud.pipeline.indices = {0, 1, 2, 2, 3, 0};
  hud.pipeline.stages[1] = stage(VK_SHADER_STAGE_FRAGMENT_BIT, "render_textured.frag");
  hud.pipeline.uniformBuffers.clear();
  const std::vector<float> quadrants = {0, 0, 1, 1, 1, 1, 0, 1,   // row 0: blue, yellow
                                        1, 0, 1, 1, 0, 1, 1, 1};  // row 1: magenta, cyan
  hud.pipeline.textures = {{0, 0, 2, 2, quadrants}};
  const float rect[4] = {4, 4, 16, 16};
  hud.pipeline.pushConstants = toBytes(rect, 4);
  hud.depthTest = false;

  Draw blend = solidDraw(quadNdc(40, 40, 56, 56, W, H, 0.1f), white);
  blend.pipeline.indices = {0, 1, 2, 0, 2, 3};
  blend.depthTest = false;
  blend.alphaBlend = true;

  req.draws = {mesh, background, hud, blend};
  RenderResult r = ctx().render(req);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.depth.size(), size_t(W) * H);
  writePng(std::string(HARNESS_OUT_DIR) + "/harness_scene.png", int(W), int(H), r.pixels.data());

  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x) {
      const uint8_t* p = r.pixel(x, y);
      std::array<int, 4> got{p[0], p[1], p[2], p[3]};
      const bool inMesh = x < 48;
      if (x >= 4 && x < 20 && y >= 4 && y < 20) {
        const size_t t = ((y - 4) / 8) * 2 + (x - 4) / 8;
        std::array<int, 4> e;
        for (int c = 0; c < 4; ++c) e[c] = int(quadrants[t * 4 + c] * 255);
        EXPECT_EQ(got, e) << "HUD pixel " << x << "," << y;
      } else if (x >= 40 && x < 56 && y >= 40 && y < 56) {
        // white at alpha 0.5 over red (mesh) or green (background); alpha: 0.5 + 1 * 0.5 = 1
        std::array<int, 4> e = inMesh ? std::array<int, 4>{255, 128, 128, 255} : std::array<int, 4>{128, 255, 128, 255};
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], e[c], 1) << "blended pixel " << x << "," << y;
      } else {
        std::array<int, 4> e = inMesh ? std::array<int, 4>{255, 0, 0, 255} : std::array<int, 4>{0, 255, 0, 255};
        EXPECT_EQ(got, e) << "pixel " << x << "," << y;
      }
      // Depth: the HUD and blend quads do not write depth (depth test off).
      EXPECT_NEAR(r.depthAt(x, y), inMesh ? 0.25f : 0.5f, 1e-7f) << "depth at " << x << "," << y;
    }
}

// A depth pre-pass (colour writes off, LESS) followed by the same geometry with EQUAL: every
// covered pixel must pass, i.e. both pipelines computed bit-identical depths. Coverage must match a
// single plain draw of the same triangle exactly.
TEST_F(Harness, RenderDepthPrepassThenEqualPassCoversTheSamePixels) {
  const uint32_t W = 48, H = 48;
  const std::vector<float> tri = {-0.83f, -0.71f, 0.13f, 0.91f, -0.37f, 0.77f, -0.29f, 0.88f, 0.41f};
  const float blue[4] = {0, 0, 1, 1};
  RenderRequest single;
  single.width = W;
  single.height = H;
  single.draws = {solidDraw(tri, blue)};
  RenderRequest twoPass = single;
  Draw pre = solidDraw(tri, blue);
  pre.colorWrite = false;
  Draw eq = solidDraw(tri, blue);
  eq.depthCompare = VK_COMPARE_OP_EQUAL;
  eq.depthWrite = false;
  twoPass.draws = {pre, eq};
  RenderResult a = ctx().render(single), b = ctx().render(twoPass);
  ASSERT_TRUE(a.ok()) << a.error;
  ASSERT_TRUE(b.ok()) << b.error;
  size_t coveredA = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 4) coveredA += a.pixels[i + 2] == 255;
  EXPECT_GT(coveredA, 300u);
  EXPECT_EQ(a.pixels, b.pixels);
}

// Multiview (two eyes in one draw): view 0 is shifted by -0.25 NDC (-4 px at 32 wide), view 1 by
// +0.25. The vertex data is dyadic, so the two coverages are exact 8-pixel translations of each
// other (the top-left rule is translation invariant): compared pixel for pixel.
TEST_F(Harness, RenderMultiviewTwoEyesAreExactTranslations) {
  if (!ctx().multiviewSupported()) GTEST_SKIP() << "multiview not supported";
  const uint32_t W = 32, H = 32;
  RenderRequest req;
  req.width = W;
  req.height = H;
  req.viewCount = 2;
  Draw d;
  d.pipeline.stages = {stage(VK_SHADER_STAGE_VERTEX_BIT, "render_multiview.vert"),
                       stage(VK_SHADER_STAGE_FRAGMENT_BIT, "render_multiview.frag")};
  const std::vector<float> tri = {-0.40625f, -0.75f, 0.5f, 0.34375f, -0.5f, 0.5f, -0.15625f, 0.6875f, 0.5f};
  d.pipeline.vertices = {toBytes(tri), 12, {{0, VK_FORMAT_R32G32B32_SFLOAT, 0}}};
  d.pipeline.vertexCount = 3;
  const float shift = 0.25f;
  d.pipeline.pushConstants = toBytes(&shift, 1);
  req.draws = {d};
  RenderResult r = ctx().render(req);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.pixels.size(), size_t(W) * H * 4 * 2);
  writePng(std::string(HARNESS_OUT_DIR) + "/harness_multiview_left.png", int(W), int(H), r.pixel(0, 0, 0));
  writePng(std::string(HARNESS_OUT_DIR) + "/harness_multiview_right.png", int(W), int(H), r.pixel(0, 0, 1));
  size_t left = 0, right = 0;
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x) {
      const uint8_t* l = r.pixel(x, y, 0);
      const uint8_t* rr = r.pixel(x, y, 1);
      const bool lOn = l[0] == 255, rOn = rr[1] == 255;
      EXPECT_TRUE(lOn ? (l[1] == 0 && l[2] == 0) : (l[0] == 0 && l[1] == 0 && l[2] == 0)) << x << "," << y;
      EXPECT_TRUE(rOn ? (rr[0] == 0 && rr[2] == 0) : (rr[0] == 0 && rr[1] == 0 && rr[2] == 0)) << x << "," << y;
      left += lOn;
      right += rOn;
      const bool rShifted = x + 8 < W && r.pixel(x + 8, y, 1)[1] == 255;
      if (x + 8 < W) {
        EXPECT_EQ(lOn, rShifted) << "left " << x << "," << y << " vs right " << x + 8;
      }
    }
  EXPECT_GT(left, 60u);
  EXPECT_EQ(left, right);
}

TEST_F(Harness, RenderRejectsBadRequests) {
  RenderRequest empty;
  empty.width = 16;
  empty.height = 16;
  RenderResult r = ctx().render(empty);
  EXPECT_NE(r.error.find("no draws"), std::string::npos) << r.error;
  const float c[4] = {1, 1, 1, 1};
  RenderRequest zero;
  zero.draws = {solidDraw({0, 0, 0, 1, 0, 0, 0, 1, 0}, c)};
  r = ctx().render(zero);
  EXPECT_NE(r.error.find("width and height"), std::string::npos) << r.error;
  RenderRequest noVs = zero;
  noVs.width = noVs.height = 8;
  noVs.draws[0].pipeline.stages.erase(noVs.draws[0].pipeline.stages.begin());
  r = ctx().render(noVs);
  EXPECT_NE(r.error.find("render draw 0: a vertex shader is required"), std::string::npos) << r.error;
  EXPECT_TRUE(r.pixels.empty());
}

}  // namespace
